// What the lights with a surface share: the conversion of an area density to solid angle, the
// sample record their next-event samplers return, and emission from a point of their surface with
// a cosine-weighted direction (Light::sampleEmission, render/light.h). Used by the rect, disk,
// triangle and sphere lights.
#pragma once

#include <algorithm>
#include <optional>

#include "core/check.h"
#include "core/frame.h"
#include "core/sampling.h"
#include "render/light.h"

namespace fluence::render {

// Solid-angle density of a point sampled with density `areaPdf` per unit area, seen from
// distance^2 `distanceSquared` at cosine `cosLight` to the light's normal (0 when it faces away).
inline float areaToSolidAngle(float areaPdf, float distanceSquared, float cosLight) {
    return cosLight > 0.0f ? areaPdf * distanceSquared / cosLight : 0.0f;
}

// A sample written straight into the returned optional's storage. Aggregate-initialising a
// LightSample and moving it into the optional made GCC build it on the stack piece by piece and
// copy it out in 16-byte loads, which the store buffer cannot forward: a stall on every sample.
inline std::optional<LightSample> surfaceSample(const RGB& Li, const Vec3f& wi, float distance, float pdf) {
    FLUENCE_DCHECK(isUnit(wi));
    FLUENCE_DCHECK(isValidDensity(pdf) && pdf > 0.0f);
    FLUENCE_DCHECK(isFinite(Li));
    std::optional<LightSample> s(std::in_place);
    s->Li = Li;
    s->wi = wi;
    s->distance = distance;
    s->pdf = pdf;
    return s;
}

// Emission from a surface point with unit emitting normal n, drawn with area density `areaPdf`,
// in a cosine-weighted direction about n; Le is left black for the light to fill in.
inline EmissionSample fromSurface(const Vec3f& point, const Vec3f& n, float areaPdf, Vec2f uDirection) {
    FLUENCE_DCHECK(isUnit(n));
    Vec3f direction = normalize(Frame::fromNormal(n).toWorld(sampleCosineHemisphere(uDirection)));
    float cosine = std::max(0.0f, dot(n, direction));
    return {point, direction, n, RGB(0.0f), {areaPdf, cosineHemispherePdf(cosine), cosine}};
}

// The densities fromSurface draws `direction` with, from a point of area density `areaPdf`.
inline EmissionDensity surfaceDensity(const Vec3f& n, float areaPdf, const Vec3f& direction) {
    float cosine = dot(n, direction);
    return cosine > 0.0f ? EmissionDensity{areaPdf, cosineHemispherePdf(cosine), cosine} : EmissionDensity{};
}

}  // namespace fluence::render
