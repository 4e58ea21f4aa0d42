#!/usr/bin/python3
"""Speed against accuracy: regenerates the error-against-time figures (`make figures`).

  bench/run.py [--quick] [--suite figures|cycles|stability|all] [--scenes A,B] [--fluence BIN] [--no-cycles]
               [--peer DIR] [--budgets SECONDS ...] [--spp-rungs N ...] [--cycles-spp N ...] [--rounds N]
  bench/run.py chart CSV --x COLUMN --y COLUMN --group COLUMN --out BASE [--where COLUMN=VALUE]
               [--title T] [--xlabel L] [--ylabel L]

The first form runs three suites on 2 threads. `figures` renders every benchmark scene
(fluence_bench/scenes.py) with each of its methods at a ladder of time budgets (default 0.5 1 2 4
s). `cycles`, where blender is installed, renders the scenes the Cycles peer has with Fluence's
path tracer and with Cycles, interleaved, at a ladder of sample counts (default 16 64 256) in
ROUNDS rounds of their own seed (default 3), timing each render's wall and CPU time
(fluence_bench/peer_suite.py). `stability` renders the stability scenes (bench/stability/) at a
ladder of sample counts (default 8 32 128). --quick: budgets 0.25 0.5 1 2, spp 4 16 64 (both
ladders), 2 rounds, half resolution, references at a quarter of their samples. Each image is
measured against a reference whose own noise is subtracted (fluence_bench/metrics.py).
References are cached in bench/cache/ (delete it after changing the renderer). A run writes
bench/results/DATE-figures.csv, DATE-figures-stability.csv, DATE-cycles-ratio.csv, its record
(machine load, commit, command: DATE-figures.md, or DATE-cycles-ratio.md for `--suite cycles`
alone), the charts in bench/results/figures/, and the generated sections of docs/RESULTS.md
(`figures`, `cycles`) and docs/STABILITY.md (`stability`) of the suites it ran, and no others.
The documents are rewritten only by a run of every scene whose --record is in bench/results/; a trial
run (--scenes, or a record elsewhere) writes its record, CSV and charts and leaves docs/ alone.
--scenes limits the suites to the named scenes; the outputs then hold only those. --from-csv
renders nothing and rewrites the charts and generated sections of the --suite selection from
the CSVs already written (name an earlier run's with --csv, --stability-csv, --cycles-csv and
--record).

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
from fluence_bench import charts, peer_report, peer_suite, rendering, reports, scenes, suites  # noqa: E402

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
        "Data: %s." % ", ".join("`%s`" % f.name for f in csv_files(args).values()), ""]))


def csv_files(args):
    """{suite: its CSV} for the suites the run makes."""
    files = {"figures": args.csv, "cycles": args.cycles_csv, "stability": args.stability_csv}
    return {s: f for s, f in files.items() if args.suite in (s, "all")}


def updates_docs(args, selected):
    """Whether the run's tables go into docs/RESULTS.md and docs/STABILITY.md: only a run of every scene
    whose record is kept in bench/results; a trial run (a scene subset, or a record elsewhere) writes its
    record alone and leaves the documents as they are."""
    return not selected and args.record.resolve().parent == (ROOT / "bench" / "results").resolve()


def publish(args, figure_rows, stability_rows, cycles_rows, docs):
    """Charts, and the generated sections of the run record and, if DOCS, of docs/RESULTS.md and
    docs/STABILITY.md."""
    record_link = "Run record: [%s](../bench/results/%s).\n\n" % (args.record.name, args.record.name)
    if cycles_rows:
        stem = args.cycles_csv.stem
        peer_report.draw(cycles_rows, args.figure_dir, stem)
        reports.replace_generated(args.record, "cycles", "## Fluence against Cycles\n\n" + peer_report.markdown(
            cycles_rows, lambda s: "figures/%s-%s.png" % (stem, s)))
        if docs:
            reports.replace_generated(ROOT / "docs" / "RESULTS.md", "cycles", record_link + peer_report.markdown(
                cycles_rows, lambda s: "../bench/results/figures/%s-%s.png" % (stem, s)))
    if figure_rows:
        stem = args.csv.stem
        slopes = reports.draw_figures(figure_rows, args.figure_dir, stem)
        reports.replace_generated(args.record, "figures", "## Figures\n\n" + reports.figures_markdown(
            figure_rows, slopes, lambda s: "figures/%s-%s.png" % (stem, s)))
        if docs:
            reports.replace_generated(ROOT / "docs" / "RESULTS.md", "figures", record_link + reports.figures_markdown(
                figure_rows, slopes, lambda s: "../bench/results/figures/%s-%s.png" % (stem, s)))
    if stability_rows:
        markdown = reports.stability_markdown(stability_rows, scenes.stability_scenes())
        reports.replace_generated(args.record, "stability", "## Stability\n\n" + markdown)
        if docs:
            reports.replace_generated(ROOT / "docs" / "STABILITY.md", "stability", record_link + markdown)


def main():
    if len(sys.argv) > 1 and sys.argv[1] == "chart":
        return chart_main(sys.argv[2:])
    date = time.strftime("%Y-%m-%d", time.gmtime())
    results = ROOT / "bench" / "results"
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--fluence", default=str(ROOT / "build" / "apps" / "fluence"), help="the fluence binary")
    p.add_argument("--quick", action="store_true", help="budgets 0.25 to 2 s, stability spp 4 16 64, half resolution, "
                   "quarter-spp references")
    p.add_argument("--suite", choices=("figures", "cycles", "stability", "all"), default="all")
    p.add_argument("--scenes", default="", help="comma-separated scene names (default: all)")
    p.add_argument("--budgets", type=float, nargs="+", help="seconds per render of the figures ladder")
    p.add_argument("--spp-rungs", type=int, nargs="+", help="sample counts of the stability ladder")
    p.add_argument("--cycles-spp", type=int, nargs="+", help="sample counts of the cycles suite's ladder")
    p.add_argument("--rounds", type=int, help="rounds of the cycles suite's ladder, each with its own seed")
    p.add_argument("--no-cycles", action="store_true", help="leave the cycles suite out even where blender is installed")
    p.add_argument("--peer", type=pathlib.Path, default=rendering.PEER_SOURCE,
                   help="the Cycles peer's folder (default: shared/peers/cycles beside the checkout)")
    p.add_argument("--cache", type=pathlib.Path, default=ROOT / "bench" / "cache")
    p.add_argument("--csv", type=pathlib.Path, default=results / (date + "-figures.csv"))
    p.add_argument("--stability-csv", type=pathlib.Path, default=results / (date + "-figures-stability.csv"))
    p.add_argument("--cycles-csv", type=pathlib.Path, default=results / (date + "-cycles-ratio.csv"))
    p.add_argument("--record", type=pathlib.Path, help="the run's record (default: DATE-figures.md, or "
                   "DATE-cycles-ratio.md for --suite cycles)")
    p.add_argument("--figure-dir", type=pathlib.Path, default=results / "figures")
    p.add_argument("--from-csv", action="store_true", help="render nothing: redraw the charts and rewrite the "
                   "generated sections from the CSVs of an earlier run (the record's header is kept)")
    args = p.parse_args()
    args.record = args.record or results / (date + ("-cycles-ratio.md" if args.suite == "cycles" else "-figures.md"))
    args.figure_dir.mkdir(parents=True, exist_ok=True)
    if args.from_csv:
        files = csv_files(args)
        return publish(args, *(reports.read_csv(files[s]) if s in files and files[s].exists() else []
                               for s in ("figures", "stability", "cycles")), updates_docs(args, set()))

    binary = os.path.abspath(args.fluence)
    if not os.access(binary, os.X_OK):
        sys.exit("no fluence binary at %s (build it, or pass --fluence)" % binary)
    cycles = not args.no_cycles and rendering.cycles_available(args.peer)
    budgets = args.budgets or ([0.25, 0.5, 1, 2] if args.quick else [0.5, 1, 2, 4])
    spp_rungs = args.spp_rungs or ([4, 16, 64] if args.quick else [8, 32, 128])
    cycles_spp = args.cycles_spp or ([4, 16, 64] if args.quick else [16, 64, 256])
    rounds = args.rounds or (2 if args.quick else 3)
    ctx = suites.Context(binary, args.cache, budgets, spp_rungs, args.quick, cycles, args.peer)
    selected = set(filter(None, args.scenes.split(",")))
    started, load_before, t0 = time.gmtime(), shell("uptime"), time.monotonic()
    print("bench/run.py: budgets %s s, stability spp %s, Cycles %s (spp %s, %d rounds), %s mode; load: %s" % (
        budgets, spp_rungs, "on" if cycles else "off", cycles_spp, rounds, "quick" if args.quick else "full",
        load_before), flush=True)

    files = csv_files(args)
    figure_rows = suites.figures(ctx, selected) if "figures" in files else []
    if figure_rows:
        reports.write_csv(figure_rows, args.csv)
    cycles_rows = peer_suite.cycles(ctx, selected, cycles_spp, rounds) if "cycles" in files and cycles else []
    if cycles_rows:
        reports.write_csv(cycles_rows, args.cycles_csv)
    stability_rows = suites.stability(ctx, selected) if "stability" in files else []
    if stability_rows:
        reports.write_csv(stability_rows, args.stability_csv)
    write_run_record(args, started, load_before, time.monotonic() - t0)
    docs = updates_docs(args, selected)
    publish(args, figure_rows, stability_rows, cycles_rows, docs)
    print("bench/run.py: done in %.0f s; wrote %s%s" % (time.monotonic() - t0, args.record,
          " and the tables of docs/" if docs else " (docs/ left as they are: a trial run)"), flush=True)


if __name__ == "__main__":
    main()
