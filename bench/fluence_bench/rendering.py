"""Runs one render, Fluence's or Cycles', and returns what it cost.

Every render writes its log beside its image (IMAGE.log). The result holds the exit code, the
wall time of the whole process and its CPU time (user + system, from wait4), its peak resident
memory (ru_maxrss, so no /usr/bin/time is needed), and what the renderer itself reports: for
fluence the summary lines 'time ... render S s (C s CPU)' and 'throughput X Msamples/s, Y
Mrays/s', and the stderr warning that counts NaN or infinite samples; for Cycles the render time
it writes into the EXR header (cycles.ViewLayer.render_time, after its scene sync) and the CPU
time of Blender's render call (bench/cycles_render_cpu.py, which runs the peer's scenes.py).
"""
import os
import re
import shutil
import subprocess
import time

from . import scenes

PEER_SOURCE = scenes.ROOT.parent / "shared" / "peers" / "cycles"
SCENE_REFUSED = 3  # fluence's exit code for a scene error, and for an integrator that refuses the scene


def run_logged(cmd, log, cwd=None):
    """Runs CMD with its output in LOG; returns (exit code, wall seconds, peak RSS in MiB, log text,
    the process's CPU seconds)."""
    start = time.monotonic()
    with open(log, "w") as out:
        proc = subprocess.Popen(cmd, stdout=out, stderr=subprocess.STDOUT, cwd=cwd)
        _, status, usage = os.wait4(proc.pid, 0)
    wall = time.monotonic() - start
    proc.returncode = os.waitstatus_to_exitcode(status)
    return proc.returncode, wall, usage.ru_maxrss / 1024.0, open(log, errors="replace").read(), \
        usage.ru_utime + usage.ru_stime


def _number(pattern, text, default=float("nan")):
    m = re.search(pattern, text)
    return float(m.group(1)) if m else default


def fluence(binary, scene_path, method, spp, seed, res, out, scene_extra=(), time_limit=0.0):
    """Renders SCENE_PATH with METHOD at SPP and SEED on 2 threads into OUT (an .exr); with TIME_LIMIT,
    no new sample pass starts after that many seconds, and `spp` in the result is the count reached."""
    cmd = [binary, "render", str(scenes.ROOT / scene_path), "--integrator", method.integrator, *method.extra,
           *scene_extra, "--spp", str(spp), "--seed", str(seed), "-r", str(res[0]), str(res[1]), "-j", "2",
           "--time-limit", str(time_limit), "-o", str(out)]
    code, wall, rss, log, cpu = run_logged(cmd, str(out) + ".log")
    return {"renderer": "fluence", "res": "%dx%d" % tuple(res), "exit_code": code, "wall_s": wall, "peak_mib": rss,
            "process_cpu_s": cpu, "spp": int(_number(r"(\d+) spp, integrator", log, 0)),
            "render_s": _number(r"render ([0-9.]+) s", log),
            "cpu_s": _number(r"render [0-9.]+ s \(([0-9.]+) s CPU\)", log),
            "msamples_per_s": _number(r"throughput\s+([0-9.]+) Msamples/s", log),
            "mrays_per_s": _number(r"Msamples/s, ([0-9.]+) Mrays/s", log),
            "nonfinite_samples": int(_number(r"(\d+) samples were NaN or infinite", log, 0))}


def peer_dir(cache, source=PEER_SOURCE):
    """A writable copy of the peer's folder SOURCE (its scripts write beside themselves) in CACHE."""
    copy = cache / "cycles_peer"
    if not (copy / "scenes.py").exists():
        shutil.copytree(source, copy, ignore=shutil.ignore_patterns("ref", "series", "out", "preview"))
        for f in copy.rglob("*"):  # the shared folder is read-only, and so are the copies of its files
            f.chmod(f.stat().st_mode | 0o200)
    return copy


def cycles_available(source=PEER_SOURCE):
    return shutil.which("blender") is not None and (source / "scenes.py").exists()


def _cycles_render_time(exr):
    import OpenImageIO as oiio
    spec = oiio.ImageInput.open(str(exr)).spec()
    for attr in spec.extra_attribs:
        if attr.name.startswith("cycles.") and attr.name.endswith(".render_time"):
            seconds = 0.0
            for part in str(attr.value).split(":"):
                seconds = seconds * 60.0 + float(part)
            return seconds
    return float("nan")


CPU_PROBE = scenes.ROOT / "bench" / "cycles_render_cpu.py"


def cycles(peer, peer_scene, spp, seed, res, out, peer_args=()):
    """Renders the peer's scene PEER_SCENE with Cycles at SPP and SEED on 2 threads into OUT
    (PEER_ARGS: more of scenes.py's options). `render_call_cpu_s` is the CPU time of Blender's
    render call (scene sync, render, EXR write), the raw figure peer_suite.py derives the render's
    CPU time from."""
    cmd = ["blender", "-b", "--factory-startup", "-P", str(CPU_PROBE), "--", "--peer-scenes", str(peer / "scenes.py"),
           "--scene", peer_scene, "--spp", str(spp), "--seed", str(seed), "--out", str(out),
           "--res", str(res[0]), str(res[1]), "--threads", "2", *peer_args]
    if os.path.exists(out):
        os.remove(out)
    code, wall, rss, log, cpu = run_logged(cmd, str(out) + ".log", cwd=peer)
    if code == 0 and not os.path.exists(out):
        code = 1  # blender exits with 0 even when the script fails
    render_s = _cycles_render_time(out) if code == 0 else float("nan")
    return {"renderer": "cycles", "res": "%dx%d" % tuple(res), "exit_code": code, "wall_s": wall, "peak_mib": rss,
            "process_cpu_s": cpu, "spp": spp, "render_s": render_s,
            "render_call_cpu_s": _number(r"RENDER_CPU .*\"render_call_cpu_s\": ([0-9.]+)", log),
            "msamples_per_s": res[0] * res[1] * spp / render_s / 1e6 if render_s > 0 else float("nan"),
            "mrays_per_s": float("nan"),
            "nonfinite_samples": 0}
