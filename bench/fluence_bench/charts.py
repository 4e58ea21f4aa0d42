"""Log-log error-against-time charts, one line per method, with each line's fitted slope.

draw() writes BASE.png and BASE.svg and returns {line name: slope}. The slope is the least-squares
slope of log error against log time: -1 for relMSE (-0.5 for RMSE) is the Monte Carlo rate of an
unbiased method whose error is all variance; a line flattening towards 0 has hit a bias (missing
light, blur) or is stuck. chart_csv() draws any CSV the same way (`bench/run.py chart`), which is
how the older figures in bench/results/ are redrawn.
"""
import csv

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from .metrics import fitted_slope  # noqa: E402


def draw(lines, out_base, title="", xlabel="render time (s)", ylabel="relMSE"):
    """LINES maps a name to [(x, y), ...], drawn in that order (the ladder's, since a rung's time can
    come out below the one before on a loaded machine); points with x or y <= 0 are left out."""
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    slopes = {}
    for name, points in lines.items():
        points = [(x, y) for x, y in points if x > 0 and y > 0]
        if not points:
            continue
        xs, ys = [p[0] for p in points], [p[1] for p in points]
        slopes[name] = fitted_slope(xs, ys)
        ax.loglog(xs, ys, marker="o", linestyle="--" if name.startswith("cycles") else "-",
                  label="%s (slope %+.2f)" % (name, slopes[name]))
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title(title)
    ax.grid(True, which="both", alpha=0.3)
    if slopes:
        ax.legend(fontsize="small")
    fig.tight_layout()
    for ext in ("png", "svg"):
        fig.savefig("%s.%s" % (out_base, ext), dpi=110)
    plt.close(fig)
    return slopes


def chart_csv(path, x, y, group, out_base, where=None, title="", xlabel=None, ylabel=None):
    """Draws column Y against column X of the CSV at PATH, one line per value of column GROUP;
    WHERE ("COLUMN=VALUE") keeps only the matching rows. Prints each line's slope."""
    column, _, value = (where or "").partition("=")
    lines = {}
    with open(path) as f:
        for row in csv.DictReader(f):
            if not where or row.get(column) == value:
                lines.setdefault(row[group], []).append((float(row[x]), float(row[y])))
    slopes = draw(lines, out_base, title, xlabel or x, ylabel or y)
    if not slopes:
        raise SystemExit("no positive points in " + path)
    for name, s in slopes.items():
        print("%-24s slope %+.3f over %d points" % (name, s, len(lines[name])))
