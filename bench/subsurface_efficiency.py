#!/usr/bin/python3
"""Subsurface walks against each other (issue #25 item 3): relMSE per sample and CPU per sample.

  bench/subsurface_efficiency.py OUT_DIR NAME=FLUENCE:METHOD ... [--ref FLUENCE] [--ref-spp N]
                                 [--spp N] [--seeds N] [--scenes subsurface,peer_sss]

Each variant NAME is a fluence binary and a --subsurface method (randomwalk, randomwalk_guided),
so that builds of two commits can be compared. For each scene (the subsurface sample at 160 x 120;
the Cycles peer's matched scene, bench/peer_scenes/cycles_sss.usda, at 128 x 128 with
--subdiv-level 4): the reference is the classic walk of the --ref binary (default: the first
variant's) as two halves of REF_SPP / 2 samples (seeds 1001, 1002; kept if present), whose own
noise is subtracted (fluence_bench/metrics.py), rendered with the light path expression layer
`sss` (paths with a subsurface scattering). The subsurface pixels are those where that layer holds
at least half of the reference's light. Then for seeds 1..SEEDS the variants render in turn
(A B C A B C ...) at SPP samples and at 1 sample, on 2 threads; a render's CPU time is the user +
system time of its process, and the CPU per sample is (CPU at SPP - CPU at 1 spp) / (SPP - 1), so
that parsing and building the scene (the peer's level-4 subdivision) is left out. relMSE is over
R, G, B with eps 0.01, over the whole image and over the subsurface pixels; relMSE x SPP is the
relMSE of one sample per pixel. Writes OUT_DIR/series.csv and prints a summary: per variant the
means over the seeds, and the ratios to the first variant (mean, min and max over seeds, each seed's
renders against the first variant's of the same seed).

--split renders the SPP images with the `sss` layer too (which costs time: use it for errors, not
for CPU) and splits the subsurface pixels' relMSE between the paths with a subsurface scattering and
the others (relmse_sss_paths, relmse_other_paths: each layer's squared error, its reference noise
subtracted, over the reference's (R^2 + eps); they add up to the pixels' relMSE but for the
covariance of the two within a sample).
"""
import argparse
import csv
import pathlib
import resource
import subprocess
import sys

import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from fluence_bench import metrics  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parent.parent
SCENES = {
    "subsurface": ["usd_samples/subsurface/subsurface.usda", "-r", "160", "120"],
    "peer_sss": ["bench/peer_scenes/cycles_sss.usda", "-r", "128", "128", "--subdiv-level", "4"],
}
SSS_LPE = "sss=C.*<V'subsurface'>.*[LO]"


def render(binary, scene, method, spp, seed, out, lpe=False):
    """Renders and returns the CPU seconds (user + system) of the fluence process."""
    scene_file, *extra = SCENES[scene]
    args = [binary, "render", str(ROOT / scene_file), *extra, "--integrator", "path", "--subsurface", method,
            "--spp", str(spp), "--seed", str(seed), "-j", "2", "-o", str(out)] + (["--lpe", SSS_LPE] if lpe else [])
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    with open(out.with_suffix(".log"), "w") as log:
        code = subprocess.run(args, stdout=log, stderr=subprocess.STDOUT).returncode
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if code:
        sys.exit("%s failed (exit %d); see %s" % (" ".join(args), code, out.with_suffix(".log")))
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def layer(path, names):
    import OpenImageIO as oiio
    buf = oiio.ImageBuf(str(path))
    channels = list(buf.spec().channelnames)
    pixels = np.asarray(buf.get_pixels(oiio.FLOAT), dtype=np.float64)
    return pixels[:, :, [channels.index(n) for n in names]]


def subsurface_mask(half_a, half_b):
    """Pixels where paths with a subsurface scattering carry at least half of the reference's light."""
    beauty = sum(layer(h, ["R", "G", "B"]) for h in (half_a, half_b)).sum(axis=2)
    sss = sum(layer(h, ["sss.R", "sss.G", "sss.B"]) for h in (half_a, half_b)).sum(axis=2)
    return (beauty > 0) & (sss >= 0.5 * beauty)


def errors(ref, mask, image):
    x = metrics.read_rgb(image)
    x = np.where(np.isfinite(x), x, 0.0)
    per_pixel = ((x - ref.mean) ** 2 - ref.variance) / (ref.mean ** 2 + metrics.REL_EPS)
    return float(per_pixel.mean()), float(per_pixel[mask].mean())


def split_errors(ref, mask, halves, image):
    """The subsurface pixels' relMSE of the sss layer and of the rest of the beauty."""
    def parts(path):
        beauty, sss = layer(path, ["R", "G", "B"]), layer(path, ["sss.R", "sss.G", "sss.B"])
        return sss, beauty - sss
    out = []
    for (a, b, x) in zip(parts(halves[0]), parts(halves[1]), parts(image)):
        per_pixel = ((x - (a + b) / 2) ** 2 - (a - b) ** 2 / 4) / (ref.mean ** 2 + metrics.REL_EPS)
        out.append(float(per_pixel[mask].mean()))
    return out


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("out", type=pathlib.Path)
    p.add_argument("variants", nargs="+", help="NAME=FLUENCE:METHOD")
    p.add_argument("--ref", help="the binary of the classic reference (default: the first variant's)")
    p.add_argument("--ref-spp", type=int, default=1024)
    p.add_argument("--spp", type=int, default=64)
    p.add_argument("--seeds", type=int, default=3)
    p.add_argument("--scenes", default="subsurface,peer_sss")
    p.add_argument("--split", action="store_true", help="split the subsurface pixels' error by path (see above)")
    args = p.parse_args()
    variants = []
    for v in args.variants:
        name, rest = v.split("=", 1)
        binary, method = rest.rsplit(":", 1)
        variants.append((name, str(pathlib.Path(binary).resolve()), method))
    ref_binary = str(pathlib.Path(args.ref).resolve()) if args.ref else variants[0][1]
    args.out.mkdir(parents=True, exist_ok=True)
    rows = []
    for scene in args.scenes.split(","):
        halves = [args.out / ("%s_ref_%s.exr" % (scene, h)) for h in "ab"]
        for half, seed in zip(halves, (1001, 1002)):
            if not half.exists():
                cpu = render(ref_binary, scene, "randomwalk", args.ref_spp // 2, seed, half, lpe=True)
                print("%s reference half %s: %.1f CPU s" % (scene, half.name, cpu), flush=True)
        ref = metrics.Reference(*halves, args.ref_spp)
        mask = subsurface_mask(*halves)
        print("%s: reference own relMSE %.5f; %d subsurface pixels of %d" % (
            scene, ref.noise()["ref_relmse"], mask.sum(), mask.size), flush=True)
        for seed in range(1, args.seeds + 1):
            for name, binary, method in variants:
                base = args.out / ("%s_%s_seed%d" % (scene, name, seed))
                image = base.with_name(base.name + "_spp%d.exr" % args.spp)
                cpu = render(binary, scene, method, args.spp, seed, image, lpe=args.split)
                cpu1 = render(binary, scene, method, 1, seed, base.with_name(base.name + "_spp1.exr"), lpe=args.split)
                whole, sss = errors(ref, mask, image)
                row = {"scene": scene, "variant": name, "method": method, "seed": seed, "spp": args.spp,
                       "cpu_s": round(cpu, 3), "cpu_1spp_s": round(cpu1, 3),
                       "cpu_per_spp": (cpu - cpu1) / (args.spp - 1), "relmse": whole, "relmse_sss": sss}
                if args.split:
                    row["relmse_sss_paths"], row["relmse_other_paths"] = split_errors(ref, mask, halves, image)
                    print("  subsurface pixels: sss paths %.5f, other paths %.5f" % (
                        row["relmse_sss_paths"], row["relmse_other_paths"]), flush=True)
                rows.append(row)
                print("%s seed %d %-12s CPU %.2f s (1 spp %.2f s), relMSE %.5f, subsurface pixels %.5f" % (
                    scene, seed, name, cpu, cpu1, whole, sss), flush=True)
    with open(args.out / "series.csv", "a", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        if f.tell() == 0:
            writer.writeheader()
        writer.writerows(rows)
    summarize(rows, [v[0] for v in variants])


def summarize(rows, names):
    print("\nscene, variant: means over seeds | ratios to %s per seed: mean [min, max]" % names[0])
    for scene in dict.fromkeys(r["scene"] for r in rows):
        first = {r["seed"]: r for r in rows if r["scene"] == scene and r["variant"] == names[0]}
        for name in names:
            mine = [r for r in rows if r["scene"] == scene and r["variant"] == name]
            line = "%s %-12s CPU/spp %.4f s, relMSE %.5f, subsurface %.5f, relMSE/spp x CPU/spp (sss) %.3g" % (
                scene, name, np.mean([r["cpu_per_spp"] for r in mine]), np.mean([r["relmse"] for r in mine]),
                np.mean([r["relmse_sss"] for r in mine]),
                np.mean([r["relmse_sss"] * r["spp"] * r["cpu_per_spp"] for r in mine]))
            for key in ("cpu_per_spp", "relmse", "relmse_sss"):
                ratios = [r[key] / first[r["seed"]][key] for r in mine]
                line += " | %s %.3f [%.3f, %.3f]" % (key, np.mean(ratios), min(ratios), max(ratios))
            eff = [r["relmse_sss"] * r["cpu_per_spp"] / (first[r["seed"]]["relmse_sss"] * first[r["seed"]]["cpu_per_spp"])
                   for r in mine]
            line += " | relMSE(sss) x CPU %.3f [%.3f, %.3f]" % (np.mean(eff), min(eff), max(eff))
            print(line)


if __name__ == "__main__":
    main()
