"""Renders of several fluence configurations over seeds, interleaved, for the tools that measure the
error per sample by the spread over seeds (seed_variance.py, subsurface_split.py).

A configuration is NAME=FLUENCE[:FLAGS] (FLAGS: extra render arguments, space-separated). Seeds
FIRST_SEED, FIRST_SEED + 1, ... render every configuration in turn, the order rotated per seed, so
the machine's load falls on all alike; each render's CPU is the user + sys time the `render`
summary reports.
"""
import os
import pathlib
import re
import subprocess
import sys

FIRST_SEED = 200


def parse_configs(specs):
    """[(name, binary, [flags])] from NAME=FLUENCE[:FLAGS] strings."""
    configs = []
    for spec in specs:
        name, rest = spec.split("=", 1)
        binary, _, flags = rest.partition(":")
        configs.append((name, binary, flags.split()))
    return configs


def interleaved(configs, seeds):
    """(seed, name, binary, flags) for every seed and configuration, the order rotated per seed."""
    for i in range(seeds):
        for name, binary, flags in configs[i % len(configs):] + configs[:i % len(configs)]:
            yield FIRST_SEED + i, name, binary, flags


def render_cpu(binary, scene, spp, seed, res, out, args):
    """Renders SCENE at RES x RES with 2 threads into OUT; returns its render CPU seconds. Exits with
    the command and its output if the render fails."""
    cmd = [binary, "render", str(scene), "--spp", str(spp), "--seed", str(seed), "-r", str(res), str(res),
           "-j", "2", "-o", str(out), *args]
    r = subprocess.run(cmd, capture_output=True, text=True, env=dict(os.environ))
    m = re.search(r"render [0-9.]+ s \(([0-9.]+) s CPU\)", r.stdout + r.stderr)
    if r.returncode != 0 or not m:
        sys.exit("%s failed:\n%s%s" % (" ".join(cmd), r.stdout, r.stderr))
    return float(m.group(1))


def add_arguments(parser):
    """The arguments both tools take: SCENE SPP SEEDS OUT_DIR NAME=FLUENCE[:FLAGS] ... [--res N]."""
    parser.add_argument("scene")
    parser.add_argument("spp", type=int)
    parser.add_argument("seeds", type=int)
    parser.add_argument("out", type=pathlib.Path)
    parser.add_argument("configs", nargs="+", help="NAME=FLUENCE[:FLAGS]")
    parser.add_argument("--res", type=int, default=128)
