// How texture coordinates change across a triangle and across a pixel.
//
// Texture filtering needs, at a hit, how far st moves over one pixel of the image (the lookup's
// footprint). Fluence approximates the ray differentials from the camera at every path vertex,
// as pbrt-v4 does: the footprint is that of a pixel of the camera at the hit's distance (camera
// rays get their own pixel; later vertices a footprint at least as wide as if the camera saw
// them), spread over the surface by the angle it is seen at, then mapped into st by the
// triangle's own st parameterisation.
#pragma once

#include "core/vec.h"

namespace fluence::render {

// A triangle's edges in world space and the same edges in a 2D texture parameterisation.
struct TriangleParameterisation {
    Vec3f e1, e2;        // p1 - p0, p2 - p0
    float d1[2], d2[2];  // st1 - st0, st2 - st0
};

// World-space offsets of one pixel step along the image's x and y, in the surface's plane.
struct PixelFootprint {
    Vec3f dpdx{0.0f}, dpdy{0.0f};
    bool valid = false;
};

// The footprint at p (unit geometric normal n) seen from a camera at `eye` with `pixelsPerUnit`
// (render::Camera::pixelsPerUnitAt(p)). Grazing views are limited to 1/20 of the cosine so the
// footprint stays finite.
PixelFootprint pixelFootprint(const Vec3f& p, const Vec3f& n, const Vec3f& eye, float pixelsPerUnit);

// How st changes along a world-space offset dp in the triangle's plane.
void stAlong(const TriangleParameterisation& tri, const Vec3f& dp, float dst[2]);

// dp/ds of the parameterisation (the direction s grows along), or zero when st is degenerate.
Vec3f dpds(const TriangleParameterisation& tri);
// dp/dt likewise.
Vec3f dpdt(const TriangleParameterisation& tri);

}  // namespace fluence::render
