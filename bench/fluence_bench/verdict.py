"""The stability verdict of one method on one scene, computed from its ladder of rows.

RULE is the rule, in the order it is applied; docs/STABILITY.md prints it.
"""
from .metrics import fitted_slope

CONVERGING_SLOPE = -0.5  # relMSE against spp; the Monte Carlo rate is -1, a stuck or biased method's ~0

RULE = (
    "1. **refuses**: fluence exited with code 3 (the integrator refused the scene).",
    "2. **NaN**: any rung reported NaN or infinite samples (the render log's warning) or wrote a non-finite pixel.",
    "3. **failed**: any other non-zero exit code.",
    "4. **converges**: at the highest rung the bias is within %d standard errors of zero, and the fitted slope "
    "of relMSE against spp is at most %.1f." % (3, CONVERGING_SLOPE),
    "5. **misses**: otherwise, if `fluence info` lists path classes of the scene this integrator misses.",
    "6. **biased**: otherwise.",
)


def judge(ladder):
    """LADDER: one method's rows on one scene, in rung order. Returns (verdict, slope, top row)."""
    top = ladder[-1]
    ok = [r for r in ladder if r["status"] == "ok"]
    slope = fitted_slope([r["spp"] for r in ok], [r["relmse"] for r in ok])
    if any(r["status"] == "refused" for r in ladder):
        return "refuses", slope, top
    if any(r["nonfinite_samples"] or r.get("nonfinite_pixels") for r in ladder):
        return "NaN", slope, top
    if any(r["status"] == "failed" for r in ladder):
        return "failed", slope, top
    if not top["bias_significant"] and slope <= CONVERGING_SLOPE:
        return "converges", slope, top
    return ("misses" if top["misses"] else "biased"), slope, top
