"""Two of the suites: `figures` (Fluence's methods against time, per scene) and `stability`; the
third, `cycles` (Fluence against Cycles), is peer_suite.py.

Both render each scene's reference as two cached halves (bench/cache/, seeds 1 and 2; metrics.py
says why), then climb a ladder, every method taking its turn at each rung so that the machine's
load falls on all alike, and measure each image against the reference. The figures ladder is
one of time budgets (fluence --time-limit; so every method costs the same and slow methods take
fewer samples), the stability ladder one of sample counts (its slope is the variance trend per
sample). A method that exits with code 3
(the scene refused) is recorded as refused and left out of the later rungs, and so is one whose
render outlasted the largest budget (a start-up cost such as radiosity's solve: its later rungs
would only repeat it). Each render gives one
CSV row (ROW_FIELDS).
"""
import hashlib
import re
import subprocess
import sys

from . import metrics, rendering, scenes

ROW_FIELDS = ("suite", "scene", "method", "renderer", "res", "budget_s", "spp", "seed", "repeat", "status", "exit_code",
              "wall_s", "render_s", "cpu_s", "process_cpu_s", "render_call_cpu_s",
              "msamples_per_s", "mrays_per_s", "peak_mib", "nonfinite_samples", "nonfinite_pixels", "relmse",
              "relmse_uncorrected", "mare", "ref_spp", "ref_relmse", "ref_mare", "bias", "bias_se", "bias_significant", "misses",
              "channel_bias")


class Context:
    """What every render of a run shares: the binary, the cache folder, the two ladders, quick mode,
    whether Cycles renders and the Cycles peer's folder."""

    def __init__(self, binary, cache, budgets, spp_rungs, quick, cycles, peer_source=rendering.PEER_SOURCE):
        self.binary, self.cache, self.quick, self.cycles = binary, cache, quick, cycles
        self.budgets, self.spp_rungs, self.peer_source = budgets, spp_rungs, peer_source

    def res(self, res):
        return tuple(max(8, r // scenes.QUICK_RES_SCALE) for r in res) if self.quick else tuple(res)

    def reference_spp(self, spp):
        return spp // 4 if self.quick else spp


def missed_classes(binary, scene_path):
    """{integrator: what it misses} from `fluence info` ('' when it covers every path class)."""
    text = subprocess.run([binary, "info", str(scenes.ROOT / scene_path)], capture_output=True, text=True).stdout
    misses, in_block = {}, False
    for line in text.splitlines():
        if line.startswith("path classes"):
            in_block = True
        elif in_block and line.startswith("  "):
            m = re.match(r"\s+(\w+)\s+(?:misses (.*)|covers them all)", line)
            if m:
                misses[m.group(1)] = m.group(2) or ""
        elif in_block:
            break
    return misses


def log(text):
    print(text, flush=True)


def two_half_reference(ctx, scene_name, spp, key_parts, render_half):
    """Renders (or finds in the cache) the two halves of SPP in all; RENDER_HALF(seed, out) renders one."""
    key = hashlib.sha1(repr(key_parts).encode()).hexdigest()[:12]
    folder = ctx.cache / scene_name / ("ref-" + key)
    folder.mkdir(parents=True, exist_ok=True)
    halves = [folder / "half1.exr", folder / "half2.exr"]
    for seed, half in zip((1, 2), halves):
        if not half.exists():
            result = render_half(seed, half)
            if result["exit_code"] != 0:
                raise RuntimeError("reference %s failed (exit %d): see %s.log" % (half, result["exit_code"], half))
            log("  reference %s seed %d: %.1f s" % (scene_name, seed, result["render_s"]))
    return metrics.Reference(*halves, spp)


def fluence_reference(ctx, name, path, method_name, spp, res, extra):
    scene_text = (scenes.ROOT / path).read_bytes()
    m = scenes.method(method_name)
    key = (hashlib.sha1(scene_text).hexdigest(), m, spp, res, extra)
    return two_half_reference(ctx, name, spp, key, lambda seed, out: rendering.fluence(
        ctx.binary, path, m, spp // 2, seed, res, out, extra))


SPP_CAP = 1 << 16  # the spp of a time-limited render: never reached


def row(suite, scene, method_name, result, reference, misses):
    """One render's CSV row: the renderer's RESULT (rendering.py) and its error against REFERENCE."""
    r = {"suite": suite, "scene": scene, "method": method_name, "seed": 0, "misses": misses, **result}
    if result["exit_code"] == rendering.SCENE_REFUSED:
        r["status"] = "refused"
    elif result["exit_code"] != 0:
        r["status"] = "failed"
    else:
        r["status"] = "ok"
        r.update(reference.error(result["image"]))
    return r


def log_row(row):
    log("  %-16s %-15s %6d spp  %-7s render %7.2f s  relMSE %s" % (
        row["scene"], row["method"], row["spp"], row["status"], row["render_s"],
        "%.4g" % row["relmse"] if "relmse" in row else "-"))


def _ladder(ctx, suite, scene_name, rungs, runners, rows):
    """RUNNERS maps a method name to (render(rung, out) -> result, reference, misses)."""
    work = ctx.cache / scene_name / "runs"
    work.mkdir(parents=True, exist_ok=True)
    stopped = set()
    for i, rung in enumerate(rungs):
        for name, (render, reference, misses) in runners.items():
            if name in stopped:
                continue
            out = work / ("%s_%s_rung%d.exr" % (suite, name.replace("+", "_"), i))
            result = dict(render(rung, out), image=out)
            r = row(suite, scene_name, name, result, reference, misses)
            del r["image"]
            rows.append(r)
            log_row(r)
            if r["status"] != "ok" or ("budget_s" in r and r["render_s"] > max(rungs)):
                stopped.add(name)


def _time_limited(ctx, scene, m, res):
    def render(budget, out):
        return dict(rendering.fluence(ctx.binary, scene.path, m, SPP_CAP, 0, res, out, scene.extra, budget),
                    budget_s=budget)
    return render


def figures(ctx, selected):
    rows = []
    for scene in scenes.FIGURE_SCENES:
        if selected and scene.name not in selected:
            continue
        log("figures: %s (%s)" % (scene.name, scene.path))
        res, ref_spp = ctx.res(scene.res), ctx.reference_spp(scene.reference_spp)
        reference = fluence_reference(ctx, scene.name, scene.path, scene.reference, ref_spp, res, scene.extra)
        misses = missed_classes(ctx.binary, scene.path)
        runners = {name: (_time_limited(ctx, scene, scenes.method(name), res), reference,
                          misses.get(scenes.method(name).integrator, "")) for name in scene.methods}
        _ladder(ctx, "figures", scene.name, ctx.budgets, runners, rows)
    return rows


STABILITY_RES = (64, 48)
STABILITY_REFERENCE_CAP = 512  # a scene's `# reference:` spp is capped so the suite fits its time budget


def stability(ctx, selected, res=STABILITY_RES):
    rows = []
    found = scenes.stability_scenes()
    if not found:
        log("stability: no scenes in bench/stability/")
    for scene in found:
        if selected and scene.name not in selected:
            continue
        log("stability: %s (%s)" % (scene.name, scene.path))
        r = ctx.res(res)
        try:
            reference = fluence_reference(ctx, scene.name, scene.path, scene.reference,
                                           ctx.reference_spp(min(scene.reference_spp, STABILITY_REFERENCE_CAP)), r, ())
        except RuntimeError as e:
            print("stability: %s skipped: %s" % (scene.name, e), file=sys.stderr)
            continue
        misses = missed_classes(ctx.binary, scene.path)
        runners = {name: ((lambda m: lambda spp, out: rendering.fluence(ctx.binary, scene.path, m, spp, 0, r, out))(
            scenes.method(name)), reference, misses.get(scenes.method(name).integrator, ""))
            for name in scene.integrators}
        _ladder(ctx, "stability", scene.name, ctx.spp_rungs, runners, rows)
    return rows
