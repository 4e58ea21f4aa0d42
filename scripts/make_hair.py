#!/usr/bin/env python3
"""Writes usd_samples/hair/hair.usda: a head of groomed hair, BasisCurves grown procedurally.

Run from the repository root: python3 scripts/make_hair.py
A sphere "scalp" carries 3,000 cubic B-spline strands (pinned, 6 vertices each) rooted on its
upper half, combed back and down by gravity, tapering from root to tip; a few hundred are
flyaways. Render settings ask for 640 x 360. The strands bind a UsdPreviewSurface whose diffuseColor is the hair's colour (Fluence
turns it into the hair BSDF's absorption), read by a UsdPrimvarReader_float3 from the vertex
primvar hairColor: dark at the root, sun-bleached towards the tip, each strand a little lighter or
darker than the next; its roughness is the fibre's. Deterministic: the
same file every run (a fixed-seed generator).
"""
import math
import os
import random

OUT = "usd_samples/hair"
STRANDS = 3000
VERTICES = 6
RADIUS = 1.0       # the scalp
LENGTH = 1.6       # a strand, before gravity bends it
ROOT_WIDTH = 0.012
TIP_WIDTH = 0.003
ROOT_COLOUR = (0.16, 0.07, 0.03)  # hairColor at the root and at the tip, before each strand's shade
TIP_COLOUR = (0.70, 0.45, 0.20)


def strand(rng):
    """The vertices and widths of one strand rooted at a random point of the upper scalp."""
    while True:  # uniform on the sphere, kept above the ears and off the face (-y)
        z = rng.uniform(-0.1, 1.0)
        phi = rng.uniform(0.0, 2.0 * math.pi)
        r = math.sqrt(1.0 - z * z)
        x, y = r * math.cos(phi), r * math.sin(phi)
        if not (y < -0.55 and z < 0.55):
            break
    root = (x * RADIUS, y * RADIUS, z * RADIUS)
    normal = (x, y, z)
    flyaway = rng.random() < 0.08
    length = LENGTH * rng.uniform(0.8, 1.1) * (1.2 if flyaway else 1.0)
    points, widths = [], []
    p = list(root)
    # Leaves the scalp at a shallow angle, combed back (+y) and down.
    d = [normal[0] * 0.35, normal[1] * 0.35 + 0.6, normal[2] * 0.35 - 0.2]
    step = length / (VERTICES - 1)
    for i in range(VERTICES):
        points.append(tuple(p))
        t = i / (VERTICES - 1)
        widths.append(ROOT_WIDTH + (TIP_WIDTH - ROOT_WIDTH) * t)
        # Combed back (+y) and pulled down by gravity (-z); pushed out so it clears the scalp.
        gravity = 0.45 if not flyaway else 0.15
        d = [d[0] + rng.gauss(0, 0.06), d[1] + 0.15 + rng.gauss(0, 0.06), d[2] - gravity]
        n = math.sqrt(sum(c * c for c in d))
        d = [c / n for c in d]
        p = [p[k] + d[k] * step for k in range(3)]
        dist = math.sqrt(sum(c * c for c in p))
        if dist < RADIUS * 1.02:
            p = [c * RADIUS * 1.02 / dist for c in p]
    return points, widths


def colours(rng, vertices):
    """The hairColor of a strand's vertices: root to tip, times the strand's own shade."""
    shade = rng.uniform(0.75, 1.2)
    out = []
    for i in range(vertices):
        t = (i / (vertices - 1)) ** 1.5
        out.append(tuple(min(1.0, shade * (r + (tip - r) * t)) for r, tip in zip(ROOT_COLOUR, TIP_COLOUR)))
    return out


def fmt(v):
    return "(" + ", ".join("%.5f" % c for c in v) + ")"


def main():
    rng = random.Random(23)
    shades = random.Random(2323)  # its own stream: the strands' shapes stay those of its first version
    counts, points, widths, hair_colours = [], [], [], []
    for _ in range(STRANDS):
        p, w = strand(rng)
        counts.append(len(p))
        points.extend(p)
        widths.extend(w)
        hair_colours.extend(colours(shades, len(p)))
    os.makedirs(OUT, exist_ok=True)
    with open(os.path.join(OUT, "hair.usda"), "w") as f:
        f.write("""#usda 1.0
(
    doc = "Groomed hair: 3,000 BasisCurves strands on a sphere, written by scripts/make_hair.py"
    upAxis = "Z"
    metersPerUnit = 0.1
    renderSettingsPrimPath = "/RenderSettings"
)

def RenderSettings "RenderSettings"
{
    uniform int2 resolution = (640, 360)
}

def Xform "World"
{
    def Sphere "Scalp" (
        prepend apiSchemas = ["MaterialBindingAPI"]
    )
    {
        double radius = %(radius)g
        rel material:binding = </World/Looks/Skin>
    }

    def BasisCurves "Hair" (
        prepend apiSchemas = ["MaterialBindingAPI"]
    )
    {
        uniform token type = "cubic"
        uniform token basis = "bspline"
        uniform token wrap = "pinned"
        token visibility = "inherited"
        int[] curveVertexCounts = [%(counts)s]
        point3f[] points = [%(points)s]
        float[] widths = [%(widths)s] (
            interpolation = "vertex"
        )
        color3f[] primvars:hairColor = [%(colours)s] (
            interpolation = "vertex"
        )
        rel material:binding = </World/Looks/Hair>
    }

    def Mesh "Floor"
    {
        uniform token subdivisionScheme = "none"
        int[] faceVertexCounts = [4]
        int[] faceVertexIndices = [0, 1, 2, 3]
        point3f[] points = [(-8, -8, -2.2), (8, -8, -2.2), (8, 8, -2.2), (-8, 8, -2.2)]
        color3f[] primvars:displayColor = [(0.3, 0.3, 0.32)]
    }

    def Scope "Looks"
    {
        def Material "Hair"
        {
            token outputs:surface.connect = </World/Looks/Hair/Surface.outputs:surface>
            def Shader "Surface"
            {
                uniform token info:id = "UsdPreviewSurface"
                color3f inputs:diffuseColor.connect = </World/Looks/Hair/HairColor.outputs:result>
                float inputs:roughness = 0.3
                token outputs:surface
            }
            def Shader "HairColor"
            {
                uniform token info:id = "UsdPrimvarReader_float3"
                string inputs:varname = "hairColor"
                float3 inputs:fallback = (0.45, 0.22, 0.08)
                float3 outputs:result
            }
        }
        def Material "Skin"
        {
            token outputs:surface.connect = </World/Looks/Skin/Surface.outputs:surface>
            def Shader "Surface"
            {
                uniform token info:id = "UsdPreviewSurface"
                color3f inputs:diffuseColor = (0.6, 0.42, 0.35)
                float inputs:roughness = 0.6
                token outputs:surface
            }
        }
    }

    def DistantLight "Key"
    {
        float inputs:intensity = 3
        float inputs:angle = 2
        float3 xformOp:rotateXYZ = (50, 0, 150)
        uniform token[] xformOpOrder = ["xformOp:rotateXYZ"]
    }

    def DomeLight "Sky"
    {
        float inputs:intensity = 0.3
    }

    def Camera "Camera"
    {
        float focalLength = 50
        float horizontalAperture = 36
        float verticalAperture = 24
        float2 clippingRange = (0.1, 100)
        double3 xformOp:translate = (6.2, -4.4, 0.9)
        float3 xformOp:rotateXYZ = (84, 0, 55)
        uniform token[] xformOpOrder = ["xformOp:translate", "xformOp:rotateXYZ"]
    }
}
""" % {"radius": RADIUS, "counts": ", ".join(map(str, counts)), "points": ", ".join(fmt(p) for p in points),
       "widths": ", ".join("%.5f" % w for w in widths), "colours": ", ".join(fmt(c) for c in hair_colours)})


if __name__ == "__main__":
    main()
