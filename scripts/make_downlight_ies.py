#!/usr/bin/env python3
"""Writes usd_samples/lights/textures/downlight.ies: an IES LM-63-2002 type C profile of a
plausible recessed downlight, made up here (no manufacturer's data, free of any licence).

The distribution: a beam of about 40 degrees (cos^8 of the vertical angle), a wider wash
(cos^2), slightly wider along horizontal angle 0 than along 90 (an elliptical reflector, so the
table is quadrant-symmetric: horizontal angles 0-90), nothing above the ceiling (vertical angles
0-90, a hemisphere). Candela for 1000 lumens.

Run from the repository root: python3 scripts/make_downlight_ies.py
"""
import math

VERTICAL = list(range(0, 91, 5))
HORIZONTAL = list(range(0, 91, 15))


def candela(v, h):
    c = math.cos(math.radians(v))
    spread = 1.0 + 0.25 * math.cos(math.radians(h)) ** 2  # wider along horizontal angle 0
    beam = 900.0 * max(c, 0.0) ** (8.0 / spread)
    wash = 120.0 * max(c, 0.0) ** 2
    return beam + wash


def numbers(values, per_line=10):
    return "\n".join(" ".join(values[i:i + per_line]) for i in range(0, len(values), per_line))


lines = [
    "IESNA:LM-63-2002",
    "[TEST] made by scripts/make_downlight_ies.py",
    "[MANUFAC] Fluence sample (fictitious)",
    "[LUMCAT] DL-40",
    "[LUMINAIRE] recessed downlight, 40 degree beam",
    "TILT=NONE",
    # lamps, lumens per lamp, multiplier, vertical count, horizontal count, type C, units metres,
    # opening width, length, height
    f"1 1000 1.0 {len(VERTICAL)} {len(HORIZONTAL)} 1 2 0.1 0.1 0.0",
    "1.0 1.0 12",
    numbers([str(v) for v in VERTICAL]),
    numbers([str(h) for h in HORIZONTAL]),
]
for h in HORIZONTAL:
    lines.append(numbers([f"{candela(v, h):.1f}" for v in VERTICAL]))
with open("usd_samples/lights/textures/downlight.ies", "w") as f:
    f.write("\n".join(lines) + "\n")
