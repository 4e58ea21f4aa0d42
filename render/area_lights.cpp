#include "render/area_lights.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/sampling.h"

namespace fluence::render {

namespace {

// Solid-angle density of a point sampled with density `areaPdf` per unit area, seen from
// distance^2 `distanceSquared` at cosine `cosLight` to the light's normal (0 when it faces away).
float areaToSolidAngle(float areaPdf, float distanceSquared, float cosLight) {
    return cosLight > 0.0f ? areaPdf * distanceSquared / cosLight : 0.0f;
}

// A sample written straight into the returned optional's storage. Aggregate-initialising a
// LightSample and moving it into the optional made GCC build it on the stack piece by piece and
// copy it out in 16-byte loads, which the store buffer cannot forward: a stall on every sample.
std::optional<LightSample> surfaceSample(const RGB& Li, const Vec3f& wi, float distance, float pdf) {
    std::optional<LightSample> s(std::in_place);
    s->Li = Li;
    s->wi = wi;
    s->distance = distance;
    s->pdf = pdf;
    return s;
}

}  // namespace

RectLight::RectLight(const LightDesc& d) : name_(d.name), radiance_(d.radiance), texture_(d.texture) {
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
    if (d.shaping) shaping_ = LightShaping(*d.shaping, normal_);
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
    return surfaceSample(uniformRadiance_ ? radiance_ : radianceAt(uv, -wi), wi, dist, areaToSolidAngle(areaPdf, dist2, cosLight));
}

float RectLight::pdf(const Vec3f& p, const Vec3f& wi, const LightHit& hit) const {
    if (area_ == 0.0f) return 0.0f;
    float areaPdf = distribution_ ? distribution_->pdf(textureCoordinates(hit.point)) / area_ : inverseArea_;
    return areaToSolidAngle(areaPdf, lengthSquared(hit.point - p), -dot(normal_, wi));
}

RGB RectLight::emitted(const LightHit& hit, const Vec3f& wo) const {
    return dot(normal_, wo) > 0.0f ? radianceAt(textureCoordinates(hit.point), wo) : RGB(0.0f);
}

float RectLight::power(const SceneBounds&) const {
    return meanLuminance_ * area_ * kPi * shaping_.powerFraction(true);
}

std::optional<LightBounds> RectLight::bounds() const {
    LightBounds b;
    b.lo = b.hi = corner_;
    for (const Vec3f& c : corners()) {
        b.lo = vmin(b.lo, c);
        b.hi = vmax(b.hi, c);
    }
    b.phi = meanLuminance_ * area_ * kPi;
    b.axis = normal_;
    b.cosThetaO = 1.0f;
    return shaping_.narrow(b, true);
}

DiskLight::DiskLight(const LightDesc& d) : name_(d.name), radiance_(d.radiance) {
    const Matrix4& t = d.transform;
    centre_ = Vec3f(t.transformPoint({0.0, 0.0, 0.0}));
    frame_ = Frame::fromNormal(normalize(Vec3f(t.transformNormal({0.0, 0.0, -1.0}))));
    double areaScale = length(cross(t.transformVector({1.0, 0.0, 0.0}), t.transformVector({0.0, 1.0, 0.0})));
    radius_ = static_cast<float>(d.radius * std::sqrt(areaScale));
    area_ = kPi * radius_ * radius_;
    if (d.normalize && area_ > 0.0f) radiance_ /= area_;
    if (d.shaping) shaping_ = LightShaping(*d.shaping, frame_.n);
}

std::optional<LightSample> DiskLight::sample(const Vec3f& p, Vec2f u) const {
    if (area_ == 0.0f) return std::nullopt;
    Vec2f s = sampleUniformDisk(u);
    Vec3f q = centre_ + (frame_.s * s.x + frame_.t * s.y) * radius_;
    Vec3f d = q - p;
    float dist2 = lengthSquared(d);
    if (dist2 == 0.0f) return std::nullopt;
    float dist = std::sqrt(dist2);
    Vec3f wi = d / dist;
    float cosLight = -dot(frame_.n, wi);
    if (cosLight <= 0.0f) return std::nullopt;
    return surfaceSample(radiance_ * shaping_.factor(-wi), wi, dist, areaToSolidAngle(1.0f / area_, dist2, cosLight));
}

float DiskLight::pdf(const Vec3f& p, const Vec3f& wi, const LightHit& hit) const {
    return area_ > 0.0f ? areaToSolidAngle(1.0f / area_, lengthSquared(hit.point - p), -dot(frame_.n, wi)) : 0.0f;
}

RGB DiskLight::emitted(const LightHit&, const Vec3f& wo) const {
    return dot(frame_.n, wo) > 0.0f ? radiance_ * shaping_.factor(wo) : RGB(0.0f);
}

float DiskLight::power(const SceneBounds&) const {
    return luminance(radiance_) * area_ * kPi * shaping_.powerFraction(true);
}

void DiskLight::shapeBounds(Vec3f& lo, Vec3f& hi) const {
    // A disk reaches r * sqrt(1 - n_i^2) from its centre along axis i.
    const Vec3f& n = frame_.n;
    Vec3f extent = Vec3f(std::sqrt(std::max(0.0f, 1.0f - n.x * n.x)), std::sqrt(std::max(0.0f, 1.0f - n.y * n.y)),
                         std::sqrt(std::max(0.0f, 1.0f - n.z * n.z))) * radius_;
    lo = centre_ - extent;
    hi = centre_ + extent;
}

std::optional<LightBounds> DiskLight::bounds() const {
    LightBounds b;
    shapeBounds(b.lo, b.hi);
    b.phi = luminance(radiance_) * area_ * kPi;
    b.axis = frame_.n;
    b.cosThetaO = 1.0f;
    return shaping_.narrow(b, true);
}

std::optional<ShapeHit> DiskLight::intersect(const Vec3f& o, const Vec3f& d, float tMin, float tMax) const {
    float denom = dot(d, frame_.n);
    if (!(denom < 0.0f)) return std::nullopt;  // seen from behind (or edge on): rays pass through
    float t = dot(centre_ - o, frame_.n) / denom;
    if (!(t > tMin && t < tMax) || lengthSquared(o + d * t - centre_) > radius_ * radius_) return std::nullopt;
    return ShapeHit{t, frame_.n};
}

TriangleLight::TriangleLight(std::string meshName, const Vec3f& p0, const Vec3f& p1, const Vec3f& p2,
                             const RGB& radiance)
    : name_(std::move(meshName)), p0_(p0), p1_(p1), p2_(p2), radiance_(radiance) {
    Vec3f n = cross(p1 - p0, p2 - p0);
    area_ = 0.5f * length(n);
    normal_ = area_ > 0.0f ? normalize(n) : Vec3f(0, 0, 1);
}

std::optional<LightSample> TriangleLight::sample(const Vec3f& p, Vec2f u) const {
    if (area_ == 0.0f) return std::nullopt;
    Vec2f b = sampleUniformTriangle(u);
    Vec3f q = p0_ * b.x + p1_ * b.y + p2_ * (1.0f - b.x - b.y);
    Vec3f d = q - p;
    float dist2 = lengthSquared(d);
    if (dist2 == 0.0f) return std::nullopt;
    float dist = std::sqrt(dist2);
    Vec3f wi = d / dist;
    float pdf = areaToSolidAngle(1.0f / area_, dist2, std::abs(dot(normal_, wi)));
    if (pdf == 0.0f) return std::nullopt;
    return surfaceSample(radiance_, wi, dist, pdf);
}

float TriangleLight::pdf(const Vec3f& p, const Vec3f& wi, const LightHit& hit) const {
    return area_ > 0.0f ? areaToSolidAngle(1.0f / area_, lengthSquared(hit.point - p), std::abs(dot(normal_, wi)))
                        : 0.0f;
}

float TriangleLight::power(const SceneBounds&) const { return luminance(radiance_) * area_ * 2.0f * kPi; }

std::optional<LightBounds> TriangleLight::bounds() const {
    LightBounds b;
    b.lo = vmin(p0_, vmin(p1_, p2_));
    b.hi = vmax(p0_, vmax(p1_, p2_));
    b.phi = power({});
    b.axis = normal_;
    b.cosThetaO = 1.0f;
    b.twoSided = true;
    return b;
}

}  // namespace fluence::render
