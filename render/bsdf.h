// BSDFs: the interface convention every scattering model in Fluence follows.
//
// All directions are unit vectors in the local shading frame (z = shading normal) and point
// away from the surface: `wo` towards the viewer (or previous vertex), `wi` towards the light
// (or next vertex).
//   f(wo, wi)        the BSDF value, WITHOUT the cosine factor |cos theta_i|.
//   sample(wo, u)    draws wi with density pdf(wo, wi) (solid angle); returns f and pdf
//                    separately (never pre-divided); std::nullopt when no direction is produced.
//   pdf(wo, wi)      the density sample() draws wi with.
// A test checks, for every model, that sample() agrees with f() and pdf(), and a chi-square
// test checks the distribution of sample() against pdf() (tests/render/bsdf_test.cpp).
//
// Surfaces are two-sided: a BSDF evaluated with wo below the shading hemisphere mirrors both
// directions to the upper side, so a single-sided wall reflects the same from either side.
#pragma once

#include <optional>

#include "core/rgb.h"
#include "core/sampling.h"

namespace fluence::render {

struct BsdfSample {
    RGB f;
    Vec3f wi;
    float pdf = 0.0f;
};

// Lambertian diffuse reflection: f = albedo / pi on the side wo is on.
class LambertianBsdf {
public:
    explicit LambertianBsdf(const RGB& albedo) : albedo_(albedo) {}

    const RGB& albedo() const { return albedo_; }

    RGB f(const Vec3f& wo, const Vec3f& wi) const {
        return sameHemisphere(wo, wi) ? albedo_ * kInvPi : RGB(0.0f);
    }
    float pdf(const Vec3f& wo, const Vec3f& wi) const {
        return sameHemisphere(wo, wi) ? cosineHemispherePdf(std::abs(wi.z)) : 0.0f;
    }
    std::optional<BsdfSample> sample(const Vec3f& wo, Vec2f u) const {
        Vec3f wi = sampleCosineHemisphere(u);
        if (wo.z < 0.0f) wi.z = -wi.z;
        float p = cosineHemispherePdf(std::abs(wi.z));
        if (p == 0.0f) return std::nullopt;
        return BsdfSample{albedo_ * kInvPi, wi, p};
    }

private:
    static bool sameHemisphere(const Vec3f& a, const Vec3f& b) { return a.z * b.z > 0.0f; }
    RGB albedo_;
};

}  // namespace fluence::render
