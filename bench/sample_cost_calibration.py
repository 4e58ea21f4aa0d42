#!/usr/bin/python3
"""The weights of integrators/sample_cost.h, from the CPU time of uniform renders.

  bench/sample_cost_calibration.py FLUENCE OUT_DIR [--res N] [--spp LO HI] [--scenes A,B] [--repeat N]
                                   [--peer-scenes DIR]

Renders each scene of bench/adaptive_compare.py uniformly at LO and HI spp (default 16 and 144),
the scenes and the two counts alternating, REPEAT times (default 2); the least CPU time (user +
system, from the kernel) of each is kept. The differences between HI and LO remove the scene's
loading: per scene, the CPU time dT of the extra samples and what they counted (the summary's
rays, medium collisions, guided random-walk steps and samples: deterministic). Then
dT = a (rays + w steps + m collisions), the cost of integrators/sample_cost.h, is solved by least
squares over the scenes and kMediumCollisionCost = m printed, with each scene's time as the fit
predicts it (how far one weight fits every scene); and, as a check, the fit with a per-sample term
as well (dT = a (rays + w steps) + b collisions + c samples).

The walk steps' weight w is not fitted here but read from integrators/sample_cost.h
(kWalkStepCost): a whole scene's rays and walk steps grow together (only the subsurface scene has
steps, in proportion to its rays), so the scenes cannot tell them apart; w was fitted over the
subsurface scene's tiles instead (bench/results/2026-12-06-adaptive-5.md). Charging the steps at w
keeps their time out of a and m.
"""
import argparse
import os
import pathlib
import re
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import adaptive_compare  # noqa: E402


def walk_step_cost():
    """kWalkStepCost of integrators/sample_cost.h."""
    header = (adaptive_compare.ROOT / "integrators/sample_cost.h").read_text()
    return float(re.search(r"kWalkStepCost = ([0-9.]+);", header).group(1))


def counted(out):
    """The summary's rays, medium collisions, samples and guided random-walk steps."""
    rays = collisions = samples = steps = 0
    for line in open(str(out) + ".log"):
        if "throughput" in line and "rays:" in line:
            rays = int(line.split("(")[1].split()[0])
        elif line.strip().startswith("media") and "tentative collisions" in line:
            collisions = int(line.split()[1])
        elif line.strip().startswith("interiors") and "guided random-walk steps" in line:
            steps = int(line.split()[1])
        elif re.match(r"\s*image\s+\d+ x \d+, \d+ spp", line):
            width, height, spp = map(int, re.match(r"\s*image\s+(\d+) x (\d+), (\d+) spp", line).groups())
            samples = width * height * spp
    return rays, collisions, samples, steps


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("fluence")
    p.add_argument("out")
    p.add_argument("--res", type=int, default=128)
    p.add_argument("--spp", type=int, nargs=2, default=[16, 144])
    p.add_argument("--scenes", default="cornell,smoke,sss")
    p.add_argument("--repeat", type=int, default=2)
    p.add_argument("--peer-scenes", default=str(adaptive_compare.ROOT / "bench/peer_scenes"))
    args = p.parse_args()
    args.sampler = None
    binary = str(pathlib.Path(args.fluence).resolve())
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    scenes = args.scenes.split(",")
    cpu = {(s, n): [] for s in scenes for n in args.spp}
    for _ in range(args.repeat):
        for s in scenes:
            for n in args.spp:
                image = out / ("%s_%d.exr" % (s, n))
                cpu[(s, n)].append(adaptive_compare.render(binary, s, args, image, ["--spp", str(n), "--seed", "0"]))
                print("%s %d spp: %.2f CPU s" % (s, n, cpu[(s, n)][-1]), flush=True)
    lo, hi = args.spp
    w = walk_step_cost()
    rows, steps, times = [], [], []
    for s in scenes:
        a, b = counted(out / ("%s_%d.exr" % (s, lo))), counted(out / ("%s_%d.exr" % (s, hi)))
        rows.append([b[0] - a[0] + w * (b[3] - a[3]), b[1] - a[1], b[2] - a[2]])  # rays + w steps, collisions, samples
        steps.append(b[3] - a[3])
        times.append(min(cpu[(s, hi)]) - min(cpu[(s, lo)]))
    counts, times = np.array(rows, dtype=float), np.array(times)
    x, *_ = np.linalg.lstsq(counts[:, :2], times, rcond=None)
    free, *_ = np.linalg.lstsq(counts, times, rcond=None)
    print("\nwalk steps charged at kWalkStepCost = %g rays (integrators/sample_cost.h)" % w)
    print("\nscene    dT (s)  rays+w steps  walk steps  collisions  samples   predicted dT  (rays+w steps)/sample  collisions/sample")
    for s, r, n, t in zip(scenes, counts, steps, times):
        print("%-8s %6.2f  %-12d  %-10d  %-10d  %-8d  %6.2f        %6.2f                 %6.2f" %
              (s, t, r[0], n, r[1], r[2], float(np.dot(x, r[:2])), r[0] / r[2], r[1] / r[2]))
    print("\nper ray %.3g s; kMediumCollisionCost = %.3f rays" % (x[0], x[1] / x[0]))
    print("with a per-sample term: collisions %.3f rays, per sample %.3f rays" % (free[1] / free[0], free[2] / free[0]))

if __name__ == "__main__":
    main()
