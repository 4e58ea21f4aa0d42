#!/usr/bin/python3
"""Error-vs-time charts for bench/results: one log-log line per method, PNG and SVG, slopes printed.

  bench/chart.py CSV --x COLUMN --y COLUMN --group COLUMN --out BASE [--where COLUMN=VALUE]
                 [--title T] [--xlabel L] [--ylabel L]

Reads CSV (a header row), draws COLUMN y against COLUMN x for each value of the group column, and
writes BASE.png and BASE.svg; --where keeps only the rows whose COLUMN is VALUE. For each group it prints the least-squares slope of log y against
log x (about -0.5 for an unbiased Monte Carlo estimator whose error is all variance; flattening
towards 0 where a method's bias dominates). Needs Debian's python3-matplotlib (run with
/usr/bin/python3).
"""
import argparse
import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def slope(xs, ys):
    lx = [math.log(x) for x in xs]
    ly = [math.log(y) for y in ys]
    mx, my = sum(lx) / len(lx), sum(ly) / len(ly)
    sxx = sum((a - mx) ** 2 for a in lx)
    return sum((a - mx) * (b - my) for a, b in zip(lx, ly)) / sxx if sxx > 0 else float("nan")


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("csv")
    p.add_argument("--x", required=True)
    p.add_argument("--y", required=True)
    p.add_argument("--group", required=True)
    p.add_argument("--out", required=True)
    p.add_argument("--where", default=None)
    p.add_argument("--title", default="")
    p.add_argument("--xlabel", default=None)
    p.add_argument("--ylabel", default=None)
    a = p.parse_args()

    column, _, value = (a.where or "").partition("=")
    groups = {}
    with open(a.csv) as f:
        for row in csv.DictReader(f):
            if a.where and row.get(column) != value:
                continue
            x, y = float(row[a.x]), float(row[a.y])
            if x > 0 and y > 0:
                groups.setdefault(row[a.group], []).append((x, y))
    if not groups:
        sys.exit("no positive points in " + a.csv)

    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    for name, points in groups.items():
        points.sort()
        xs, ys = [q[0] for q in points], [q[1] for q in points]
        s = slope(xs, ys) if len(points) > 1 else float("nan")
        print("%-24s slope %+.3f over %d points" % (name, s, len(points)))
        ax.loglog(xs, ys, marker="o", label="%s (slope %+.2f)" % (name, s))
    ax.set_xlabel(a.xlabel or a.x)
    ax.set_ylabel(a.ylabel or a.y)
    ax.set_title(a.title)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
    fig.tight_layout()
    for ext in ("png", "svg"):
        fig.savefig("%s.%s" % (a.out, ext), dpi=110)


if __name__ == "__main__":
    main()
