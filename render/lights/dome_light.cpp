#include "render/lights/dome_light.h"

#include <algorithm>
#include <cmath>

#include "core/check.h"
#include "core/sampling.h"
#include "render/lights/emission_at_infinity.h"

namespace fluence::render {

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
    : InfiniteLight(d.name),
      radiance_(d.radiance),
      frame_(rotationOf(d.transform)),
      texture_(d.texture),
      meanRadiance_(d.radiance) {
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
    FLUENCE_DCHECK(isValidDensity(s.pdf));
    return LightSample{radianceAt(s.uv), direction(s.uv), kInfinity, s.pdf / (2.0f * kPi * kPi * sinTheta), false};
}

float DomeLight::pdf(const Vec3f&, const Vec3f& wi, const LightHit&) const {
    if (!texture_) return kUniformSpherePdf;
    float y = dot(frame_.t, wi);
    float sinTheta = std::sqrt(std::max(0.0f, 1.0f - y * y));
    return sinTheta > 0.0f ? distribution_.pdf(imageCoordinates(wi)) / (2.0f * kPi * kPi * sinTheta) : 0.0f;
}

RGB DomeLight::escaped(const Vec3f& direction) const {
    return texture_ ? radianceAt(imageCoordinates(direction)) : radiance_;
}

float DomeLight::power(const SceneBounds& b) const {
    return luminance(meanRadiance_) * 4.0f * kPi * kPi * b.radius * b.radius;
}

std::optional<EmissionSample> DomeLight::sampleEmission(Vec2f uPosition, Vec2f uDirection,
                                                        const SceneBounds& scene) const {
    std::optional<LightSample> s = sample(scene.centre, uDirection);
    if (!s) return std::nullopt;
    return fromInfinity(-s->wi, s->pdf, s->Li, uPosition, scene);
}

EmissionDensity DomeLight::emissionDensity(const Vec3f&, const Vec3f& direction, const SceneBounds& scene) const {
    return {infinityPositionDensity(scene), pdf(scene.centre, -direction, {}), 1.0f};
}

}  // namespace fluence::render
