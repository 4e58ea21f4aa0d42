// GgxReflectionBsdf<Fresnel>: single-scattering GGX microfacet reflection with a pluggable
// Fresnel reflectance, written once for the models that differ only in it (a metal,
// render/bsdfs/ggx_conductor.h; the reflection of a dielectric, render/bsdfs/dielectric_reflection.h).
//
//   rough:  f = F(wo.h) D(h) G2(wo, wi) / (4 cos theta_o cos theta_i),    h = normalize(wo + wi)
//   smooth: a delta mirror, f = F(cos theta_o) / cos theta_i, chosen with probability 1
//   D, G2: GGX with height-correlated Smith masking-shadowing (render/bsdfs/ggx.h)
//
// Fresnel is a copyable functor RGB operator()(float cosTheta) giving the reflectance, per
// channel in [0, 1], of a microfacet (or the smooth surface) lit at cosTheta, with
// albedo(w, ggx) and averageAlbedo(ggx): the lobe's tabulated directional albedo at w (w.z > 0,
// in the distribution's frame: an anisotropic albedo depends on w's azimuth) and its
// cosine-weighted average (render/bsdfs/ggx_albedo.h, ggx_anisotropic_albedo.h). reflectance() and averageReflectance() make them
// available to layers (render/bsdfs/layered.h) as the share of the light the lobe keeps from what
// lies beneath.
//
// Torrance-Sparrow / Cook-Torrance microfacet reflection (the seeds, 000) with the GGX
// distribution (Walter et al. 2007). Rough: sampled by the visible normals of wo (Heitz 2018),
// pdf = D_wo(h) / (4 wo.h), so a sample's weight f cos / pdf = F(wo.h) G2 / G1(wo) <= max F.
// Single scattering: light that would bounce between microfacets more than once is lost, a
// deficit that grows with the widths (Kulla & Conty 2017). Reciprocal (F depends on wo.h = wi.h);
// two-sided. Flags: reflection and glossy (rough) or specular (smooth). Path-class label: D
// (glossy) when rough, S when smooth.
#pragma once

#include <cmath>
#include <optional>

#include "render/bsdfs/ggx.h"
#include "render/bsdfs/two_sided.h"

namespace fluence::render {

template <typename Fresnel>
class GgxReflectionBsdf final : public TwoSidedReflection<GgxReflectionBsdf<Fresnel>> {
public:
    GgxReflectionBsdf(const Fresnel& fresnel, const GgxDistribution& ggx) : fresnel_(fresnel), distribution_(ggx) {}

    unsigned flags() const override {
        return kBsdfReflection | (distribution_.isSmooth() ? kBsdfSpecular : kBsdfGlossy);
    }
    // The share of the light arriving from w (w.z > 0) that the lobe keeps from a base, and its
    // cosine-weighted average over the hemisphere (see Fresnel above).
    RGB reflectance(const Vec3f& w) const { return fresnel_.albedo(w, distribution_); }
    RGB averageReflectance() const { return fresnel_.averageAlbedo(distribution_); }

private:
    friend class TwoSidedReflection<GgxReflectionBsdf<Fresnel>>;

    RGB fUpper(const Vec3f& wo, const Vec3f& wi) const {
        if (distribution_.isSmooth()) return RGB(0.0f);
        Vec3f h = normalize(wo + wi);
        return fresnel_(dot(wo, h)) * distribution_.reflectionTerm(wo, wi, h);
    }
    float pdfUpper(const Vec3f& wo, const Vec3f& wi) const {
        if (distribution_.isSmooth()) return 0.0f;
        return distribution_.reflectionPdf(wo, normalize(wo + wi));
    }
    std::optional<BsdfSample> sampleUpper(const Vec3f& wo, float, Vec2f u) const {
        if (distribution_.isSmooth()) {
            Vec3f wi = mirrorZ(-wo);
            return BsdfSample{fresnel_(wo.z) / wi.z, wi, 1.0f, true};
        }
        Vec3f h = distribution_.sampleVisibleNormal(wo, u);
        Vec3f wi = reflect(wo, h);
        if (wi.z <= 0.0f) return std::nullopt;
        float p = distribution_.reflectionPdf(wo, h);
        if (!(p > 0.0f)) return std::nullopt;
        return BsdfSample{fresnel_(dot(wo, h)) * distribution_.reflectionTerm(wo, wi, h), wi, p};
    }

    Fresnel fresnel_;
    GgxDistribution distribution_;
};

}  // namespace fluence::render
