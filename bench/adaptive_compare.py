#!/usr/bin/python3
"""Adaptive against uniform sampling at equal CPU time, on the Cornell box, the smoke and the subsurface scene.

  bench/adaptive_compare.py FLUENCE OUT_DIR [--res N] [--ref-spp N] [--spp N ...] [--uniform-spp N ...] [--scenes A,B]
                            [--sampler NAME] [--min-spp N] [--repeat N] [--seed S] [--peer-scenes DIR]
                            [--baseline FLUENCE]

For each scene: a reference made of two uniform renders of REF_SPP / 2 samples (seeds 1 and 2,
kept in OUT_DIR if present), whose own noise is subtracted from every error (relMSE, eps 0.01, as
bench/fluence_bench/metrics.py computes it); then, at each rung (seed SEED, default 0), the uniform render
(`--spp N`, at the UNIFORM_SPP rungs, default the SPP ones) and the adaptive one (`--mean-spp N`, at the SPP rungs: the
counted cost of N uniform samples per pixel, spread by the budget rule of integrators/adaptive_sampling.h; the
summary's "the cost of X uniform spp" is kept as cost_spp), alternating so that the machine's load falls on
both alike. Each render's CPU time (user + system of the fluence process, scene loading included)
is taken from the kernel (RUSAGE_CHILDREN), the least of REPEAT renders (default 2, interleaved
too: the image is the same each time, the load is not). The uniform relMSE at each adaptive render's CPU time
is interpolated in log-log between the two uniform rungs around it (extrapolated from the nearest
two, marked '*', outside them), and the ratio adaptive / uniform printed: below 1, adaptive wins at
equal time. Writes OUT_DIR/series.csv (every render) and OUT_DIR/equal_time.csv (the table).
`--scenes sample` renders the subsurface sample (usd_samples/subsurface), a second scene with guided
random walks. PEER_SCENES (default bench/peer_scenes) is where cycles_smoke.usda and cycles_sss.usda
are read from: a copy whose VDB path is absolute lets a checkout that is not beside ../shared (a worktree) render them.
With --baseline, another binary's adaptive renders (`--mean-spp N` with the same options: another
budget rule or cost model) are rendered too, interleaved with the others, and compared the same way
(mode "baseline" in series.csv, baseline_ratio in the table).
Needs oiiotool and numpy (the images are read as FITS through oiiotool).
"""
import argparse
import csv
import math
import os
import pathlib
import resource
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fluence_bench import metrics  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parent.parent
SCENES = {
    "cornell": (ROOT / "usd_samples/cornell_box.usda", []),
    "smoke": (pathlib.Path("cycles_smoke.usda"), []),  # under --peer-scenes
    "sss": (pathlib.Path("cycles_sss.usda"), ["--subdiv-level", "4"]),  # Cycles' render level
    "sample": (ROOT / "usd_samples/subsurface/subsurface.usda", []),  # guided walks; not a default
}


def read_rgb_through_oiiotool(path):
    """The image's R G B as float64 [rows, columns, 3], through a FITS file written by oiiotool (the
    rows may come bottom-up: every image of a comparison is read the same way)."""
    fits = pathlib.Path(str(path) + ".fits")
    subprocess.run(["oiiotool", str(path), "--ch", "R,G,B", "-d", "float", "-o", str(fits)], check=True)
    data = fits.read_bytes()
    fits.unlink()
    cards, offset = {}, 0
    while True:  # 80-character cards in 2880-byte blocks, up to END
        block = data[offset:offset + 2880]
        offset += 2880
        for i in range(0, 2880, 80):
            key, _, value = block[i:i + 80].decode("ascii").partition("=")
            cards[key.strip()] = value.split("/")[0].strip()
        if "END" in cards:
            break
    assert cards["BITPIX"] == "-32" and cards["NAXIS1"] == "3", cards
    width, height = int(cards["NAXIS2"]), int(cards["NAXIS3"])
    pixels = np.frombuffer(data, dtype=">f4", count=3 * width * height, offset=offset)
    return pixels.reshape(height, width, 3).astype(np.float64)


def render(binary, scene, args, out, options):
    """Renders; returns the CPU seconds of the fluence process."""
    path, extra = SCENES[scene]
    path = pathlib.Path(args.peer_scenes) / path  # an absolute path (cornell) stays itself
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    cmd = [binary, "render", str(path), *extra, "-r", str(args.res), str(args.res), "-j", "2", "-o", str(out),
           *(["--sampler", args.sampler] if args.sampler else []), *options]
    with open(str(out) + ".log", "w") as log:
        subprocess.run(cmd, stdout=log, stderr=subprocess.STDOUT, check=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def adaptive_spp(out):
    """The adaptive render's mean spp and the uniform spp of the same counted cost, from its summary."""
    for line in open(str(out) + ".log"):
        if "adaptive" in line and "on average" in line:
            return float(line.split(":")[1].split()[0]), float(line.split("the cost of")[1].split()[0])
    return None, None


def uniform_at(cpu, uniform):
    """relMSE of uniform sampling at `cpu` seconds, log-log between the rungs around it (or the
    nearest two, extrapolating); and whether it extrapolated."""
    points = sorted((u["cpu_s"], u["relmse"]) for u in uniform if u["relmse"] > 0)
    below = [p for p in points if p[0] <= cpu]
    above = [p for p in points if p[0] > cpu]
    if below and above:
        (t0, e0), (t1, e1), outside = below[-1], above[0], False
    elif above:
        (t0, e0), (t1, e1), outside = points[0], points[1], True
    else:
        (t0, e0), (t1, e1), outside = points[-2], points[-1], True
    slope = (math.log(e1) - math.log(e0)) / (math.log(t1) - math.log(t0))
    return math.exp(math.log(e0) + slope * (math.log(cpu) - math.log(t0))), outside


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("fluence")
    p.add_argument("out")
    p.add_argument("--res", type=int, default=256)
    p.add_argument("--ref-spp", type=int, default=2048)
    p.add_argument("--spp", type=int, nargs="+", default=[16, 32, 64, 128])
    p.add_argument("--uniform-spp", type=int, nargs="+", default=None,
                   help="the uniform rungs (default: the --spp ones); they should reach past the adaptive renders' CPU time")
    p.add_argument("--scenes", default="cornell,smoke,sss")
    p.add_argument("--sampler", default=None, help="--sampler for every render (default: fluence's)")
    p.add_argument("--min-spp", type=int, default=16)
    p.add_argument("--repeat", type=int, default=2, help="renders of each image, the least CPU time kept")
    p.add_argument("--seed", type=int, default=0, help="the rungs' seed (the references take 1 and 2)")
    p.add_argument("--peer-scenes", default=str(ROOT / "bench/peer_scenes"),
                   help="the folder of cycles_smoke.usda and cycles_sss.usda")
    p.add_argument("--baseline", default=None, help="another fluence whose adaptive renders are compared too")
    args = p.parse_args()
    binary = str(pathlib.Path(args.fluence).resolve())
    binaries = {"uniform": binary, "adaptive": binary}
    if args.baseline:
        binaries["baseline"] = str(pathlib.Path(args.baseline).resolve())
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    metrics.read_rgb = read_rgb_through_oiiotool
    series, table = [], []
    for scene in args.scenes.split(","):
        halves = [out / ("%s_ref_%d.exr" % (scene, seed)) for seed in (1, 2)]
        for seed, half in zip((1, 2), halves):
            if not half.exists():
                cpu = render(binary, scene, args, half, ["--spp", str(args.ref_spp // 2), "--seed", str(seed)])
                print("%s reference half %d: %d spp, %.1f CPU s" % (scene, seed, args.ref_spp // 2, cpu), flush=True)
        reference = metrics.Reference(halves[0], halves[1], args.ref_spp)
        print("%s reference: relMSE of its own %.3g" % (scene, reference.noise()["ref_relmse"]), flush=True)
        rows = []
        rungs = sorted(set(args.spp) | set(args.uniform_spp or args.spp))
        for n in rungs:
            modes = [m for m, spps in (("uniform", args.uniform_spp or args.spp), ("adaptive", args.spp),
                                       ("baseline", args.spp if args.baseline else [])) if n in spps]
            images = {mode: out / ("%s_%s_%d.exr" % (scene, mode, n)) for mode in modes}
            seeded = ["--seed", str(args.seed)]
            options = {"uniform": ["--spp", str(n)] + seeded,
                       "adaptive": ["--mean-spp", str(n), "--min-spp", str(min(args.min_spp, n))] + seeded}
            options["baseline"] = options["adaptive"]
            cpus = {mode: [] for mode in modes}
            for _ in range(args.repeat):  # the same image each time: the least CPU time is the least disturbed
                for mode in modes:
                    cpus[mode].append(render(binaries[mode], scene, args, images[mode], options[mode]))
            for mode in modes:
                e = reference.error(images[mode])
                spp, cost_spp = adaptive_spp(images[mode])
                row = {"scene": scene, "mode": mode, "spp": n, "mean_spp": spp or n, "cost_spp": cost_spp or n,
                       "cpu_s": round(min(cpus[mode]), 3), "cpu_runs": " ".join("%.3f" % c for c in cpus[mode]),
                       "relmse": e["relmse"], "relmse_uncorrected": e["relmse_uncorrected"], "bias": e["bias"],
                       "bias_se": e["bias_se"]}
                print(",".join(str(v) for v in row.values()), flush=True)
                rows.append(row)
        series += rows
        uniform = [r for r in rows if r["mode"] == "uniform"]
        baseline = {r["spp"]: r for r in rows if r["mode"] == "baseline"}
        for a in (r for r in rows if r["mode"] == "adaptive"):
            u, outside = uniform_at(a["cpu_s"], uniform)
            row = {"scene": scene, "mean_spp": a["spp"], "cpu_s": a["cpu_s"], "adaptive_relmse": a["relmse"],
                   "uniform_relmse_same_cpu": u, "ratio": a["relmse"] / u, "extrapolated": "*" if outside else ""}
            if a["spp"] in baseline:
                b = baseline[a["spp"]]
                bu, b_outside = uniform_at(b["cpu_s"], uniform)
                row.update({"baseline_cpu_s": b["cpu_s"], "baseline_relmse": b["relmse"],
                            "baseline_ratio": b["relmse"] / bu, "baseline_extrapolated": "*" if b_outside else ""})
            table.append(row)
    for name, rows in (("series.csv", series), ("equal_time.csv", table)):
        with open(out / name, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
            w.writeheader()
            w.writerows(rows)
    print("\nscene    mean spp  CPU s   adaptive relMSE  uniform relMSE (same CPU)  ratio")
    for t in table:
        print("%-8s %8d %7.1f %16.5g %16.5g%-1s %18.3f" % (t["scene"], t["mean_spp"], t["cpu_s"], t["adaptive_relmse"],
                                                          t["uniform_relmse_same_cpu"], t["extrapolated"], t["ratio"]) +
              ("   baseline %.3f%s" % (t["baseline_ratio"], t["baseline_extrapolated"]) if "baseline_ratio" in t else ""))


if __name__ == "__main__":
    main()
