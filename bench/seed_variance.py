#!/usr/bin/env python3
"""Per-sample error and CPU time of several fluence configurations on one scene, interleaved, with
no reference: the error is measured by the spread over independent seeds.

    /usr/bin/python3 bench/seed_variance.py SCENE.usda SPP SEEDS OUT_DIR NAME=FLUENCE[:FLAGS] ...
        [--res 128]   (FLAGS: extra render arguments, space-separated, e.g. "--subdiv-level 4")

Seeds 200, 201, ... render every configuration in turn (the order rotated per seed, so the
machine's load falls on all alike). For each configuration: relMSE = the mean over pixels and
channels of Var_seeds(X) / (mean_seeds(X)^2 + 1e-2) (fluence_bench/metrics.py's epsilon; for an
unbiased renderer the variance is the MSE), the same over each half of the seeds (their agreement
is the figure's spread), the median CPU seconds of a render (user + sys, as `render` reports it),
and the ratios of relMSE, CPU and relMSE x CPU to the first configuration.
"""
import argparse
import pathlib
import sys

import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from fluence_bench.metrics import REL_EPS, read_rgb  # noqa: E402
from fluence_bench.seeded import add_arguments, interleaved, parse_configs, render_cpu  # noqa: E402


def rel_variance(images, mean):
    return float((images.var(axis=0, ddof=1) / (mean ** 2 + REL_EPS)).mean())


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    add_arguments(p)
    a = p.parse_args()
    if a.seeds < 4:
        p.error("SEEDS must be at least 4 (two halves of two)")
    configs = parse_configs(a.configs)
    a.out.mkdir(parents=True, exist_ok=True)
    images = {name: [] for name, _, _ in configs}
    cpus = {name: [] for name, _, _ in configs}
    for seed, name, binary, flags in interleaved(configs, a.seeds):
        out = a.out / ("%s_%d.exr" % (name, seed))
        cpus[name].append(render_cpu(binary, a.scene, a.spp, seed, a.res, out, flags))
        images[name].append(read_rgb(out))
    first = None
    for name, _, _ in configs:
        x = np.array(images[name])
        mean = x.mean(axis=0)
        rel = rel_variance(x, mean)
        h = len(x) // 2
        cpu = float(np.median(cpus[name]))
        first = first or (rel, cpu)
        print("%-10s relMSE %.4g (halves %.4g %.4g) ratio %.3f | CPU median %.3f s (%.2f-%.2f) ratio %.3f | "
              "relMSE x CPU ratio %.3f | image mean %s" % (
                  name, rel, rel_variance(x[:h], mean), rel_variance(x[h:], mean), rel / first[0], cpu,
                  min(cpus[name]), max(cpus[name]), cpu / first[1], rel * cpu / (first[0] * first[1]),
                  " ".join("%.4f" % v for v in mean.reshape(-1, 3).mean(axis=0))))


if __name__ == "__main__":
    main()
