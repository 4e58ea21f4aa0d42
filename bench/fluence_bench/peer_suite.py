"""The `cycles` suite: Fluence's path tracer against Blender Cycles on the Cycles peer's scenes.

For each figure scene the peer also has (scenes.FIGURE_SCENES' `peer`): both references, two
cached halves each at the scene's reference samples (Fluence's is the figures suite's own), and
how far apart they are (metrics.Reference.agreement: each renderer is measured against its own
reference, so a difference is not error, but a large one means the two scenes differ); then
ROUNDS rounds of a ladder of sample counts, every round with its own seed for both renderers
(FIRST_SEED, FIRST_SEED + 1, ...: never a reference half's 1 or 2). At each rung Fluence and Cycles
render in turn, which goes first alternating from rung to rung, and Cycles renders the scene at 1
sample too (its CPU baseline, below).

Times. Wall: Fluence's `render` time, Cycles' render_time from the EXR header, each after its
scene is built. CPU (user + system, every thread), which the other processes on a shared machine
inflate far less: Fluence's is the render's own (`render ... (C s CPU)`); Cycles' is the CPU time
of Blender's render call (bench/cycles_render_cpu.py), which holds the scene sync and the EXR
write too, so the scene's median over its 1-sample renders, b, is taken off: a render of N samples
costs (call - b) * N / (N - 1) (b is the sync, the write and one sample). Each render is one CSV
row (suites.ROW_FIELDS; the baselines' method is BASELINE, and the references' agreement is one
row of method AGREEMENT); reports.cycles_markdown() makes the tables.
"""
import statistics

from . import rendering, scenes, suites

FIRST_SEED = 10
BASELINE = "cycles@1spp"
AGREEMENT = "references"


def _cycles_render_cpu(rows):
    """Fills `cpu_s` of the Cycles rows of ROWS (one scene's) from their render calls' CPU time."""
    baseline = [r["render_call_cpu_s"] for r in rows if r["method"] == BASELINE and r["status"] == "ok"]
    if not baseline:
        return
    b = statistics.median(baseline)
    for r in rows:
        if r["method"] == "cycles" and r["status"] == "ok" and r["spp"] > 1:
            r["cpu_s"] = (r["render_call_cpu_s"] - b) * r["spp"] / (r["spp"] - 1)


def _agreement_row(scene_name, fluence_ref, cycles_ref):
    a = fluence_ref.agreement(cycles_ref)
    suites.log("  references: Fluence's against Cycles', relMSE %.3g (noise taken out); image means differ by "
               "%s (R, G, B)" % (a["relmse"], ", ".join("%+.2f%% ± %.2f" % (100 * b, 100 * s)
                                                         for b, s in zip(a["bias"], a["bias_se"]))))
    return {"suite": "cycles", "scene": scene_name, "method": AGREEMENT, "renderer": "both", "status": "ok",
            "spp": fluence_ref.spp, "relmse": a["relmse"], "bias": sum(a["bias"]) / 3,
            "bias_se": (sum(s * s for s in a["bias_se"]) ** 0.5) / 3,
            "channel_bias": " ".join("%+.5f" % b for b in a["bias"])}


def cycles(ctx, selected, spp_rungs, rounds):
    """The suite's rows over the peer scenes (SELECTED: their names, or empty for all)."""
    rows = []
    peer = rendering.peer_dir(ctx.cache, ctx.peer_source)
    for scene in scenes.FIGURE_SCENES:
        if not scene.peer or (selected and scene.name not in selected):
            continue
        suites.log("cycles: %s (%s; the peer's scene %s)" % (scene.name, scene.path, scene.peer))
        res, ref_spp = ctx.res(scene.res), ctx.reference_spp(scene.reference_spp)
        path = scenes.method("path")
        ours = suites.fluence_reference(ctx, scene.name, scene.path, path.name, ref_spp, res, scene.extra)
        theirs = suites.two_half_reference(
            ctx, scene.name, ref_spp, ("cycles", scene.peer, ref_spp, res, scene.peer_args),
            lambda seed, out: rendering.cycles(peer, scene.peer, ref_spp // 2, seed, res, out, scene.peer_args))
        scene_rows = [_agreement_row(scene.name, ours, theirs)]
        renderers = {
            "path": (lambda spp, seed, out: rendering.fluence(ctx.binary, scene.path, path, spp, seed, res, out,
                                                              scene.extra), ours),
            "cycles": (lambda spp, seed, out: rendering.cycles(peer, scene.peer, spp, seed, res, out,
                                                               scene.peer_args), theirs),
        }
        work = ctx.cache / scene.name / "runs"
        work.mkdir(parents=True, exist_ok=True)
        for round_index in range(rounds):
            seed = FIRST_SEED + round_index
            for i, spp in enumerate(spp_rungs):
                turns = [("path", spp), ("cycles", spp)]
                if (i + round_index) % 2:
                    turns.reverse()
                for name, n in [(BASELINE, 1)] + turns:
                    render, reference = renderers["cycles" if name == BASELINE else name]
                    out = work / ("cycles_%s_%dspp_seed%d.exr" % (name.replace("@", "_"), n, seed))
                    r = suites.row("cycles", scene.name, name, dict(render(n, seed, out), image=out), reference, "")
                    del r["image"]
                    r.update(seed=seed, repeat=round_index)
                    scene_rows.append(r)
                    suites.log_row(r)
        _cycles_render_cpu(scene_rows)
        rows += scene_rows
    return rows
