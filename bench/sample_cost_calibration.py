#!/usr/bin/python3
"""The weights of integrators/sample_cost.h, from the CPU time of uniform renders.

  bench/sample_cost_calibration.py FLUENCE OUT_DIR [--res N] [--spp LO HI] [--scenes A,B] [--repeat N]
                                   [--peer-scenes DIR] [--tiles K [--tile-spp N] [--refit]]

Renders each scene of bench/adaptive_compare.py uniformly at LO and HI spp (default 16 and 144),
the scenes and the two counts alternating, REPEAT times (default 2); the least CPU time (user +
system, from the kernel) of each is kept. The differences between HI and LO remove the scene's
loading: per scene, the CPU time dT of the extra samples and what they counted (the summary's
rays, medium collisions, guided random-walk steps and samples: deterministic). Then
dT = a (rays + w steps + m collisions), the cost of integrators/sample_cost.h, is solved by least
squares over the scenes and kMediumCollisionCost = m printed, with each scene's time as the fit
predicts it (how far one weight fits every scene); and, as a check, the fit with a per-sample term
as well (dT = a (rays + w steps) + b collisions + c samples). This was the weights' fit up to
session 19 (every ray 1); the header's weights now come from --tiles, which fits each kind.

The walk steps' weight w is not fitted here but read from integrators/sample_cost.h
(kWalkStepCost): a whole scene's rays and walk steps grow together (only the subsurface scene has
steps, in proportion to its rays), so the scenes cannot tell them apart; w is fitted over the
subsurface scene's tiles instead (--tiles, below). Charging the steps at w
keeps their time out of a and m.

With --tiles K: the kinds apart. Each scene is rendered as K x K tiles (`--tile-count K K`), one
thread, TILE_SPP samples per pixel (default 1024), REPEAT rounds, the tiles and scenes interleaved;
of each tile the least of the render's own CPU time (the summary's "render ... (X s CPU)", scene
loading left out) and what it counted: camera, bounce and shadow rays, medium collisions, walk
steps, exact-flight cells and flights, and missed samples (the camera rays times 1 - the tile's mean alpha: a
sample whose camera ray met nothing; "camera" counts the others). Written to OUT_DIR/tiles.csv;
--refit fits that file again without rendering. A scene's tiles see the kinds in different
proportions (the Cornell box's tiles trace 1.5-3.0 bounce rays a sample, the peers' background
tiles are all missed samples), which the whole-scene differences cannot. Fitted by non-negative
least squares, each tile's equation divided by its CPU (each tile weighs alike), CPU = sum of
(seconds per item) x (items) over the kinds, in two stages: the ray kinds (camera, bounce, shadow)
over the scenes that trace rays only (the Cornell box: in the others bounce and shadow rays come
together and cannot be told apart), then each other scene's own kinds with those fixed: first the
scenes that start no exact flight, whose missed samples (the geometric mean over the scenes with
tiles of missed samples only) are a missed sample's own cost, then, with that fixed too, the scenes
with flights (a missed sample there is its camera ray and an exact flight that walks no cell).
Printed: the seconds per item and the weights in shadow rays (integrators/sample_cost.h's unit),
and per scene the tiles' CPU over the prediction of a free fit of its kinds, of the staged fit and
of sample_cost.h's weights, the last two over their mean in the scene (adaptive sampling compares a
scene's pixels with each other only); rms: how far one set of weights fits.
"""
import argparse
import csv
import os
import pathlib
import re
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import adaptive_compare  # noqa: E402


def header_weight(name, fallback=None):
    """The constant `name` of integrators/sample_cost.h (`fallback` if it has none)."""
    header = (adaptive_compare.ROOT / "integrators/sample_cost.h").read_text()
    found = re.search(r"%s = ([0-9.]+);" % name, header)
    return float(found.group(1)) if found else fallback


def walk_step_cost():
    """kWalkStepCost of integrators/sample_cost.h."""
    return header_weight("kWalkStepCost")


def header_weights():
    """integrators/sample_cost.h's weights by KINDS (a kind it does not weigh costs 1 ray)."""
    names = {"camera": "kCameraRayCost", "bounce": "kBounceRayCost", "shadow": "kShadowRayCost",
             "collisions": "kMediumCollisionCost", "steps": "kWalkStepCost", "cells": "kExactCellCost",
             "flights": "kExactFlightCost", "missed": "kMissedCameraRayCost"}
    return {kind: header_weight(name, 1.0) for kind, name in names.items()}


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


KINDS = ("camera", "bounce", "shadow", "collisions", "steps", "cells", "flights", "missed")


def tile_counts(image, spp):
    """The render's own CPU seconds and its counts by KINDS, from the tile's summary and alpha."""
    counts = dict.fromkeys(KINDS, 0.0)
    cpu = None
    for line in open(str(image) + ".log"):
        if re.match(r"\s*time\s", line):
            cpu = float(re.search(r"render [0-9.]+ s \(([0-9.]+) s CPU\)", line).group(1))
        elif "throughput" in line and "rays:" in line:
            kinds = re.search(r"(\d+) camera, (\d+) bounce, (\d+) shadow", line).groups()
            counts["camera"], counts["bounce"], counts["shadow"] = map(float, kinds)
        elif line.strip().startswith("media") and "tentative collisions" in line:
            counts["collisions"] = float(line.split()[1])
        elif line.strip().startswith("interiors") and "guided random-walk steps" in line:
            counts["steps"] = float(line.split()[1])
        elif line.strip().startswith("exact") and "grid cells" in line:
            counts["cells"] = float(line.split()[1])
            flights = re.search(r"walked by (\d+) exact flights", line)
            counts["flights"] = float(flights.group(1)) if flights else 0.0
    alpha = subprocess.run(["oiiotool", str(image), "--ch", "A", "--printstats"], capture_output=True, text=True,
                           check=True).stdout
    mean = float(re.search(r"Stats Avg: ([0-9.eE+-]+)", alpha).group(1))
    counts["missed"] = counts["camera"] * (1.0 - mean)
    counts["camera"] -= counts["missed"]  # the camera rays of the samples that met something
    return cpu, counts


def fit_tiles(rows, kinds, fixed=None):
    """Non-negative seconds per item of `kinds`, fitted as CPU = sum(w x) with the `fixed` kinds'
    time known, each tile's equation divided by its CPU; all the weights, and each tile's CPU over
    the fit's prediction."""
    fixed = fixed or {}
    t = np.array([r[0] for r in rows])
    known = np.array([sum(w * r[1][k] for k, w in fixed.items()) for r in rows])
    x = np.array([[r[1][k] for k in kinds] for r in rows])
    w = nnls(x / t[:, None], 1.0 - known / t)
    return dict(fixed, **dict(zip(kinds, w))), t / (known + x @ w)


def rms(ratio):
    return np.sqrt(np.mean((ratio - 1.0) ** 2))


def nnls(a, b):
    """min |a w - b| with w >= 0 (Lawson-Hanson, active set: the few columns here need no scipy)."""
    n = a.shape[1]
    passive, w = np.zeros(n, bool), np.zeros(n)
    for _ in range(3 * n):
        gradient = a.T @ (b - a @ w)
        if passive.all() or gradient[~passive].max() <= 1e-12:
            break
        passive[np.argmax(np.where(passive, -np.inf, gradient))] = True
        while True:
            z = np.zeros(n)
            z[passive] = np.linalg.lstsq(a[:, passive], b, rcond=None)[0]
            if (z[passive] > 0).all():
                w = z
                break
            blocked = passive & (z <= 0)
            step = np.min(w[blocked] / (w[blocked] - z[blocked]))
            w = w + step * (z - w)
            passive &= w > 1e-15
    return w


def render_tiles(binary, args, out, scenes):
    """Renders the tiles (see the module's doc); writes and returns the rows of OUT_DIR/tiles.csv."""
    k = args.tiles
    cpu = {}
    for _ in range(args.repeat):
        for tile in range(k * k):
            for s in scenes:
                path, extra = adaptive_compare.SCENES[s]
                cmd = [binary, "render", str(pathlib.Path(args.peer_scenes) / path), *extra, "-r", str(args.res),
                       str(args.res), "-j", "1", "--spp", str(args.tile_spp), "--seed", "0", "--tile-count", str(k),
                       str(k), "--tile-index", str(tile), "-o", str(out / ("%s.exr" % s))]
                tiled = out / ("%s_tile%d.exr" % (s, tile))
                with open(str(tiled) + ".log", "w") as log:
                    subprocess.run(cmd, stdout=log, stderr=subprocess.STDOUT, check=True)
                cpu.setdefault((s, tile), []).append(tile_counts(tiled, args.tile_spp)[0])
                print("%s tile %d: %.3f CPU s" % (s, tile, cpu[(s, tile)][-1]), flush=True)
    rows = []
    for s in scenes:
        for tile in range(k * k):
            counts = tile_counts(out / ("%s_tile%d.exr" % (s, tile)), args.tile_spp)[1]
            rows.append(dict(scene=s, tile=tile, cpu_s=min(cpu[(s, tile)]),
                             cpu_runs=" ".join("%.3f" % c for c in cpu[(s, tile)]), **counts))
    with open(out / "tiles.csv", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    return rows


def calibrate_tiles(rows):
    """The staged fit of the tiles' rows (see the module's doc), printed."""
    scenes = list(dict.fromkeys(r["scene"] for r in rows))
    tiles = {s: [(float(r["cpu_s"]), {k: float(r.get(k) or 0.0) for k in KINDS}) for r in rows if r["scene"] == s]
             for s in scenes}
    has = {s: [k for k in KINDS if any(t[1][k] > 0 for t in tiles[s])] for s in scenes}
    rays = ("camera", "bounce", "shadow")
    rays_only = [s for s in scenes if not set(has[s]) - set(rays) - {"missed"}]
    if not rays_only:
        print("\nno scene traces rays only (the Cornell box): the ray kinds cannot be fitted; fit these tiles "
              "with such a scene's (tiles.csv rows together, --refit)")
        return
    weights, _ = fit_tiles([t for s in rays_only for t in tiles[s]], [k for k in rays + ("missed",)
                                                                      if any(k in has[s] for s in rays_only)])
    weights = {k: weights[k] for k in rays}
    missed = {}
    # Scenes whose missed samples start no exact flight first: their background tiles give a missed
    # sample's own cost, which the scenes with flights then keep (their missed samples' flights are
    # the flights' weight, not the missed sample's).
    for s in sorted((s for s in scenes if s not in rays_only), key=lambda s: "flights" in has[s]):
        fixed = {k: weights[k] for k in rays}
        if missed and "flights" in has[s]:
            fixed["missed"] = float(np.exp(np.mean(np.log(list(missed.values())))))
        fitted, _ = fit_tiles(tiles[s], [k for k in has[s] if k not in fixed], fixed)
        weights.update({k: v for k, v in fitted.items() if k not in rays and k != "missed"})
        if "missed" not in fixed and any(t[1]["camera"] == 0 and t[1]["missed"] > 0 for t in tiles[s]):
            missed[s] = fitted["missed"]  # background tiles
    weights["missed"] = float(np.exp(np.mean(np.log(list(missed.values()))))) if missed else 0.0
    print("\nthe ray kinds from %s; a missed sample: %s" %
          (", ".join(rays_only), ", ".join("%.1f ns in %s" % (v * 1e9, s) for s, v in missed.items())))
    print("  ".join("%s %.1f ns (%.2f)" % (k, weights[k] * 1e9, weights[k] / weights["shadow"]) for k in KINDS
                    if k in weights))
    header = header_weights()
    print("\ntiles' CPU over the prediction, per scene: a free fit of its kinds, the staged fit, sample_cost.h")
    for s in scenes:
        seconds = np.array([t[0] for t in tiles[s]])
        _, free = fit_tiles(tiles[s], has[s])
        staged = seconds / np.array([sum(weights.get(k, 0.0) * t[1][k] for k in KINDS) for t in tiles[s]])
        model = seconds / np.array([sum(header[k] * t[1][k] for k in KINDS) for t in tiles[s]])
        for name, ratio in (("free", free), ("staged", staged / np.mean(staged)), ("header", model / np.mean(model))):
            print("%-8s %-7s %s (rms %.3f)" % (s, name, " ".join("%.2f" % r for r in ratio), rms(ratio)))


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("fluence")
    p.add_argument("out")
    p.add_argument("--res", type=int, default=128)
    p.add_argument("--spp", type=int, nargs=2, default=[16, 144])
    p.add_argument("--scenes", default="cornell,smoke,sss")
    p.add_argument("--repeat", type=int, default=2)
    p.add_argument("--peer-scenes", default=str(adaptive_compare.ROOT / "bench/peer_scenes"))
    p.add_argument("--tiles", type=int, default=0, help="fit the ray kinds over K x K tiles of each scene")
    p.add_argument("--tile-spp", type=int, default=1024)
    p.add_argument("--refit", action="store_true", help="with --tiles: fit OUT_DIR/tiles.csv again, no rendering")
    args = p.parse_args()
    args.sampler = None
    binary = str(pathlib.Path(args.fluence).resolve())
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    scenes = args.scenes.split(",")
    if args.tiles:
        if args.refit:
            with open(out / "tiles.csv") as f:
                calibrate_tiles(list(csv.DictReader(f)))
        else:
            calibrate_tiles(render_tiles(binary, args, out, scenes))
        return
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
