// The GGX (Trowbridge-Reitz) microfacet distribution with Smith's height-correlated
// masking-shadowing, and sampling of its visible normals.
//
//   D(h)        = alpha^2 / (pi ((alpha^2 - 1) cos^2 theta_h + 1)^2)       (Walter et al. 2007)
//   Lambda(w)   = (sqrt(1 + alpha^2 tan^2 theta) - 1) / 2
//   G1(w)       = 1 / (1 + Lambda(w));   G2(wo, wi) = 1 / (1 + Lambda(wo) + Lambda(wi))
//   D_wo(h)     = G1(wo) max(0, wo.h) D(h) / wo.z     (the visible normals; Heitz 2014)
//
// D is normalised as a distribution of projected microfacet area (the integral of D(h) cos
// theta_h over the hemisphere is 1) and D_wo as a density over h; tests/render/bsdf_microfacet_test.cpp
// checks both. Microfacet normals are always in the upper hemisphere (h.z > 0); the functions
// taking wo require wo.z > 0 (the BSDFs mirror their configuration first).
#pragma once

#include "core/vec.h"

namespace fluence::render {

// Below this alpha a GGX model is evaluated as its smooth limit (a delta lobe): D is then too
// peaked to be evaluated or sampled reliably in float (alpha^2 < 1e-6).
inline constexpr float kGgxSmoothAlpha = 1e-3f;

class GgxDistribution {
public:
    // alpha: the GGX width (the RMS slope of the microsurface is alpha / sqrt(2) for small
    // alpha); a material's perceptual roughness r usually maps to alpha = r^2.
    explicit GgxDistribution(float alpha) : alpha_(alpha) {}

    bool isSmooth() const { return alpha_ < kGgxSmoothAlpha; }

    float D(const Vec3f& h) const;
    float lambda(const Vec3f& w) const;
    float G1(const Vec3f& w) const { return 1.0f / (1.0f + lambda(w)); }
    float G2(const Vec3f& wo, const Vec3f& wi) const { return 1.0f / (1.0f + lambda(wo) + lambda(wi)); }

    // A microfacet normal with density visibleNormalPdf(wo, h), wo.z > 0 (Heitz 2018, "Sampling
    // the GGX Distribution of Visible Normals", JCGT 7(4)).
    Vec3f sampleVisibleNormal(const Vec3f& wo, Vec2f u) const;
    float visibleNormalPdf(const Vec3f& wo, const Vec3f& h) const;

    // Single-scattering mirror reflection off the microfacets of normal h = normalize(wo + wi),
    // without the Fresnel factor: D(h) G2(wo, wi) / (4 wo.z wi.z), for wo.z, wi.z > 0; and the
    // density of wi = reflect(wo, h) when h is drawn by sampleVisibleNormal: D_wo(h) / (4 wo.h).
    float reflectionTerm(const Vec3f& wo, const Vec3f& wi, const Vec3f& h) const {
        return D(h) * G2(wo, wi) / (4.0f * wo.z * wi.z);
    }
    float reflectionPdf(const Vec3f& wo, const Vec3f& h) const {
        return visibleNormalPdf(wo, h) / (4.0f * dot(wo, h));
    }

private:
    float alpha_;
};

}  // namespace fluence::render
