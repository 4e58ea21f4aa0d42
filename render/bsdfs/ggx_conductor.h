// GgxConductorBsdf: a metal, as GGX microfacet reflection with Schlick's Fresnel.
//
//   f = F(wo.h) D(h) G2(wo, wi) / (4 cos theta_o cos theta_i),    h = normalize(wo + wi)
//   D, G2: GGX with height-correlated Smith masking-shadowing (render/bsdfs/ggx.h)
//   F: Schlick's approximation from the reflectance at normal incidence F0 (render/bsdfs/fresnel.h)
//
// | parameter | meaning                                                                    |
// |-----------|----------------------------------------------------------------------------|
// | f0        | reflectance at normal incidence, per channel (the metal's "specular colour")|
// | alpha     | GGX width; below kGgxSmoothAlpha (1e-3) the surface is a perfect mirror     |
//
// The microfacet model of the seeds' Torrance-Sparrow / Cook-Torrance (000), with the GGX
// distribution (Walter et al. 2007) in place of Beckmann's for its longer highlight tails.
// Fresnel: Schlick's F0 form, chosen over the complex index of refraction because F0 is what
// material descriptions (UsdPreviewSurface's specularColor, metalness workflows) provide; it
// lacks the dip of real metals near grazing angles.
//
// Rough: sampled by visible normals (Heitz 2018), so f cos / pdf = F G2 / G1(wo) <= 1. Single
// scattering: light that would bounce between microfacets more than once is lost, a deficit that
// grows with alpha (Kulla & Conty 2017); with F0 = 1 the albedo is 1 at alpha -> 0 and below 1
// otherwise. Smooth: a delta mirror, f = F(cos theta_o) / cos theta_i, chosen with probability 1.
//
// Reciprocal; two-sided. Flags: reflection and glossy (rough) or specular (smooth).
// Path-class label: D (glossy) when rough, S when smooth.
#pragma once

#include <optional>

#include "render/bsdfs/ggx.h"
#include "render/bsdfs/two_sided.h"

namespace fluence::render {

class GgxConductorBsdf final : public TwoSidedReflection<GgxConductorBsdf> {
public:
    GgxConductorBsdf(const RGB& f0, float alpha) : f0_(f0), distribution_(alpha) {}

    unsigned flags() const override {
        return kBsdfReflection | (distribution_.isSmooth() ? kBsdfSpecular : kBsdfGlossy);
    }

private:
    friend class TwoSidedReflection<GgxConductorBsdf>;

    RGB fUpper(const Vec3f& wo, const Vec3f& wi) const;
    float pdfUpper(const Vec3f& wo, const Vec3f& wi) const;
    std::optional<BsdfSample> sampleUpper(const Vec3f& wo, float uLobe, Vec2f u) const;

    RGB f0_;
    GgxDistribution distribution_;
};

}  // namespace fluence::render
