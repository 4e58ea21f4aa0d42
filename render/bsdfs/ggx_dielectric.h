// GgxDielectricBsdf: the interface between two dielectrics (glass, water), reflecting and
// refracting, rough (GGX microfacets) or smooth.
//
// In the configuration mirrored so that wo is on the +z side, with eta' = n(wi side) / n(wo side)
// for a refracted wi (eta or 1/eta) and F = exact dielectric Fresnel at the microfacet:
//   reflection (wi.z > 0), h = normalize(wo + wi):
//       f = F(wo.h) D(h) G2(wo, wi) / (4 cos theta_o cos theta_i)
//   refraction (wi.z < 0), h = normalize(wo + eta' wi) turned to +z:
//       f = (1 - F(wo.h)) D(h) G2(wo, wi) |wo.h| |wi.h| / (|cos theta_o| |cos theta_i| (wo.h + eta' wi.h)^2)
// (Walter et al. 2007, "Microfacet Models for Refraction through Rough Surfaces", eq. 20-21),
// which includes the radiance factor 1 / eta'^2 (render/bsdf.h, "RADIANCE, NOT IMPORTANCE").
// Smooth (alpha < kGgxSmoothAlpha, or eta == 1: an index-matched interface is invisible): a delta
// mirror with reflectance F(cos theta_o) and a delta refraction with transmittance
// (1 - F) / eta'^2, each chosen with its Fresnel probability.
//
// | parameter | meaning                                                                   |
// |-----------|---------------------------------------------------------------------------|
// | eta       | IOR of the inside (the side opposite the normal) over the outside's; > 0  |
// | alpha     | GGX width; below kGgxSmoothAlpha (1e-3) the interface is smooth            |
//
// The Fresnel term of the seeds' Cook-Torrance (000) carried to transmission: Fresnel's exact
// unpolarised equations (render/bsdfs/fresnel.h), total internal reflection included. Sampling:
// h from the visible normals of wo (Heitz 2018), then reflection with probability F(wo.h), else
// refraction, so the weight is G2 / G1(wo) (times 1 / eta'^2 when refracted): no variance from F.
// Generalised reciprocity f(wo, wi) / n(wo)^2 = f(wi, wo) / n(wi)^2; flux is conserved exactly
// when smooth and up to the single-scattering deficit of GGX when rough.
//
// One-sided: wo.z > 0 is outside. Flags: reflection, transmission, and glossy (rough) or specular
// (smooth). Path-class label: D (glossy) when rough, S when smooth.
#pragma once

#include <optional>

#include "render/bsdf.h"
#include "render/bsdfs/ggx.h"

namespace fluence::render {

class GgxDielectricBsdf final : public Bsdf {
public:
    GgxDielectricBsdf(float eta, float alpha) : eta_(eta), distribution_(alpha) {}

    RGB f(const Vec3f& wo, const Vec3f& wi) const override;
    float pdf(const Vec3f& wo, const Vec3f& wi) const override;
    std::optional<BsdfSample> sample(const Vec3f& wo, float uLobe, Vec2f u) const override;
    unsigned flags() const override {
        return kBsdfReflection | kBsdfTransmission | (isSmooth() ? kBsdfSpecular : kBsdfGlossy);
    }

private:
    // A pair of directions mirrored so that wo.z > 0, with the relative IOR of the refracted side
    // and the microfacet normal that scatters wo into wi.
    struct Configuration {
        Vec3f wo, wi, h;
        float eta;      // n(refracted side) / n(wo side)
        bool reflected;
        float fresnel;  // F(wo.h)
    };
    bool isSmooth() const { return distribution_.isSmooth() || eta_ == 1.0f; }
    float relativeEta(const Vec3f& wo) const { return wo.z > 0.0f ? eta_ : 1.0f / eta_; }
    std::optional<Configuration> configuration(const Vec3f& wo, const Vec3f& wi) const;
    float value(const Configuration& c) const;
    float density(const Configuration& c) const;
    std::optional<BsdfSample> sampleSmooth(const Vec3f& wo, float uLobe) const;

    float eta_;
    GgxDistribution distribution_;
};

}  // namespace fluence::render
