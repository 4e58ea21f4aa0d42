#include "render/lights/rect_light.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "render/lights/surface_sampling.h"

namespace fluence::render {

RectLight::RectLight(const LightDesc& d) : Light(d.name), radiance_(d.radiance), texture_(d.texture) {
    const Matrix4& t = d.transform;
    corner_ = Vec3f(t.transformPoint({-0.5 * d.width, -0.5 * d.height, 0.0}));
    edgeU_ = Vec3f(t.transformVector({double(d.width), 0.0, 0.0}));
    edgeV_ = Vec3f(t.transformVector({0.0, double(d.height), 0.0}));
    normal_ = normalize(Vec3f(t.transformNormal({0.0, 0.0, -1.0})));
    area_ = length(cross(edgeU_, edgeV_));
    inverseArea_ = 1.0f / area_;
    if (d.normalize && area_ > 0.0f) radiance_ /= area_;
    if (texture_ && texture_->texels.empty()) texture_.reset();
    meanLuminance_ = luminance(radiance_);
    if (texture_) {
        // The sampling weights, whose mean is the power's too (so a texel the sampler never picks,
        // a non-finite one, adds no infinite power).
        std::vector<float> weights = luminanceWeights(*texture_, radiance_);
        meanLuminance_ = static_cast<float>(std::accumulate(weights.begin(), weights.end(), 0.0) / weights.size());
        if (std::any_of(weights.begin(), weights.end(), [&](float w) { return w != weights[0]; }))
            distribution_.emplace(texture_->width, texture_->height, std::move(weights));
    }
    if (d.shaping) shaping_ = LightShaping(*d.shaping, normal_, d.transform);
    uniformRadiance_ = !texture_ && !shaping_.active();
}

std::array<Vec3f, 4> RectLight::corners() const {
    return {corner_, corner_ + edgeU_, corner_ + edgeU_ + edgeV_, corner_ + edgeV_};
}

Vec2f RectLight::textureCoordinates(const Vec3f& point) const {
    // Solve point - corner = a edgeU + b edgeV (the edges need not be orthogonal under a shear).
    Vec3f q = point - corner_;
    float uu = dot(edgeU_, edgeU_), uv = dot(edgeU_, edgeV_), vv = dot(edgeV_, edgeV_);
    float qu = dot(q, edgeU_), qv = dot(q, edgeV_), det = uu * vv - uv * uv;
    float a = (qu * vv - qv * uv) / det, b = (qv * uu - qu * uv) / det;
    // The texture's top-left corner, uv = (0, 0), sits at local (+X, +Y): a = 1, b = 1.
    return {1.0f - a, 1.0f - b};
}

RGB RectLight::radianceAt(Vec2f uv, const Vec3f& wo) const {
    RGB radiance = radiance_ * shaping_.factor(wo);
    if (!texture_) return radiance;
    int x = std::clamp(static_cast<int>(uv.x * texture_->width), 0, texture_->width - 1);
    int y = std::clamp(static_cast<int>(uv.y * texture_->height), 0, texture_->height - 1);
    return radiance * texture_->at(x, y);
}

RectLight::PointSample RectLight::samplePoint(Vec2f u) const {
    // The point's texture coordinates: by the texture's luminance, or uniform (u measured from
    // the corner at local (-X, -Y), the texture's bottom-right) without a texture or when its
    // luminance is the same everywhere (black included).
    if (!distribution_) return {{1.0f - u.x, 1.0f - u.y}, inverseArea_};
    ImageDistribution::Sample s = distribution_->sample(u);
    return {s.uv, s.pdf / area_};
}

std::optional<LightSample> RectLight::sample(const Vec3f& p, Vec2f u) const {
    if (area_ == 0.0f) return std::nullopt;
    const auto [uv, areaPdf] = samplePoint(u);
    Vec3f d = pointAt(uv) - p;
    float dist2 = lengthSquared(d);
    if (dist2 == 0.0f) return std::nullopt;
    float dist = std::sqrt(dist2);
    Vec3f wi = d / dist;
    float cosLight = -dot(normal_, wi);
    if (cosLight <= 0.0f) return std::nullopt;
    return surfaceSample(uniformRadiance_ ? radiance_ : radianceAt(uv, -wi), wi, dist,
                         areaToSolidAngle(areaPdf, dist2, cosLight));
}

float RectLight::pdf(const Vec3f& p, const Vec3f& wi, const LightHit& hit) const {
    if (area_ == 0.0f) return 0.0f;
    float areaPdf = distribution_ ? distribution_->pdf(textureCoordinates(hit.point)) / area_ : inverseArea_;
    return areaToSolidAngle(areaPdf, lengthSquared(hit.point - p), -dot(normal_, wi));
}

RGB RectLight::emitted(const LightHit& hit, const Vec3f& wo) const {
    return dot(normal_, wo) > 0.0f ? radianceAt(textureCoordinates(hit.point), wo) : RGB(0.0f);
}

float RectLight::unshapedPower() const { return meanLuminance_ * area_ * kPi; }

float RectLight::power(const SceneBounds&) const { return unshapedPower() * shaping_.powerFraction(true); }

std::optional<LightBounds> RectLight::bounds() const {
    LightBounds b;
    b.lo = b.hi = corner_;
    for (const Vec3f& c : corners()) {
        b.lo = vmin(b.lo, c);
        b.hi = vmax(b.hi, c);
    }
    b.phi = unshapedPower();
    b.axis = normal_;
    b.cosThetaO = 1.0f;
    return shaping_.narrow(b, true);
}

LightSurface RectLight::surface() const { return LightSurface::quad(corners(), normal_); }

std::optional<EmissionSample> RectLight::sampleEmission(Vec2f uPosition, Vec2f uDirection, const SceneBounds&) const {
    if (area_ == 0.0f) return std::nullopt;
    const auto [uv, areaPdf] = samplePoint(uPosition);
    EmissionSample e = fromSurface(pointAt(uv), normal_, areaPdf, uDirection);
    e.Le = radianceAt(uv, e.direction);
    return e;
}

EmissionDensity RectLight::emissionDensity(const Vec3f& point, const Vec3f& direction, const SceneBounds&) const {
    if (area_ == 0.0f) return {};
    float areaPdf = (distribution_ ? distribution_->pdf(textureCoordinates(point)) : 1.0f) / area_;
    return surfaceDensity(normal_, areaPdf, direction);
}

}  // namespace fluence::render
