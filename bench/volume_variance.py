#!/usr/bin/env python3
"""Per-sample error and CPU time of two fluence binaries on one scene, interleaved.

    /usr/bin/python3 bench/volume_variance.py --before FLUENCE_A --after FLUENCE_B --scene SCENE.usda
        --out DIR [--res 128] [--ref-spp 1024] [--spp 64] [--runs 4] [--threads 2] [-- EXTRA fluence args]

The reference is two renders by the `after` binary of REF_SPP samples each, seeds 1 and 2 (kept in
DIR if present: copy another binary's there to use it instead), combined as bench/fluence_bench/metrics.py's Reference (its own variance is
subtracted from every squared error). Then, RUNS times, each binary renders SPP samples with seed
10 + run, the two alternating so that the machine's load falls on both alike. For each render:
relMSE (metrics.py), relMSE x spp (the per-sample relMSE: constant for independent samples), and
the CPU seconds (user + sys of the render process, from wait4) per sample, after subtracting the
CPU of a 1-sample render of the same binary (scene loading). Prints one line per render, then per
binary the mean and range over the runs, and the ratio of efficiencies 1 / (relMSE x spp x CPU per
sample), after over before.
"""
import argparse
import os
import subprocess
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from fluence_bench.metrics import Reference  # noqa: E402


def render(binary, scene, out, res, spp, seed, threads, extra):
    """Renders and returns the CPU seconds (user + sys) the process used."""
    cmd = [binary, "render", scene, "-o", str(out), "-r", str(res), str(res), "--spp", str(spp), "--seed", str(seed),
           "-j", str(threads)] + extra
    with open(str(out) + ".log", "w") as log:
        proc = subprocess.Popen(cmd, stdout=log, stderr=subprocess.STDOUT)
        _, status, usage = os.wait4(proc.pid, 0)
    if status != 0:
        sys.exit(f"failed ({status}): {' '.join(cmd)}")
    return usage.ru_utime + usage.ru_stime


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--before", required=True)
    p.add_argument("--after", required=True)
    p.add_argument("--scene", required=True)
    p.add_argument("--out", required=True)
    p.add_argument("--res", type=int, default=128)
    p.add_argument("--ref-spp", type=int, default=1024)
    p.add_argument("--spp", type=int, default=64)
    p.add_argument("--runs", type=int, default=4)
    p.add_argument("--threads", type=int, default=2)
    p.add_argument("extra", nargs="*", help="extra fluence render arguments, after --")
    a = p.parse_args()
    out = Path(a.out)
    out.mkdir(parents=True, exist_ok=True)
    halves = [out / f"ref_{seed}.exr" for seed in (1, 2)]
    for seed, half in zip((1, 2), halves):
        if not half.exists():
            cpu = render(a.after, a.scene, half, a.res, a.ref_spp, seed, a.threads, a.extra)
            print(f"reference half seed {seed}: {a.ref_spp} spp, {cpu:.1f} CPU s", flush=True)
    ref = Reference(halves[0], halves[1], 2 * a.ref_spp)
    print(f"reference noise: relMSE {ref.noise()['ref_relmse']:.3g}")
    binaries = {"before": a.before, "after": a.after}
    overhead = {name: render(b, a.scene, out / f"{name}_spp1.exr", a.res, 1, 0, a.threads, a.extra)
                for name, b in binaries.items()}
    rows = {name: [] for name in binaries}
    print("binary,run,relmse,relmse_x_spp,cpu_s,cpu_per_spp_ms,bias,bias_se")
    for run in range(a.runs):
        for name, binary in binaries.items():
            img = out / f"{name}_spp{a.spp}_run{run}.exr"
            cpu = render(binary, a.scene, img, a.res, a.spp, 10 + run, a.threads, a.extra)
            e = ref.error(img)
            per_spp = max(cpu - overhead[name], 1e-9) / (a.spp - 1)
            rows[name].append((e["relmse"] * a.spp, per_spp))
            print(f"{name},{run},{e['relmse']:.5g},{e['relmse'] * a.spp:.5g},{cpu:.2f},{per_spp * 1e3:.2f},"
                  f"{e['bias']:.4f},{e['bias_se']:.4f}", flush=True)
    for name in binaries:
        r = [x for x, _ in rows[name]]
        c = [y for _, y in rows[name]]
        print(f"{name}: relMSE x spp {sum(r) / len(r):.4g} ({min(r):.4g}-{max(r):.4g}), CPU ms/spp "
              f"{1e3 * sum(c) / len(c):.3g} ({1e3 * min(c):.3g}-{1e3 * max(c):.3g}), overhead {overhead[name]:.2f} s")
    ratios = [(rb * cb) / (ra * ca) for (rb, cb), (ra, ca) in zip(rows["before"], rows["after"])]
    print(f"efficiency after / before, per interleaved pair: {', '.join(f'{x:.2f}' for x in ratios)}")


if __name__ == "__main__":
    main()
