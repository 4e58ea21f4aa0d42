"""The two suites: `figures` (methods and Cycles against time, per scene) and `stability`.

Both render each scene's reference as two cached halves (bench/cache/, seeds 1 and 2; metrics.py
says why), then climb a ladder, every method taking its turn at each rung so that the machine's
load falls on all alike, and measure each image against the reference. The figures ladder is
one of time budgets (fluence --time-limit; so every method costs the same and slow methods take
fewer samples), the stability ladder one of sample counts (its slope is the variance trend per
sample). Cycles has no time limit: its first rung takes CYCLES_FIRST_SPP samples and each later
one the samples its last measured rate fits into the budget. A method that exits with code 3
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

ROW_FIELDS = ("suite", "scene", "method", "renderer", "res", "budget_s", "spp", "seed", "status", "exit_code", "wall_s", "render_s",
              "msamples_per_s", "mrays_per_s", "peak_mib", "nonfinite_samples", "nonfinite_pixels", "relmse",
              "relmse_uncorrected", "mare", "ref_spp", "ref_relmse", "ref_mare", "bias", "bias_se", "bias_significant", "misses",
              "relmse_vs_peer")


class Context:
    """What every render of a run shares: the binary, the cache folder, the two ladders, quick mode."""

    def __init__(self, binary, cache, budgets, spp_rungs, quick, cycles):
        self.binary, self.cache, self.quick, self.cycles = binary, cache, quick, cycles
        self.budgets, self.spp_rungs = budgets, spp_rungs

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


def _log(text):
    print(text, flush=True)


def _reference(ctx, scene_name, spp, key_parts, render_half):
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
            _log("  reference %s seed %d: %.1f s" % (scene_name, seed, result["render_s"]))
    return metrics.Reference(*halves, spp)


def _fluence_reference(ctx, name, path, method_name, spp, res, extra):
    scene_text = (scenes.ROOT / path).read_bytes()
    m = scenes.method(method_name)
    key = (hashlib.sha1(scene_text).hexdigest(), m, spp, res, extra)
    return _reference(ctx, name, spp, key, lambda seed, out: rendering.fluence(
        ctx.binary, path, m, spp // 2, seed, res, out, extra))


SPP_CAP = 1 << 16  # the spp of a time-limited render: never reached
CYCLES_FIRST_SPP = 4


def _row(suite, scene, method_name, result, reference, misses):
    row = {"suite": suite, "scene": scene, "method": method_name, "seed": 0, "misses": misses, **result}
    if result["exit_code"] == rendering.SCENE_REFUSED:
        row["status"] = "refused"
    elif result["exit_code"] != 0:
        row["status"] = "failed"
    else:
        row["status"] = "ok"
        row.update(reference.error(result["image"]))
    return row


def _ladder(ctx, suite, scene_name, rungs, runners, rows, peer_reference=None):
    """RUNNERS maps a method name to (render(rung, out) -> result, reference, misses). With
    PEER_REFERENCE (Cycles' own reference of the scene), every Fluence image's relMSE against it is
    kept too (`relmse_vs_peer`), so that the two renderers can be timed to the same error against
    the same reference."""
    work = ctx.cache / scene_name / "runs"
    work.mkdir(parents=True, exist_ok=True)
    stopped = set()
    for i, rung in enumerate(rungs):
        for name, (render, reference, misses) in runners.items():
            if name in stopped:
                continue
            out = work / ("%s_%s_rung%d.exr" % (suite, name.replace("+", "_"), i))
            result = dict(render(rung, out), image=out)
            row = _row(suite, scene_name, name, result, reference, misses)
            if peer_reference is not None and name != "cycles" and row["status"] == "ok":
                row["relmse_vs_peer"] = peer_reference.error(out)["relmse"]
            del row["image"]
            rows.append(row)
            _log("  %-16s %-15s %6d spp  %-7s render %7.2f s  relMSE %s" % (
                scene_name, name, row["spp"], row["status"], row["render_s"], "%.4g" % row["relmse"] if "relmse" in row else "-"))
            if row["status"] != "ok" or ("budget_s" in row and row["render_s"] > max(rungs)):
                stopped.add(name)


def _time_limited(ctx, scene, m, res):
    def render(budget, out):
        return dict(rendering.fluence(ctx.binary, scene.path, m, SPP_CAP, 0, res, out, scene.extra, budget),
                    budget_s=budget)
    return render


def _cycles_in_budget(peer, peer_scene, res, peer_args):
    seconds_per_spp = []

    def render(budget, out):
        spp = max(1, round(budget / seconds_per_spp[-1])) if seconds_per_spp else CYCLES_FIRST_SPP
        result = rendering.cycles(peer, peer_scene, spp, 0, res, out, peer_args)
        if result["render_s"] > 0:
            seconds_per_spp.append(result["render_s"] / spp)
        return dict(result, budget_s=budget)
    return render


def figures(ctx, selected):
    rows = []
    for scene in scenes.FIGURE_SCENES:
        if selected and scene.name not in selected:
            continue
        _log("figures: %s (%s)" % (scene.name, scene.path))
        res, ref_spp = ctx.res(scene.res), ctx.reference_spp(scene.reference_spp)
        reference = _fluence_reference(ctx, scene.name, scene.path, scene.reference, ref_spp, res, scene.extra)
        misses = missed_classes(ctx.binary, scene.path)
        runners = {name: (_time_limited(ctx, scene, scenes.method(name), res), reference,
                          misses.get(scenes.method(name).integrator, "")) for name in scene.methods}
        peer_ref = None
        if scene.peer and ctx.cycles:
            peer = rendering.peer_dir(ctx.cache)
            peer_ref = _reference(ctx, scene.name, ref_spp, ("cycles", scene.peer, ref_spp, res, scene.peer_args),
                                  lambda seed, out: rendering.cycles(peer, scene.peer, ref_spp // 2, seed, res, out,
                                                                     scene.peer_args))
            runners["cycles"] = (_cycles_in_budget(peer, scene.peer, res, scene.peer_args), peer_ref, "")
        _ladder(ctx, "figures", scene.name, ctx.budgets, runners, rows, peer_ref)
    return rows


STABILITY_RES = (64, 48)
STABILITY_REFERENCE_CAP = 512  # a scene's `# reference:` spp is capped so the suite fits its time budget


def stability(ctx, selected, res=STABILITY_RES):
    rows = []
    found = scenes.stability_scenes()
    if not found:
        _log("stability: no scenes in bench/stability/")
    for scene in found:
        if selected and scene.name not in selected:
            continue
        _log("stability: %s (%s)" % (scene.name, scene.path))
        r = ctx.res(res)
        try:
            reference = _fluence_reference(ctx, scene.name, scene.path, scene.reference,
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
