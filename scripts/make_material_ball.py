#!/usr/bin/env python3
"""Writes usd_samples/material_ball/: the material-ball scene and its small procedural textures.

Run from the repository root: python3 scripts/make_material_ball.py
The textures are written as uncompressed TGA files and converted to PNG with oiiotool (Debian
package openimageio-tools), so the script needs nothing but Python and OIIO.
"""
import math
import os
import subprocess

OUT = "usd_samples/material_ball"
N = 256


def write_tga(path, width, height, channels, pixel):
    """An uncompressed TGA of 8-bit channels; pixel(x, y) -> tuple of floats in [0, 1], y down."""
    image_type = 3 if channels == 1 else 2  # grey or true colour
    descriptor = 0x20 | (8 if channels == 4 else 0)  # top-left origin, alpha bits
    header = bytes([0, 0, image_type, 0, 0, 0, 0, 0, 0, 0, 0, 0, width & 255, width >> 8, height & 255, height >> 8,
                    8 * channels, descriptor])
    data = bytearray()
    for y in range(height):
        for x in range(width):
            v = [max(0, min(255, round(255 * c))) for c in pixel(x, y)]
            if channels >= 3:
                v[0], v[2] = v[2], v[0]  # TGA stores BGR(A)
            data.extend(v)
    with open(path, "wb") as f:
        f.write(header + bytes(data))


def texture(name, channels, pixel):
    tga = os.path.join(OUT, "textures", name + ".tga")
    write_tga(tga, N, N, channels, pixel)
    subprocess.run(["oiiotool", tga, "-o", os.path.join(OUT, "textures", name + ".png")], check=True)
    os.remove(tga)


def checker(x, y):  # sRGB-encoded colour: 8 x 8 squares, warm and cool
    warm, cool = (0.85, 0.55, 0.25), (0.25, 0.45, 0.7)
    return warm if (x * 8 // N + y * 8 // N) % 2 == 0 else cool


def roughness(x, y):  # raw data: stripes from glossy (0.1) to rough (0.7)
    return (0.1 + 0.6 * (0.5 + 0.5 * math.sin(2 * math.pi * 6 * x / N)),)


def bumps(x, y):  # tangent-space normals of a grid of round bumps, stored (n + 1) / 2
    cell = N / 8
    u, v = (x % cell) / cell - 0.5, 0.5 - (y % cell) / cell  # v grows up the texture
    r2 = u * u + v * v
    if r2 > 0.16:
        n = (0.0, 0.0, 1.0)
    else:  # the slope of a spherical cap, tilting away from the bump's centre
        nx, ny = u * 2.0, v * 2.0
        n = (nx, ny, 1.0)
    length = math.sqrt(sum(c * c for c in n))
    return tuple(0.5 * c / length + 0.5 for c in n)


def leaf_mask(x, y):  # colour white, alpha 1 inside a grid of discs (a cut-out), 0 outside
    cell = N / 4
    u, v = (x % cell) / cell - 0.5, (y % cell) / cell - 0.5
    return (1.0, 1.0, 1.0, 1.0 if u * u + v * v < 0.16 else 0.0)


def sphere_mesh(name, radius, segments=48, rings=24):
    """A UsdGeomMesh UV sphere with faceVarying st (s around, t from the south pole up)."""
    points, counts, indices, st = [], [], [], []
    for r in range(rings + 1):
        theta = math.pi * r / rings
        for s in range(segments + 1):
            phi = 2 * math.pi * s / segments
            points.append((radius * math.sin(theta) * math.cos(phi), radius * math.cos(theta),
                           -radius * math.sin(theta) * math.sin(phi)))
    at = lambda r, s: r * (segments + 1) + s
    for r in range(rings):
        for s in range(segments):
            quad = [at(r, s), at(r + 1, s), at(r + 1, s + 1), at(r, s + 1)]
            counts.append(4)
            indices.extend(quad)
            for q in quad:
                rr, ss = divmod(q, segments + 1)
                st.append((ss / segments, 1.0 - rr / rings))
    normals = [(p[0] / radius, p[1] / radius, p[2] / radius) for p in points]
    fmt = lambda v: ", ".join("(" + ", ".join(f"{c:.6g}" for c in t) + ")" for t in v)
    return f'''def Mesh "{name}"
{{
    uniform token subdivisionScheme = "none"
    int[] faceVertexCounts = [{", ".join(map(str, counts))}]
    int[] faceVertexIndices = [{", ".join(map(str, indices))}]
    point3f[] points = [{fmt(points)}]
    normal3f[] normals = [{fmt(normals)}] (interpolation = "vertex")
    texCoord2f[] primvars:st = [{fmt(st)}] (interpolation = "faceVarying")
}}
'''


def main():
    os.makedirs(os.path.join(OUT, "textures"), exist_ok=True)
    texture("checker", 3, checker)
    texture("roughness", 1, roughness)
    texture("bumps_normal", 3, bumps)
    texture("disc_mask", 4, leaf_mask)
    with open(os.path.join(OUT, "ball.usda"), "w") as f:
        f.write("#usda 1.0\n(\n    defaultPrim = \"Ball\"\n    upAxis = \"Y\"\n    metersPerUnit = 1\n)\n\n")
        f.write(sphere_mesh("Ball", 0.5))


if __name__ == "__main__":
    main()
