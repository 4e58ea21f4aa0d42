// The GGX (Trowbridge-Reitz) microfacet distribution, isotropic or anisotropic, with Smith's
// height-correlated masking-shadowing, and sampling of its visible normals.
//
//   D(h)        = 1 / (pi ax ay (hx^2 / ax^2 + hy^2 / ay^2 + hz^2)^2)
//                 (Walter et al. 2007; the anisotropic form of Burley 2012 and Heitz 2014)
//   Lambda(w)   = (sqrt(1 + (ax^2 wx^2 + ay^2 wy^2) / wz^2) - 1) / 2
//   G1(w)       = 1 / (1 + Lambda(w));   G2(wo, wi) = 1 / (1 + Lambda(wo) + Lambda(wi))
//   D_wo(h)     = G1(wo) max(0, wo.h) D(h) / wo.z     (the visible normals; Heitz 2014)
//
// ax and ay are the widths along the local x axis (the surface tangent, where the integrator has
// one) and y; with ax == ay == alpha this is the isotropic GGX, D = alpha^2 / (pi ((alpha^2 - 1)
// cos^2 theta_h + 1)^2). D is normalised as a distribution of projected microfacet area (the
// integral of D(h) cos theta_h over the hemisphere is 1) and D_wo as a density over h;
// tests/render/bsdf_microfacet_test.cpp checks both, isotropic and anisotropic. Microfacet
// normals are always in the upper hemisphere (h.z > 0); the functions taking wo require wo.z > 0
// (the BSDFs mirror their configuration first).
#pragma once

#include <algorithm>

#include "core/vec.h"

namespace fluence::render {

// Below this alpha a GGX model is evaluated as its smooth limit (a delta lobe): D is then too
// peaked to be evaluated or sampled reliably in float (alpha^2 < 1e-6).
inline constexpr float kGgxSmoothAlpha = 1e-3f;

class GgxDistribution {
public:
    // alpha: the GGX width (the RMS slope of the microsurface is alpha / sqrt(2) for small
    // alpha); a material's perceptual roughness r usually maps to alpha = r^2.
    explicit GgxDistribution(float alpha) : GgxDistribution(alpha, alpha) {}
    // Anisotropic widths along x and y. The distribution is smooth when both are below
    // kGgxSmoothAlpha; otherwise the narrower one is raised to kGgxSmoothAlpha, which keeps D
    // finite in float (a width that small is a mirror along that axis to within a pixel anyway).
    GgxDistribution(float alphaX, float alphaY)
        : smooth_(std::max(alphaX, alphaY) < kGgxSmoothAlpha),
          alphaX_(smooth_ ? alphaX : std::max(alphaX, kGgxSmoothAlpha)),
          alphaY_(smooth_ ? alphaY : std::max(alphaY, kGgxSmoothAlpha)) {}

    // The widths of a material's perceptual roughness r and anisotropy a in [0, 1] (Standard
    // Surface's specular_roughness and specular_anisotropy), mapped as MaterialX's
    // standard_surface does (its roughness_anisotropy node, after Burley 2012, "Physically-Based
    // Shading at Disney", addendum B): alpha = r^2, aspect = sqrt(1 - min(a, 0.98)),
    // ax = min(alpha / aspect, 1), ay = alpha * aspect. The highlight stretches along x.
    static GgxDistribution fromRoughness(float roughness, float anisotropy = 0.0f);

    bool isSmooth() const { return smooth_; }
    float alphaX() const { return alphaX_; }
    float alphaY() const { return alphaY_; }

    float D(const Vec3f& h) const;
    float lambda(const Vec3f& w) const;
    float G1(const Vec3f& w) const { return 1.0f / (1.0f + lambda(w)); }
    float G2(const Vec3f& wo, const Vec3f& wi) const { return 1.0f / (1.0f + lambda(wo) + lambda(wi)); }

    // A microfacet normal with density visibleNormalPdf(wo, h), wo.z > 0 (Heitz 2018, "Sampling
    // the GGX Distribution of Visible Normals", JCGT 7(4): stretch wo by (ax, ay) to the
    // configuration of a hemisphere of width 1, sample its visible projected area, unstretch).
    Vec3f sampleVisibleNormal(const Vec3f& wo, Vec2f u) const;
    float visibleNormalPdf(const Vec3f& wo, const Vec3f& h) const;

    // Single-scattering mirror reflection off the microfacets of normal h = normalize(wo + wi),
    // without the Fresnel factor: D(h) G2(wo, wi) / (4 wo.z wi.z), for wo.z, wi.z > 0; and the
    // density of wi = reflect(wo, h) when h is drawn by sampleVisibleNormal: D_wo(h) / (4 wo.h).
    float reflectionTerm(const Vec3f& wo, const Vec3f& wi, const Vec3f& h) const {
        return D(h) * G2(wo, wi) / (4.0f * wo.z * wi.z);
    }
    float reflectionPdf(const Vec3f& wo, const Vec3f& h) const { return visibleNormalPdf(wo, h) / (4.0f * dot(wo, h)); }

private:
    bool smooth_;
    float alphaX_, alphaY_;
};

}  // namespace fluence::render
