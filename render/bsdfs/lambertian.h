// LambertianBsdf: ideal diffuse reflection.
//
//   f = albedo / pi        (wo and wi on the same side; two-sided)
//
// | parameter | meaning                                                  |
// |-----------|----------------------------------------------------------|
// | albedo    | hemispherical reflectance, per channel in [0, 1]         |
//
// The seeds' diffuse BRDF rho_d / pi (003, "diffuse BRDF"); it reflects exactly `albedo` at
// every incident angle. Sampling is cosine-weighted (core/sampling.h), so f |cos| / pdf equals
// the albedo for every sample. Flags: reflection, diffuse. Path-class label: D.
#pragma once

#include <optional>

#include "core/sampling.h"
#include "render/bsdfs/two_sided.h"

namespace fluence::render {

class LambertianBsdf final : public TwoSidedReflection<LambertianBsdf> {
public:
    explicit LambertianBsdf(const RGB& albedo) : albedo_(albedo) {}

    unsigned flags() const override { return kBsdfReflection | kBsdfDiffuse; }

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
};

}  // namespace fluence::render
