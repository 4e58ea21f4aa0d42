// CoatedBsdf: a clear dielectric coat over a reflecting base (plastic, varnish, car paint, a
// coated metal), as a Fresnel-weighted coat lobe plus the base attenuated by the coat.
//
//   f(wo, wi) = f_coat(wo, wi) + (1 - F(cos theta_o)) (1 - F(cos theta_i)) f_base(wo, wi)
//   f_coat    = F(wo.h) D(h) G2(wo, wi) / (4 cos theta_o cos theta_i)   (GGX, rough coat), or
//               a delta mirror of reflectance F(cos theta_o)                 (smooth coat)
//   F         = exact dielectric Fresnel of the coat's index eta (render/bsdfs/fresnel.h)
//
// | parameter | meaning                                                                       |
// |-----------|-------------------------------------------------------------------------------|
// | base      | any reflection-only Bsdf (Lambertian: plastic; GgxConductor: coated metal); it |
// |           | must outlive the CoatedBsdf (both live in the same BsdfArena)                 |
// | eta       | the coat's index of refraction relative to the outside (1.5 typical)          |
// | alpha     | the coat's GGX width; below kGgxSmoothAlpha (1e-3) the coat is a mirror        |
//
// The seeds' recipe of "ambient + diffuse + specular" (000) made physical: the specular term is
// the dielectric's Fresnel reflection (Torrance-Sparrow with the Fresnel term, 000), and only the
// light the coat transmits, in and out, reaches and leaves the base (in the spirit of
// Weidlich & Wilkie 2007, "Arbitrarily Layered Micro-Facet Surfaces", simplified).
// Assumptions:
//   - the coat is thin and clear (no absorption, no thickness) and smooth as far as the base is
//     concerned: the transmission factors use the macro-surface Fresnel F(cos theta);
//   - the base is evaluated at the outside directions wo, wi: refraction into the coat, which
//     would narrow a glossy base's lobe and move it, is ignored (exact for a Lambertian base);
//   - light the coat reflects back down onto the base (internal reflection, total beyond the
//     critical angle) is dropped.
// Energy: the albedo is at most E_coat(wo) + (1 - F(cos theta_o)) E_base, which is <= 1 for a
// smooth coat and, for a rough coat, as long as its single-scattering albedo does not exceed
// F(cos theta_o) by more than the base term loses (tests/render/bsdf_coated_test.cpp checks
// albedo <= 1 for rough coats up to alpha = 0.5). What is LOST, against a full simulation of the
// layer (in which a white base returns, after bounces between base and coat, all the light the
// coat lets in): the light reflected back down by the underside of the coat and its later
// re-emergence; with a Lambertian base only the cosine-weighted average of (1 - F) leaves per
// pass, 0.908 for eta = 1.5, so a white plastic (albedo 1, eta 1.5, smooth) reflects
// F(1) + (1 - F(1)) 0.908 = 0.912 at normal incidence instead of 1. A rough coat further loses
// its own multiple scattering, like every single-scattering microfacet model.
//
// Sampling: the coat with probability F(cos theta_o), else the base (with its own uLobe
// rescaled); a non-delta sample returns the whole f and the mixture's pdf. Reciprocal when the
// base is. Two-sided. Flags: reflection, the coat's glossy or specular, and the base's.
// Path-class label: S for a smooth coat's mirror sample, D for the rest.
#pragma once

#include <optional>

#include "render/bsdfs/ggx.h"
#include "render/bsdfs/two_sided.h"

namespace fluence::render {

class CoatedBsdf final : public TwoSidedReflection<CoatedBsdf> {
public:
    // Throws std::invalid_argument if `base` transmits.
    CoatedBsdf(const Bsdf& base, float eta, float alpha);

    unsigned flags() const override {
        return base_->flags() | (distribution_.isSmooth() ? kBsdfSpecular : kBsdfGlossy);
    }

private:
    friend class TwoSidedReflection<CoatedBsdf>;

    RGB fUpper(const Vec3f& wo, const Vec3f& wi) const;
    float pdfUpper(const Vec3f& wo, const Vec3f& wi) const;
    std::optional<BsdfSample> sampleUpper(const Vec3f& wo, float uLobe, Vec2f u) const;
    float coatFresnel(float cosTheta) const;

    const Bsdf* base_;
    float eta_;
    GgxDistribution distribution_;
};

}  // namespace fluence::render
