// LambertianBsdf: ideal diffuse reflection.
//
//   f = albedo / pi        (wo and wi on the same side; two-sided)
//
// | parameter | meaning                                                               |
// |-----------|-----------------------------------------------------------------------|
// | albedo    | hemispherical reflectance, per channel in [0, 1]                      |
// | kind      | the lobe kind it reports: kBsdfDiffuse, or kBsdfGlossy for a lobe that |
// |           | stands in for glossy light (a metal's multiple scattering,             |
// |           | render/bsdfs/ggx_multiple_scattering.h)                               |
//
// The seeds' diffuse BRDF rho_d / pi (003, "diffuse BRDF"); it reflects exactly `albedo` at
// every incident angle. Sampling is cosine-weighted (core/sampling.h), so f |cos| / pdf equals
// the albedo for every sample. Flags: reflection and `kind` (diffuse by default). Path-class
// label: D.
#pragma once

#include <optional>

#include "core/sampling.h"
#include "render/bsdfs/two_sided.h"

namespace fluence::render {

class LambertianBsdf final : public TwoSidedReflection<LambertianBsdf> {
public:
    explicit LambertianBsdf(const RGB& albedo, unsigned kind = kBsdfDiffuse) : albedo_(albedo), kind_(kind) {}

    unsigned flags() const override { return kBsdfReflection | kind_; }

private:
    friend class TwoSidedReflection<LambertianBsdf>;

    RGB fUpper(const Vec3f&, const Vec3f&) const { return albedo_ * kInvPi; }
    float pdfUpper(const Vec3f&, const Vec3f& wi) const { return cosineHemispherePdf(wi.z); }
    std::optional<BsdfSample> sampleUpper(const Vec3f&, float, Vec2f u) const {
        Vec3f wi = sampleCosineHemisphere(u);
        float p = cosineHemispherePdf(wi.z);
        if (p == 0.0f) return std::nullopt;
        return BsdfSample{albedo_ * kInvPi, wi, p};
    }

    RGB albedo_;
    unsigned kind_;
};

}  // namespace fluence::render
