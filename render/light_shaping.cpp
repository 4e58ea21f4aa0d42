#include "render/light_shaping.h"

#include <algorithm>
#include <cmath>

#include "core/frame.h"
#include "core/sampling.h"

namespace fluence::render {

namespace {

constexpr int kThetaCells = 64, kPhiCells = 128;  // the direction grid of a profiled light

// `v` less its components along the unit vectors `a` and `b`, normalized; `fallback` when nothing is left.
Vec3f orthogonalTo(Vec3f v, const Vec3f& a, const Vec3f& b, const Vec3f& fallback) {
    v = v - a * dot(v, a) - b * dot(v, b);
    float len = length(v);
    return len > 1e-6f ? v / len : fallback;
}

}  // namespace

ShapingFrame::ShapingFrame(const Vec3f& axisIn, const Matrix4& lightToWorld) : axis(axisIn) {
    x = orthogonalTo(Vec3f(lightToWorld.transformVector({1.0, 0.0, 0.0})), axis, Vec3f(0.0f),
                     Frame::fromNormal(axis).s);
    y = orthogonalTo(Vec3f(lightToWorld.transformVector({0.0, 1.0, 0.0})), axis, x, cross(x, axis));
}

LightShaping::LightShaping(const LightShapingDesc& desc, const Vec3f& axis, const Matrix4& lightToWorld)
    : active_(true), axis_(axis), focus_(std::max(0.0f, desc.focus)), focusTint_(desc.focusTint) {
    cutoff_ = std::clamp(desc.coneAngleDegrees, 0.0f, 180.0f) * kPi / 180.0f;
    cosCutoff_ = std::cos(cutoff_);
    softStart_ = (1.0f - std::clamp(desc.coneSoftness, 0.0f, 1.0f)) * cutoff_;
    // The cone is at most 1 and the focus lerp(f, focusTint, 1) at most max(1, focusTint), both
    // reached on the axis or towards the cone's edge; luminance is linear, so this bounds it.
    if (focus_ > 0.0f) peak_ = std::max(1.0f, luminance(focusTint_));
    if (!desc.ies) return;
    const ShapingFrame frame(axis_, lightToWorld);
    xAxis_ = frame.x;
    yAxis_ = frame.y;
    ies_ = std::make_shared<IesProfile>(*desc.ies, desc.iesAngleScale, desc.iesNormalize);
    buildDirections();
}

float LightShaping::iesFactor(const Vec3f& emission) const {
    float theta = std::acos(std::clamp(dot(axis_, emission), -1.0f, 1.0f));
    float phi = std::atan2(-dot(emission, yAxis_), -dot(emission, xAxis_));
    return ies_->factor(theta, phi);
}

Vec3f LightShaping::direction(float theta, float phi) const {
    float sinTheta = std::sin(theta);
    return normalize(xAxis_ * (-sinTheta * std::cos(phi)) + yAxis_ * (-sinTheta * std::sin(phi)) +
                     axis_ * std::cos(theta));
}

void LightShaping::buildDirections() {
    std::vector<float> weights(std::size_t(kThetaCells) * kPhiCells);
    const float dTheta = kPi / kThetaCells, dPhi = 2.0f * kPi / kPhiCells;
    double iesIntegral = 0.0;
    peak_ = 0.0f;
    for (int i = 0; i < kThetaCells; ++i)
        for (int j = 0; j < kPhiCells; ++j) {
            float largest = 0.0f;
            for (int a = 0; a <= 2; ++a)
                for (int b = 0; b <= 2; ++b)
                    largest =
                        std::max(largest, luminance(factor(direction((i + 0.5f * a) * dTheta, (j + 0.5f * b) * dPhi))));
            float theta = (i + 0.5f) * dTheta;
            weights[std::size_t(i) * kPhiCells + j] = largest * std::sin(theta);
            peak_ = std::max(peak_, largest);
            iesIntegral += iesFactor(direction(theta, (j + 0.5f) * dPhi)) * std::sin(theta) * dTheta * dPhi;
        }
    iesMean_ = static_cast<float>(iesIntegral / (4.0 * kPi));
    directions_ = ImageDistribution(kPhiCells, kThetaCells, std::move(weights));
}

std::optional<LightShaping::DirectionSample> LightShaping::sampleDirection(Vec2f u) const {
    ImageDistribution::Sample s = directions_.sample(u);
    float theta = s.uv.y * kPi, sinTheta = std::sin(theta);
    if (!(s.pdf > 0.0f) || !(sinTheta > 0.0f)) return std::nullopt;
    return DirectionSample{direction(theta, s.uv.x * 2.0f * kPi), s.pdf / (2.0f * kPi * kPi * sinTheta)};
}

float LightShaping::directionPdf(const Vec3f& emission) const {
    float theta = std::acos(std::clamp(dot(axis_, emission), -1.0f, 1.0f)), sinTheta = std::sin(theta);
    if (!(sinTheta > 0.0f)) return 0.0f;
    float phi = std::atan2(-dot(emission, yAxis_), -dot(emission, xAxis_));
    if (phi < 0.0f) phi += 2.0f * kPi;
    return directions_.pdf(Vec2f(phi / (2.0f * kPi), theta / kPi)) / (2.0f * kPi * kPi * sinTheta);
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
    if (ies_) cone *= iesFactor(emission);
    if (focus_ == 0.0f) return RGB(cone);
    float f = std::pow(std::abs(cosTheta), focus_);
    return (focusTint_ * (1.0f - f) + RGB(f)) * cone;
}

float LightShaping::powerFraction(bool oneSided) const {
    if (!active_) return 1.0f;
    if (oneSided) return (cutoff_ < kPi / 2 ? std::sin(cutoff_) * std::sin(cutoff_) : 1.0f) * iesMean_;
    return 0.5f * (1.0f - cosCutoff_) * iesMean_;
}

LightBounds LightShaping::narrow(LightBounds b, bool oneSided) const {
    if (!active_) return b;
    b.phi *= peak_;
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
