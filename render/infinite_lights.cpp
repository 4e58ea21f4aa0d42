#include "render/infinite_lights.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/sampling.h"

namespace fluence::render {

DistantLight::DistantLight(const LightDesc& d) : name_(d.name), value_(d.radiance) {
    towardsLight_ = normalize(Vec3f(d.transform.transformVector({0.0, 0.0, 1.0})));
    double halfAngle = std::clamp(double(d.angleDegrees), 0.0, 359.999) * 0.5 * std::numbers::pi / 180.0;
    oneMinusCosMax_ = halfAngle > 0.0 ? 2.0 * std::sin(0.5 * halfAngle) * std::sin(0.5 * halfAngle) : 0.0;
    if (!isDelta() && d.normalize) {
        // Irradiance of a uniform disk on a surface facing it: E = L * pi * sin^2(theta_max).
        double sinMax = std::sin(std::min(halfAngle, std::numbers::pi / 2));
        value_ /= static_cast<float>(std::numbers::pi * sinMax * sinMax);
    }
}

std::optional<LightSample> DistantLight::sample(const Vec3f&, Vec2f u) const {
    if (isDelta()) return LightSample{value_, towardsLight_, std::numeric_limits<float>::infinity(), 1.0f, true};
    double cosTheta = 1.0 - u.x * oneMinusCosMax_;
    double sinTheta = std::sqrt(std::max(0.0, (1.0 - cosTheta) * (1.0 + cosTheta)));
    double phi = 2.0 * std::numbers::pi * u.y;
    Vec3f wi = normalize(Frame::fromNormal(towardsLight_)
                             .toWorld(Vec3f(float(sinTheta * std::cos(phi)), float(sinTheta * std::sin(phi)),
                                            float(cosTheta))));
    return LightSample{value_, wi, std::numeric_limits<float>::infinity(),
                       static_cast<float>(1.0 / (2.0 * std::numbers::pi * oneMinusCosMax_)), false};
}

float DistantLight::pdf(const Vec3f&, const Vec3f& wi, const LightHit&) const {
    if (isDelta() || 1.0 - double(dot(wi, towardsLight_)) > oneMinusCosMax_) return 0.0f;
    return static_cast<float>(1.0 / (2.0 * std::numbers::pi * oneMinusCosMax_));
}

RGB DistantLight::escaped(const Vec3f& direction) const {
    if (isDelta() || 1.0 - double(dot(direction, towardsLight_)) > oneMinusCosMax_) return RGB(0.0f);
    return value_;
}

float DistantLight::power(const SceneBounds& b) const {
    float irradiance = isDelta() ? luminance(value_)
                                 : luminance(value_) * static_cast<float>(2.0 * std::numbers::pi * oneMinusCosMax_);
    return irradiance * kPi * b.radius * b.radius;
}

namespace {

// The rotation part of `m`: its X and Y axes made orthonormal, Z completing them with m's
// handedness.
Frame rotationOf(const Matrix4& m) {
    Vec3f x = normalize(Vec3f(m.transformVector({1.0, 0.0, 0.0})));
    Vec3f y = Vec3f(m.transformVector({0.0, 1.0, 0.0}));
    y = normalize(y - x * dot(x, y));
    Vec3f z = cross(x, y) * (m.determinant3x3() < 0.0 ? -1.0f : 1.0f);
    return {x, y, z};
}

}  // namespace

DomeLight::DomeLight(const LightDesc& d)
    : name_(d.name), radiance_(d.radiance), frame_(rotationOf(d.transform)), texture_(d.texture), meanRadiance_(d.radiance) {
    if (texture_ && texture_->texels.empty()) texture_.reset();
    if (!texture_) return;
    const int w = texture_->width, h = texture_->height;
    // Luminance weights (negative and non-finite texels weigh nothing), times the solid angle of
    // each row's texels.
    std::vector<float> weights = luminanceWeights(*texture_, radiance_);
    Vec3d sum(0.0);
    double sinSum = 0.0;
    for (int y = 0; y < h; ++y) {
        float sinTheta = std::sin(kPi * (y + 0.5f) / h);
        for (int x = 0; x < w; ++x) {
            float& weight = weights[std::size_t(y) * w + x];
            if (weight > 0.0f) sum += Vec3d(vmax(radiance_ * texture_->at(x, y), RGB(0.0f))) * double(sinTheta);
            weight *= sinTheta;
        }
        sinSum += double(sinTheta) * w;
    }
    distribution_ = ImageDistribution(w, h, std::move(weights));
    meanRadiance_ = RGB(sum / sinSum);
}

Vec3f DomeLight::direction(Vec2f uv) const {
    float phi = kPi * (1.0f - 2.0f * uv.x), theta = kPi * uv.y;
    float sinTheta = std::sin(theta);
    return normalize(frame_.toWorld(Vec3f(sinTheta * std::sin(phi), std::cos(theta), sinTheta * std::cos(phi))));
}

Vec2f DomeLight::imageCoordinates(const Vec3f& direction) const {
    Vec3f d = frame_.toLocal(direction);
    float phi = std::atan2(d.x, d.z), theta = std::acos(std::clamp(d.y, -1.0f, 1.0f));
    return {(kPi - phi) / (2.0f * kPi), theta / kPi};
}

RGB DomeLight::radianceAt(Vec2f uv) const {
    int x = std::clamp(static_cast<int>(uv.x * texture_->width), 0, texture_->width - 1);
    int y = std::clamp(static_cast<int>(uv.y * texture_->height), 0, texture_->height - 1);
    return radiance_ * texture_->at(x, y);
}

std::optional<LightSample> DomeLight::sample(const Vec3f&, Vec2f u) const {
    constexpr float kInfinity = std::numeric_limits<float>::infinity();
    if (!texture_) return LightSample{radiance_, sampleUniformSphere(u), kInfinity, kUniformSpherePdf, false};
    ImageDistribution::Sample s = distribution_.sample(u);
    float sinTheta = std::sin(kPi * s.uv.y);
    if (!(sinTheta > 0.0f) || s.pdf == 0.0f) return std::nullopt;
    return LightSample{radianceAt(s.uv), direction(s.uv), kInfinity, s.pdf / (2.0f * kPi * kPi * sinTheta), false};
}

float DomeLight::pdf(const Vec3f&, const Vec3f& wi, const LightHit&) const {
    if (!texture_) return kUniformSpherePdf;
    float y = dot(frame_.t, wi);
    float sinTheta = std::sqrt(std::max(0.0f, 1.0f - y * y));
    return sinTheta > 0.0f ? distribution_.pdf(imageCoordinates(wi)) / (2.0f * kPi * kPi * sinTheta) : 0.0f;
}

RGB DomeLight::escaped(const Vec3f& direction) const { return texture_ ? radianceAt(imageCoordinates(direction)) : radiance_; }

float DomeLight::power(const SceneBounds& b) const {
    return luminance(meanRadiance_) * 4.0f * kPi * kPi * b.radius * b.radius;
}

}  // namespace fluence::render
