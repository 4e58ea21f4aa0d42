// GgxDielectricBsdf: the interface between two dielectrics (glass, water), reflecting and
// refracting, rough (GGX microfacets, isotropic or anisotropic) or smooth, with optional tints.
//
// In the configuration mirrored so that wo is on the +z side, with eta' = n(wi side) / n(wo side)
// for a refracted wi (eta or 1/eta), F = exact dielectric Fresnel at the microfacet, and R(F),
// T(F) its tinted split (render/bsdfs/dielectric_tints.h; R = F and T = 1 - F untinted):
//   reflection (wi.z > 0), h = normalize(wo + wi):
//       f = R(F(wo.h)) D(h) G2(wo, wi) / (4 cos theta_o cos theta_i)
//   refraction (wi.z < 0), h = normalize(wo + eta' wi) turned to +z:
//       f = T(F(wo.h)) D(h) G2(wo, wi) |wo.h| |wi.h| / (|cos theta_o| |cos theta_i| (wo.h + eta' wi.h)^2)
// (Walter et al. 2007, "Microfacet Models for Refraction through Rough Surfaces", eq. 20-21),
// which includes the radiance factor 1 / eta'^2 (render/bsdf.h, TRANSPORT MODE).
// Smooth (both widths < kGgxSmoothAlpha, or eta == 1: an index-matched interface is invisible):
// a delta mirror with reflectance R(F(cos theta_o)) and a delta refraction with transmittance
// T(F) / eta'^2.
//
// | parameter | meaning                                                                   |
// |-----------|---------------------------------------------------------------------------|
// | eta       | IOR of the inside (the side opposite the normal) over the outside's; > 0  |
// | ggx       | GGX widths (x along the tangent); smooth below kGgxSmoothAlpha             |
// | tints     | reflection tint (specular weight x colour) and transmission tint applied   |
// |           | at each crossing of the interface; white by default                        |
//
// The Fresnel term of the seeds' Cook-Torrance (000) carried to transmission: Fresnel's exact
// unpolarised equations (render/bsdfs/fresnel.h), total internal reflection included. Sampling:
// h from the visible normals of wo (Heitz 2018), then reflection with probability
// tints.reflectProbability(F(wo.h)) (F itself untinted), else refraction, so the untinted weight
// is G2 / G1(wo) (times 1 / eta'^2 when refracted): no variance from F. Generalised reciprocity
// f(wo, wi) / n(wo)^2 = f(wi, wo) / n(wi)^2 (the tints are symmetric); flux is conserved exactly
// when smooth and untinted, and up to the single-scattering deficit of GGX when rough.
//
// One-sided: wo.z > 0 is outside. Flags: reflection, transmission, and glossy (rough) or specular
// (smooth). Path-class label: D (glossy) when rough, S when smooth.
#pragma once

#include <optional>

#include "render/bsdf.h"
#include "render/bsdfs/dielectric_tints.h"
#include "render/bsdfs/ggx.h"

namespace fluence::render {

class GgxDielectricBsdf final : public Bsdf {
public:
    GgxDielectricBsdf(float eta, const GgxDistribution& ggx, const DielectricTints& tints = {})
        : eta_(eta), distribution_(ggx), tints_(tints) {}

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
        float eta;  // n(refracted side) / n(wo side)
        bool reflected;
        float fresnel;  // F(wo.h)
    };
    bool isSmooth() const { return distribution_.isSmooth() || eta_ == 1.0f; }
    float relativeEta(const Vec3f& wo) const { return wo.z > 0.0f ? eta_ : 1.0f / eta_; }
    std::optional<Configuration> configuration(const Vec3f& wo, const Vec3f& wi) const;
    RGB value(const Configuration& c) const;
    float density(const Configuration& c) const;
    std::optional<BsdfSample> sampleSmooth(const Vec3f& wo, float uLobe) const;

    float eta_;
    GgxDistribution distribution_;
    DielectricTints tints_;
};

}  // namespace fluence::render
