#!/usr/bin/python3
"""Speed against accuracy: regenerates the error-against-time figures (`make figures`).

  bench/run.py [--quick] [--suite figures|stability|all] [--scenes A,B] [--fluence BIN] [--no-cycles]
               [--budgets SECONDS ...] [--spp-rungs N ...]
  bench/run.py chart CSV --x COLUMN --y COLUMN --group COLUMN --out BASE [--where COLUMN=VALUE]
               [--title T] [--xlabel L] [--ylabel L]

The first form renders every benchmark scene (fluence_bench/scenes.py) with each of its methods,
and with Cycles where blender is installed and the peer has the scene, at a ladder of time
budgets (default 0.5 1 2 4 s), and the stability scenes (bench/stability/) at a ladder of
sample counts (default 8 32 128), on 2 threads; --quick: budgets 0.25 0.5 1 2, spp 4 16 64,
half resolution, references at a quarter of their samples. It measures each image against a
reference whose own noise is subtracted (fluence_bench/metrics.py). References are cached in bench/cache/ (delete it after
changing the renderer). It writes bench/results/DATE-figures.csv, -figures-stability.csv,
-figures.md (the run's record: machine load, commit, command), the charts in
bench/results/figures/, and the generated sections of docs/RESULTS.md and docs/STABILITY.md.
--scenes limits both suites to the named scenes; the outputs then hold only those. --from-csv
renders nothing and rewrites the charts and generated sections from the CSVs already written.

The second form draws any CSV as log-log lines with fitted slopes (the older figures in
bench/results/ were drawn this way). Run with /usr/bin/python3 (Debian's python3-numpy,
python3-openimageio, python3-matplotlib: scripts/install_dependencies.sh bench).
"""
import argparse
import os
import pathlib
import shlex
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fluence_bench import charts, rendering, reports, scenes, suites  # noqa: E402

ROOT = scenes.ROOT


def chart_main(argv):
    p = argparse.ArgumentParser(prog="bench/run.py chart", description="log-log chart of a CSV, slopes printed")
    p.add_argument("csv")
    for flag in ("--x", "--y", "--group", "--out"):
        p.add_argument(flag, required=True)
    for flag in ("--where", "--title", "--xlabel", "--ylabel"):
        p.add_argument(flag, default=None)
    a = p.parse_args(argv)
    charts.chart_csv(a.csv, a.x, a.y, a.group, a.out, a.where, a.title or "", a.xlabel, a.ylabel)


def shell(cmd):
    return subprocess.run(cmd, shell=True, capture_output=True, text=True, cwd=ROOT).stdout.strip()


def write_run_record(args, started, load_before, seconds):
    """The record's header: what ran, where, under what load; publish() appends the tables."""
    args.record.write_text("\n".join([
        "# Speed against accuracy: the `make figures` run of %s" % time.strftime("%Y-%m-%d", started), "",
        "Written by `bench/run.py`; do not edit. Mode: %s. Command:" % ("quick" if args.quick else "full"), "",
        "    /usr/bin/python3 bench/run.py %s" % " ".join(shlex.quote(a) for a in sys.argv[1:]), "",
        "- Commit: %s" % shell("git rev-parse --short HEAD; git diff --quiet HEAD -- . || echo '(with uncommitted changes)'").replace("\n", " "),
        "- Machine: %s, %s cores; shared, so times are noisy." % (shell("uname -m"), os.cpu_count()),
        "- Load (`uptime`) at the start: %s" % load_before,
        "- Load at the end: %s" % shell("uptime"),
        "- Wall time of the run: %.0f s (references included unless cached)." % seconds, "",
        "Data: `%s`, `%s`." % (args.csv.name, args.stability_csv.name), ""]))


def publish(args, stem, figure_rows, stability_rows):
    """Charts, and the generated sections of the run record, docs/RESULTS.md and docs/STABILITY.md."""
    record_link = "Run record: [%s](../bench/results/%s).\n\n" % (args.record.name, args.record.name)
    if figure_rows:
        slopes = reports.draw_figures(figure_rows, args.figure_dir, stem)
        reports.replace_generated(args.record, "figures", "## Figures\n\n" + reports.figures_markdown(
            figure_rows, slopes, lambda s: "figures/%s-%s.png" % (stem, s)))
        reports.replace_generated(ROOT / "docs" / "RESULTS.md", "figures", record_link + reports.figures_markdown(
            figure_rows, slopes, lambda s: "../bench/results/figures/%s-%s.png" % (stem, s)))
    if stability_rows:
        markdown = reports.stability_markdown(stability_rows, scenes.stability_scenes())
        reports.replace_generated(args.record, "stability", "## Stability\n\n" + markdown)
        reports.replace_generated(ROOT / "docs" / "STABILITY.md", "stability", record_link + markdown)


def main():
    if len(sys.argv) > 1 and sys.argv[1] == "chart":
        return chart_main(sys.argv[2:])
    stem = time.strftime("%Y-%m-%d", time.gmtime()) + "-figures"
    results = ROOT / "bench" / "results"
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--fluence", default=str(ROOT / "build" / "apps" / "fluence"), help="the fluence binary")
    p.add_argument("--quick", action="store_true", help="budgets 0.25 to 2 s, stability spp 4 16 64, half resolution, "
                   "quarter-spp references")
    p.add_argument("--suite", choices=("figures", "stability", "all"), default="all")
    p.add_argument("--scenes", default="", help="comma-separated scene names (default: all)")
    p.add_argument("--budgets", type=float, nargs="+", help="seconds per render of the figures ladder")
    p.add_argument("--spp-rungs", type=int, nargs="+", help="sample counts of the stability ladder")
    p.add_argument("--no-cycles", action="store_true", help="leave Cycles out even where blender is installed")
    p.add_argument("--cache", type=pathlib.Path, default=ROOT / "bench" / "cache")
    p.add_argument("--csv", type=pathlib.Path, default=results / (stem + ".csv"))
    p.add_argument("--stability-csv", type=pathlib.Path, default=results / (stem + "-stability.csv"))
    p.add_argument("--record", type=pathlib.Path, default=results / (stem + ".md"))
    p.add_argument("--figure-dir", type=pathlib.Path, default=results / "figures")
    p.add_argument("--from-csv", action="store_true", help="render nothing: redraw the charts and rewrite the "
                   "generated sections from the CSVs of an earlier run (the record's header is kept)")
    args = p.parse_args()
    args.figure_dir.mkdir(parents=True, exist_ok=True)
    if args.from_csv:
        return publish(args, args.csv.stem, *(reports.read_csv(f) if f.exists() else [] for f in (args.csv, args.stability_csv)))

    binary = os.path.abspath(args.fluence)
    if not os.access(binary, os.X_OK):
        sys.exit("no fluence binary at %s (build it, or pass --fluence)" % binary)
    cycles = not args.no_cycles and rendering.cycles_available()
    budgets = args.budgets or ([0.25, 0.5, 1, 2] if args.quick else [0.5, 1, 2, 4])
    spp_rungs = args.spp_rungs or ([4, 16, 64] if args.quick else [8, 32, 128])
    ctx = suites.Context(binary, args.cache, budgets, spp_rungs, args.quick, cycles)
    selected = set(filter(None, args.scenes.split(",")))
    started, load_before, t0 = time.gmtime(), shell("uptime"), time.monotonic()
    print("bench/run.py: budgets %s s, stability spp %s, %s mode, Cycles %s; load: %s" % (
        budgets, spp_rungs, "quick" if args.quick else "full", "on" if cycles else "off", load_before), flush=True)

    figure_rows = suites.figures(ctx, selected) if args.suite in ("figures", "all") else []
    if figure_rows:
        reports.write_csv(figure_rows, args.csv)
    stability_rows = suites.stability(ctx, selected) if args.suite in ("stability", "all") else []
    if stability_rows:
        reports.write_csv(stability_rows, args.stability_csv)
    write_run_record(args, started, load_before, time.monotonic() - t0)
    publish(args, stem, figure_rows, stability_rows)
    print("bench/run.py: done in %.0f s; wrote %s" % (time.monotonic() - t0, args.record), flush=True)


if __name__ == "__main__":
    main()
