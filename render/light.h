// Lights: the interface every emitter in the render core implements.
//
// Conventions (all quantities in world space, radiance in the rendering space):
//   sample(p, u)       picks a direction wi from reference point p towards the light; returns
//                      the radiance Li arriving at p along -wi (before visibility), the distance
//                      to the light (infinity for lights at infinity) and the density of wi in
//                      solid angle. Delta lights (a distant light with angle 0) set `delta` and
//                      pdf = 1; their Li is then irradiance.
//   pdf(p, wi, hit)    the solid-angle density sample() picks wi with, for a ray from p that
//                      reached the light at `hit` (hit.point/normal ignored by lights at infinity).
//   emitted(hit, wo)   radiance leaving the light's surface at `hit` towards wo.
//   escaped(dir)       radiance from a light at infinity along a ray that left the scene in dir.
//   power(bounds)      approximate emitted power (luminance-weighted), used to choose which
//                      light to sample.
// Every light's sample/pdf pair is checked by the chi-square and consistency tests in
// tests/render/light_test.cpp.
#pragma once

#include <limits>
#include <optional>
#include <string>

#include "core/rgb.h"

namespace fluence::render {

struct LightSample {
    RGB Li;
    Vec3f wi;
    float distance = std::numeric_limits<float>::infinity();
    float pdf = 0.0f;
    bool delta = false;
};

struct LightHit {
    Vec3f point;
    Vec3f normal;  // geometric normal of the light surface at the hit
};

struct SceneBounds {
    Vec3f centre;
    float radius = 1.0f;
};

class Light {
public:
    virtual ~Light() = default;

    virtual std::optional<LightSample> sample(const Vec3f& p, Vec2f u) const = 0;
    virtual float pdf(const Vec3f& p, const Vec3f& wi, const LightHit& hit) const = 0;
    virtual RGB emitted(const LightHit& hit, const Vec3f& wo) const { return RGB(0.0f); }
    virtual bool atInfinity() const { return false; }
    virtual RGB escaped(const Vec3f& direction) const { return RGB(0.0f); }
    virtual float power(const SceneBounds& bounds) const = 0;
    virtual std::string name() const = 0;
};

}  // namespace fluence::render
