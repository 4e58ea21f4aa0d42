"""The `cycles` suite's tables and charts: Fluence's path tracer against Cycles (peer_suite.py).

Per round (one seed for both renderers) on one scene:
- the target error is the lower error both reach, the larger of the two renderers' least relMSE;
- time to equal error: each renderer's render time (wall, and CPU) at the target, interpolated
  log-log between rungs (metrics.time_to_error), as the ratio Fluence / Cycles;
- relMSE per sample: Fluence's relMSE over Cycles' at the top rung, the same sample count for
  both (where both converge at the Monte Carlo rate, the ratio of their variances per sample);
- CPU per sample: Fluence's render CPU time over Cycles' at the top rung.
The CPU time to equal error is about the product of the last two. The summary gives each ratio as
the median over the rounds, with the least and the greatest in brackets.
"""
import statistics

from . import charts, metrics, peer_suite


def _fmt(x, spec="%.3g"):
    return "–" if x is None or x != x else spec % x


def _rounds(rows):
    """{round: {"path": [rows by spp], "cycles": [...]}} over one scene's rendered rows."""
    rounds = {}
    for r in rows:
        if r["method"] in ("path", "cycles") and r["status"] == "ok":
            rounds.setdefault(r["repeat"], {}).setdefault(r["method"], []).append(r)
    for ladders in rounds.values():
        for ladder in ladders.values():
            ladder.sort(key=lambda r: r["spp"])
    return {k: v for k, v in sorted(rounds.items()) if len(v) == 2}


def _round_ratios(ours, theirs):
    target = max(min(r["relmse"] for r in ours), min(r["relmse"] for r in theirs))

    def to_target(ladder, column):
        return metrics.time_to_error([r.get(column, float("nan")) for r in ladder], [r["relmse"] for r in ladder],
                                     target)
    top_ours, top_theirs = ours[-1], theirs[-1]
    same_top = top_ours["spp"] == top_theirs["spp"]
    return {"target": target,
            "relmse": top_ours["relmse"] / top_theirs["relmse"] if same_top else float("nan"),
            "cpu_per_sample": top_ours["cpu_s"] / top_theirs["cpu_s"] if same_top else float("nan"),
            "cpu": to_target(ours, "cpu_s") / to_target(theirs, "cpu_s"),
            "wall": to_target(ours, "render_s") / to_target(theirs, "render_s")}


def _spread(values, spec="%.2f"):
    values = [v for v in values if v == v]
    if not values:
        return "–"
    text = spec % statistics.median(values)
    return text + (" (%s–%s)" % (spec % min(values), spec % max(values)) if len(values) > 1 else "")


def _median(rows, column):
    values = [r[column] for r in rows if column in r and r[column] == r[column]]
    return statistics.median(values) if values else float("nan")


def _scenes(rows):
    return list(dict.fromkeys(r["scene"] for r in rows))


def draw(rows, figure_dir, stem):
    """Per scene, relMSE against render CPU time, each rung's median over the rounds."""
    for scene in _scenes(rows):
        lines = {}
        for name in ("path", "cycles"):
            ladder = [r for r in rows if r["scene"] == scene and r["method"] == name and r["status"] == "ok"]
            for spp in sorted({r["spp"] for r in ladder}):
                at = [r for r in ladder if r["spp"] == spp]
                lines.setdefault("fluence path" if name == "path" else "cycles", []).append(
                    (_median(at, "cpu_s"), _median(at, "relmse")))
        charts.draw(lines, figure_dir / ("%s-%s" % (stem, scene)), title=scene + ": Fluence against Cycles",
                    xlabel="render CPU time (s, user + system)", ylabel="relMSE (reference noise subtracted)")


def markdown(rows, chart_link):
    """The summary table, then per scene its chart and its rungs."""
    out = ["| scene | rounds | top rung | target relMSE | relMSE per sample, Fluence / Cycles | CPU per sample, "
           "Fluence / Cycles | **time to equal error, Fluence / Cycles: CPU** | wall | references apart: relMSE; "
           "image mean, Fluence vs Cycles (R G B, %) |", "|---|---|---|---|---|---|---|---|---|"]
    details = []
    for scene in _scenes(rows):
        scene_rows = [r for r in rows if r["scene"] == scene]
        rounds = _rounds(scene_rows)
        ratios = [_round_ratios(ladders["path"], ladders["cycles"]) for ladders in rounds.values()]
        agreement = next((r for r in scene_rows if r["method"] == peer_suite.AGREEMENT), None)
        apart = "–"
        if agreement:
            apart = "%s; %s" % (_fmt(agreement["relmse"]), " ".join(
                "%+.2f" % (100 * float(b)) for b in agreement.get("channel_bias", "").split()))
        top = max((r["spp"] for ladders in rounds.values() for r in ladders["path"]), default=0)
        out.append("| %s | %d | %d spp | %s | %s | %s | **%s** | %s | %s |" % (
            scene, len(ratios), top, _spread([q["target"] for q in ratios], "%.3g"),
            _spread([q["relmse"] for q in ratios]), _spread([q["cpu_per_sample"] for q in ratios]),
            _spread([q["cpu"] for q in ratios]), _spread([q["wall"] for q in ratios]), apart))
        details += ["", "#### %s" % scene, "", "![%s](%s)" % (scene, chart_link(scene)), "",
                    "Medians over the rounds (render times after each renderer's scene is built; Cycles' CPU time "
                    "with its 1-sample render call's CPU taken off).", "",
                    "| renderer | spp | relMSE | render s (wall) | render s (CPU) | CPU s per spp |",
                    "|---|---|---|---|---|---|"]
        for name in ("path", "cycles"):
            ladder = [r for r in scene_rows if r["method"] == name and r["status"] == "ok"]
            for spp in sorted({r["spp"] for r in ladder}):
                at = [r for r in ladder if r["spp"] == spp]
                cpu = _median(at, "cpu_s")
                details.append("| %s | %d | %s | %s | %s | %s |" % (
                    "Fluence path" if name == "path" else "Cycles", spp, _fmt(_median(at, "relmse")),
                    _fmt(_median(at, "render_s")), _fmt(cpu), _fmt(cpu / spp)))
        failed = [r for r in scene_rows if r["status"] != "ok"]
        if failed:
            details.append("\nFailed renders: " + ", ".join("%s at %d spp (exit %d)" % (
                r["method"], r["spp"], r["exit_code"]) for r in failed))
    return "\n".join(out + details)
