"""Writes what a run measured: the CSVs, the charts, and the generated sections of the documents.

A document's generated section lies between `<!-- BEGIN GENERATED: NAME -->` and
`<!-- END GENERATED: NAME -->`; only that is rewritten, so the hand-written text around it stays.
"""
import csv
import math
import re

from . import charts, metrics, scenes, verdict
from .suites import ROW_FIELDS


def write_csv(rows, path):
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=ROW_FIELDS, extrasaction="ignore")
        w.writeheader()
        for row in rows:
            w.writerow({k: ("%.6g" % v if isinstance(v, float) else v) for k, v in row.items()})


TEXT_FIELDS = {"suite", "scene", "method", "renderer", "res", "status", "misses", "channel_bias"}
INT_FIELDS = {"spp", "seed", "repeat", "exit_code", "nonfinite_samples", "nonfinite_pixels", "ref_spp"}


def read_csv(path):
    """The rows write_csv wrote, with their types back; empty cells are left out, as in a fresh run."""
    def typed(key, value):
        if key in TEXT_FIELDS:
            return value
        if key == "bias_significant":
            return value == "True"
        return int(value) if key in INT_FIELDS else float(value)
    with open(path) as f:
        return [{k: typed(k, v) for k, v in row.items() if v != "" or k == "misses"} for row in csv.DictReader(f)]


def replace_generated(doc, name, markdown):
    begin, end = "<!-- BEGIN GENERATED: %s -->" % name, "<!-- END GENERATED: %s -->" % name
    text = doc.read_text() if doc.exists() else ""
    block = "%s\n%s\n%s" % (begin, markdown.strip(), end)
    if begin in text:
        text = re.sub(re.escape(begin) + ".*?" + re.escape(end), lambda _: block, text, flags=re.S)
    else:
        text = text.rstrip() + "\n\n" + block + "\n"
    doc.write_text(text)


def _fmt(x, spec="%.3g"):
    return "–" if x is None or (isinstance(x, float) and math.isnan(x)) else spec % x


def _cell(text):
    return (text or "none").replace("|", "\\|")


def _by_method(rows):
    """Each method's ladder, a rung whose sample count repeats an earlier rung's left out: a method
    that reaches the same spp at two budgets (its rate too low for the larger one to add a sample,
    or a render the time limit cut at the same place) rendered the same image twice, and counting
    it twice bends the fitted slope (a flat step of zero error change)."""
    lines = {}
    for r in rows:
        ladder = lines.setdefault(r["method"], [])
        if r["status"] == "ok" and any(q["status"] == "ok" and q["spp"] == r["spp"] for q in ladder):
            continue
        ladder.append(r)
    return lines


def draw_figures(rows, figure_dir, stem):
    """One chart per scene (relMSE against render time); returns {scene: {method: slope}}."""
    slopes = {}
    for scene in dict.fromkeys(r["scene"] for r in rows):
        lines = {m: [(r["render_s"], r["relmse"]) for r in ladder if r["status"] == "ok"]
                 for m, ladder in _by_method([r for r in rows if r["scene"] == scene]).items()}
        slopes[scene] = charts.draw(lines, figure_dir / ("%s-%s" % (stem, scene)), title=scene,
                                    ylabel="relMSE (reference noise subtracted)")
    return slopes


def figures_markdown(rows, slopes, chart_link):
    """Per scene: its chart and a table per method at the top rung."""
    out = []
    for scene in scenes.FIGURE_SCENES:
        scene_rows = [r for r in rows if r["scene"] == scene.name]
        if not scene_rows:
            continue
        ladders = _by_method(scene_rows)
        target_method = scene.reference if scene.reference in ladders else scene.methods[0]
        first = [r for r in ladders[target_method] if r["status"] == "ok"]
        target = first[-1]["relmse"] if first else float("nan")
        reference_spp = next((r["ref_spp"] for r in ladders[scene.methods[0]] if "ref_spp" in r), 0)
        out += ["### %s" % scene.name, "", "`%s` at %s, %s. Reference: `%s`, %d spp in two halves." % (
                    scene.path, scene_rows[0].get("res", "%dx%d" % scene.res), scene.note, scene.reference, reference_spp), "",
                "![%s](%s)" % (scene.name, chart_link(scene.name)), "",
                "Target error for the time column: `%s`'s relMSE at its top rung, %s." % (target_method, _fmt(target)), "",
                "| method | slope (relMSE vs time) | top rung | render s | relMSE | MARE | bias ± s.e. | Msamples/s | Mrays/s "
                "| peak MiB | s to target | misses (fluence info) |",
                "|---|---|---|---|---|---|---|---|---|---|---|---|"]
        for name, ladder in ladders.items():
            ok = [r for r in ladder if r["status"] == "ok"]
            if not ok:
                out.append("| %s | %s at %d spp | | | | | | | | | | %s |" % (name, ladder[-1]["status"], ladder[-1]["spp"],
                                                                          _cell(ladder[-1]["misses"])))
                continue
            top = ok[-1]
            # A method whose image mean is significantly off the reference cannot converge to the
            # target however long it runs: it gets no time ("biased"), however low its error dips.
            biased = bool(top.get("bias_significant"))
            t = "biased" if biased else _fmt(
                metrics.time_to_error([r["render_s"] for r in ok], [r["relmse"] for r in ok], target))
            out.append("| %s | %s | %d spp | %s | %s | %s | %s ± %s | %s | %s | %.0f | %s | %s |" % (
                name, _fmt(slopes.get(scene.name, {}).get(name), "%+.2f"), top["spp"], _fmt(top["render_s"]),
                _fmt(top["relmse"]), _fmt(top["mare"]), _fmt(top["bias"], "%+.2g"), _fmt(top["bias_se"], "%.1g"),
                _fmt(top["msamples_per_s"]), _fmt(top["mrays_per_s"]), top["peak_mib"], t, _cell(top["misses"])))
        top_ref = ladders[scene.methods[0]][-1]
        out += ["", "Reference's own noise (subtracted above): relMSE %s, MARE %s." % (
            _fmt(top_ref.get("ref_relmse")), _fmt(top_ref.get("ref_mare"))), ""]
    return "\n".join(out)


def stability_markdown(rows, stability_scenes):
    expect = {s.name: s for s in stability_scenes}
    out = ["The verdict, computed by `bench/fluence_bench/verdict.py` in this order:", "", *verdict.RULE, "", "| scene | integrator | NaN/Inf samples | bias at top rung ± s.e. | exceeds noise | relMSE per rung "
           "| slope (relMSE vs spp) | verdict | expected | agrees |", "|---|---|---|---|---|---|---|---|---|---|"]
    for scene in dict.fromkeys(r["scene"] for r in rows):
        for name, ladder in _by_method([r for r in rows if r["scene"] == scene]).items():
            result, slope, top = verdict.judge(ladder)
            expected = expect[scene].expect.get(name, "–") if scene in expect else "–"
            nonfinite = sum(r["nonfinite_samples"] for r in ladder)
            rungs = ", ".join("%d: %s" % (r["spp"], _fmt(r.get("relmse"))) for r in ladder)
            out.append("| %s | %s | %d | %s | %s | %s | %s | **%s** | %s | %s |" % (
                scene, name, nonfinite,
                "%s ± %s" % (_fmt(top.get("bias"), "%+.2g"), _fmt(top.get("bias_se"), "%.1g")) if "bias" in top else "–",
                ("yes" if top["bias_significant"] else "no") if "bias" in top else "–", rungs, _fmt(slope, "%+.2f"),
                result, expected, "–" if expected == "–" else ("yes" if expected == result else "**no**")))
    out += ["", "Why each scene is in the suite:", ""]
    out += ["- `%s` (%s): %s" % (s.name, s.path, s.why or s.summary) for s in stability_scenes
            if any(r["scene"] == s.name for r in rows)]
    return "\n".join(out)
