#include "render/light_shaping.h"

#include <algorithm>
#include <cmath>

#include "core/sampling.h"

namespace fluence::render {

LightShaping::LightShaping(const LightShapingDesc& desc, const Vec3f& axis)
    : active_(true), axis_(axis), focus_(std::max(0.0f, desc.focus)), focusTint_(desc.focusTint) {
    cutoff_ = std::clamp(desc.coneAngleDegrees, 0.0f, 180.0f) * kPi / 180.0f;
    cosCutoff_ = std::cos(cutoff_);
    softStart_ = (1.0f - std::max(0.0f, desc.coneSoftness)) * cutoff_;
}

RGB LightShaping::factor(const Vec3f& emission) const {
    if (!active_) return RGB(1.0f);
    float cosTheta = std::clamp(dot(axis_, emission), -1.0f, 1.0f);
    if (cosTheta < cosCutoff_) return RGB(0.0f);
    float cone = 1.0f;
    if (softStart_ < cutoff_) {
        float t = std::clamp((std::acos(cosTheta) - softStart_) / (cutoff_ - softStart_), 0.0f, 1.0f);
        cone = 1.0f - t * t * (3.0f - 2.0f * t);
    }
    if (focus_ == 0.0f) return RGB(cone);
    float f = cosTheta > 0.0f ? std::pow(cosTheta, focus_) : 0.0f;
    return (focusTint_ * (1.0f - f) + RGB(f)) * cone;
}

float LightShaping::powerFraction(bool oneSided) const {
    if (!active_) return 1.0f;
    if (oneSided) return cutoff_ < kPi / 2 ? std::sin(cutoff_) * std::sin(cutoff_) : 1.0f;
    return 0.5f * (1.0f - cosCutoff_);
}

LightBounds LightShaping::narrow(LightBounds b, bool oneSided) const {
    if (!active_) return b;
    b.phi *= powerFraction(oneSided);
    if (oneSided) {
        b.cosThetaE = std::max(b.cosThetaE, cosCutoff_);
    } else {
        b.axis = axis_;
        b.cosThetaO = cosCutoff_;
        b.cosThetaE = 1.0f;
    }
    return b;
}

}  // namespace fluence::render
