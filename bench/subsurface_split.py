#!/usr/bin/env python3
"""Where a subsurface scene's error is: the per-sample relMSE (spread over seeds, no reference) split
by pixel (the skin, and the rest) and by path class (light path expressions), for several fluence
configurations rendered interleaved, and against Cycles renders of the same scene if given.

    /usr/bin/python3 bench/subsurface_split.py SCENE.usda SPP SEEDS OUT_DIR NAME=FLUENCE[:FLAGS] ...
        [--res 128] [--cycles 'DIR/c_*.exr']   (FLAGS: extra render arguments, e.g. "--subdiv-level 4")

Classes (events as integrators/light_path_expression.h names them; T is only the subsurface
material's boundary in the scenes this is for):
  surface     C[^T'subsurface']*[LO]          no subsurface walk on the path (specular layer, floor)
  exit_direct C<T>'subsurface'*<T>[LO]         the camera's point enters, one walk, light at its exit
  reentry     C<T>'subsurface'*<R>.*[LO]       the exit reflects the walk back inside
  after_exit  C<T>'subsurface'*<T>.+[LO]       bounces after the exit (floor, the skin again)
  other       the rest (beauty minus the four): walks entered after another surface
The skin pixels are those where the first configuration's paths with a walk carry at least half the
light (and the pixel is not black). relMSE = mean over pixels and channels of Var_seeds(X) /
(mean_seeds(beauty)^2 + 1e-2) (fluence_bench/metrics.py's epsilon), per class X over the same
denominator, so that the classes add up to the whole but for their covariance. Seeds 200, 201, ...
render every configuration in turn, the order rotated per seed; CPU is the median of the render
CPU the summary reports (the light path expressions' bookkeeping included, alike for all).
Under each configuration's line, its whole image's relMSE per channel (R, G, B: they average to whole).
With --cycles (a glob of Cycles renders of the same scene at the same spp, one seed each), their
whole, skin and rest relMSE over the same pixels.
"""
import argparse
import glob
import pathlib
import sys

import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from fluence_bench.metrics import REL_EPS  # noqa: E402
from fluence_bench.seeded import add_arguments, interleaved, parse_configs, render_cpu  # noqa: E402

LPES = {"surface": "C[^T'subsurface']*[LO]", "exit_direct": "C<T>'subsurface'*<T>[LO]",
        "reentry": "C<T>'subsurface'*<R>.*[LO]", "after_exit": "C<T>'subsurface'*<T>.+[LO]"}
CLASSES = ["all", *LPES, "other"]


def read_layers(path, layers):
    import OpenImageIO as oiio
    buf = oiio.ImageBuf(str(path))
    spec = buf.spec()
    pixels = np.asarray(buf.get_pixels(oiio.FLOAT), dtype=np.float64).reshape(spec.height, spec.width, -1)
    names = list(spec.channelnames)
    return {layer: pixels[..., [names.index(prefix + c) for c in "RGB"]]
            for layer, prefix in layers.items()}


def render(binary, flags, args, seed, out):
    lpes = [arg for name, expression in LPES.items() for arg in ("--lpe", "%s=%s" % (name, expression))]
    return render_cpu(binary, args.scene, args.spp, seed, args.res, out, [*flags, *lpes])


def rel_variance(stack, denominator):
    return (stack.var(axis=0, ddof=1) / denominator).mean(axis=-1)  # per pixel, channels averaged


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    add_arguments(p)
    p.add_argument("--cycles", help="glob of Cycles renders (one seed each) of the same scene")
    a = p.parse_args()
    if a.seeds < 4:
        p.error("SEEDS must be at least 4")
    configs = parse_configs(a.configs)
    a.out.mkdir(parents=True, exist_ok=True)
    layers = {"beauty": "", **{name: name + "." for name in LPES}}
    images = {name: [] for name, _, _ in configs}
    cpus = {name: [] for name, _, _ in configs}
    for seed, name, binary, flags in interleaved(configs, a.seeds):
        out = a.out / ("%s_%d.exr" % (name, seed))
        cpus[name].append(render(binary, flags, a, seed, out))
        images[name].append(read_layers(out, layers))

    first = np.array([d["beauty"] for d in images[configs[0][0]]]).mean(axis=0)
    without_walk = np.array([d["surface"] for d in images[configs[0][0]]]).mean(axis=0)
    lit = first.sum(axis=-1) > 0
    skin = lit & (without_walk.sum(axis=-1) <= 0.5 * first.sum(axis=-1))
    masks = {"skin": skin, "rest": ~skin}
    print("%d skin pixels of %d; relMSE at %d spp over %d seeds" % (skin.sum(), skin.size, a.spp, a.seeds))
    print("%-12s %8s %10s %6s  %s" % ("config", "CPU s", "whole", "skin%", " ".join(
        "%s:%s" % (m, c) for m in masks for c in CLASSES)))
    for name, _, _ in configs:
        stacks = {k: np.array([d[k] for d in images[name]]) for k in layers}
        stacks["all"] = stacks["beauty"]
        stacks["other"] = stacks["beauty"] - sum(stacks[k] for k in LPES)
        denominator = stacks["beauty"].mean(axis=0) ** 2 + REL_EPS
        whole = rel_variance(stacks["all"], denominator)
        cells = ["%.3e" % rel_variance(stacks[c], denominator)[mask].mean() for mask in masks.values() for c in CLASSES]
        print("%-12s %8.3f %10.4e %6.2f  %s" % (name, np.median(cpus[name]), whole.mean(),
                                             whole[skin].sum() / whole.sum(), " ".join(cells)))
        channels = (stacks["all"].var(axis=0, ddof=1) / denominator).mean(axis=(0, 1))
        print("%-12s per channel, whole image: R %.3e G %.3e B %.3e" % ("", *channels))
    if a.cycles:
        stack = np.array([read_layers(f, {"beauty": ""})["beauty"] for f in sorted(glob.glob(a.cycles))])
        whole = rel_variance(stack, stack.mean(axis=0) ** 2 + REL_EPS)
        print("%-12s %8s %10.4e %6.2f  skin:all %.3e rest:all %.3e (%d renders)" % (
            "cycles", "", whole.mean(), whole[skin].sum() / whole.sum(), whole[skin].mean(), whole[~skin].mean(),
            len(stack)))


if __name__ == "__main__":
    main()
