"""Fluence's speed-against-accuracy benchmark (`make figures`, bench/run.py).

One job per module: scenes (what is rendered, with which methods), rendering (running fluence and
Cycles and reading their timings), metrics (error against a reference whose own noise is taken
out), charts (log-log error against time with fitted slopes), suites (the figures and stability
runs) and reports (docs/RESULTS.md, docs/STABILITY.md).
"""
