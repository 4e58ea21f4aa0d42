// LambertianTransmissionBsdf: ideal diffuse transmission, the boundary of a subsurface walk.
//
//   f = transmittance / pi   (wo and wi on opposite sides), 0 on the same side
//
// | parameter     | meaning                                                       |
// |---------------|---------------------------------------------------------------|
// | transmittance | hemispherical transmittance, per channel in [0, 1]            |
//
// Light crossing it forgets its direction: it leaves cosine-distributed on the other side, as
// light entering or leaving a densely scattering material does (the "diffuse entry and exit" of
// random-walk subsurface scattering, Chiang et al. 2016, "Practical and Controllable Subsurface
// Scattering for Production Path Tracing"). Both sides behave alike and no index of refraction is
// crossed (eta 1), so f is symmetric. Sampling is cosine-weighted on the side opposite wo:
// f |cos| / pdf equals the transmittance. Flags: transmission, diffuse. Path-class label: D.
#pragma once

#include <optional>

#include "core/sampling.h"
#include "render/bsdf.h"

namespace fluence::render {

class LambertianTransmissionBsdf final : public Bsdf {
public:
    explicit LambertianTransmissionBsdf(const RGB& transmittance) : transmittance_(transmittance) {}

    RGB f(const Vec3f& wo, const Vec3f& wi) const override {
        return wo.z * wi.z < 0.0f ? transmittance_ * kInvPi : RGB(0.0f);
    }
    float pdf(const Vec3f& wo, const Vec3f& wi) const override {
        return wo.z * wi.z < 0.0f ? cosineHemispherePdf(std::abs(wi.z)) : 0.0f;
    }
    std::optional<BsdfSample> sample(const Vec3f& wo, float, Vec2f u) const override {
        if (wo.z == 0.0f) return std::nullopt;
        Vec3f wi = sampleCosineHemisphere(u);
        float p = cosineHemispherePdf(wi.z);
        if (p == 0.0f) return std::nullopt;
        if (wo.z > 0.0f) wi.z = -wi.z;
        return BsdfSample{transmittance_ * kInvPi, wi, p};
    }
    unsigned flags() const override { return kBsdfTransmission | kBsdfDiffuse; }

private:
    RGB transmittance_;
};

}  // namespace fluence::render
