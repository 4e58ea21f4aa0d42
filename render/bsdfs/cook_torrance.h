// CookTorranceBsdf: the Torrance-Sparrow / Cook-Torrance microfacet specular reflection.
//
//   f = ks F(wo.h) D(h) G(wo, wi) / (4 cos theta_o cos theta_i),     h = normalize(wo + wi)
//   D = Beckmann (render/bsdfs/beckmann.h), RMS slope m
//   G = min(1, 2 (n.h)(n.wo) / (wo.h), 2 (n.h)(n.wi) / (wo.h))   (Torrance & Sparrow's V-cavities)
//   F = exact unpolarised dielectric Fresnel of index eta (render/bsdfs/fresnel.h)
//
// | parameter | meaning                                                                 |
// |-----------|-------------------------------------------------------------------------|
// | ks        | per-channel scale of the lobe (1 for a physical interface)              |
// | eta       | relative index of refraction of the surface (1.5 for glass or plastic)  |
// | m         | Beckmann RMS slope; clamped to >= 1e-3 (for a mirror, use the GGX models)|
//
// From the seeds (000, "Torrance-Sparrow" and "Cook-Torrance"): rho = F/pi * D G / ((N.V)(N.L))
// with D the microfacet distribution, G the geometrical attenuation and F the Fresnel term. The
// seeds' expression and this one agree when the seeds' D carries 1 / (4 m^2 cos^4) in front of the
// exponential; we use Beckmann's D normalised as projected area (1 / (pi m^2 cos^4)) with the
// 1 / (4 cos cos) Jacobian of the half vector (Walter et al. 2007), so that F = 1 reflects at
// most all the light. Only the specular term is modelled: Cook & Torrance's diffuse term is a
// LambertianBsdf, and a plastic is a CoatedBsdf.
//
// Sampling draws h with density D(h) cos theta_h and reflects wo about it (pdf D cos_h /
// (4 wo.h)). Reciprocal; two-sided. Flags: reflection, glossy. Path-class label: D (glossy).
#pragma once

#include <optional>

#include "render/bsdfs/beckmann.h"
#include "render/bsdfs/two_sided.h"

namespace fluence::render {

class CookTorranceBsdf final : public TwoSidedReflection<CookTorranceBsdf> {
public:
    CookTorranceBsdf(const RGB& ks, float eta, float m);

    unsigned flags() const override { return kBsdfReflection | kBsdfGlossy; }

private:
    friend class TwoSidedReflection<CookTorranceBsdf>;

    RGB fUpper(const Vec3f& wo, const Vec3f& wi) const;
    float pdfUpper(const Vec3f& wo, const Vec3f& wi) const;
    std::optional<BsdfSample> sampleUpper(const Vec3f& wo, float uLobe, Vec2f u) const;

    RGB ks_;
    float eta_;
    BeckmannDistribution distribution_;
};

}  // namespace fluence::render
