#include "render/lights/triangle_light.h"

#include <cmath>

#include "core/check.h"
#include "render/lights/surface_sampling.h"

namespace fluence::render {

TriangleLight::TriangleLight(std::string meshName, const Vec3f& p0, const Vec3f& p1, const Vec3f& p2,
                             const RGB& radiance, EmittingSides sides)
    : Light(std::move(meshName)),
      p0_(p0),
      p1_(p1),
      p2_(p2),
      radiance_(radiance),
      frontOnly_(sides == EmittingSides::Front) {
    Vec3f n = cross(p1 - p0, p2 - p0);
    area_ = 0.5f * length(n);
    normal_ = area_ > 0.0f ? normalize(n) : Vec3f(0, 0, 1);
}

TriangleLight::TriangleLight(std::string meshName, const Vec3f& p0, const Vec3f& p1, const Vec3f& p2,
                             const TexturedEmission& emission, unsigned triangle)
    : TriangleLight(std::move(meshName), p0, p1, p2, emission.mean(triangle)) {
    textured_ = &emission;
    triangle_ = triangle;
}

void TriangleLight::shape(const LightShaping& shaping, const Matrix4& lightToWorld) {
    FLUENCE_DCHECK(frontOnly_);
    shaping_ = &shaping;
    shapingFrame_ = ShapingFrame(normal_, lightToWorld);
}

RGB TriangleLight::radianceAt(Vec2f b) const {
    return textured_ ? textured_->at(triangle_, b.y, 1.0f - b.x - b.y) : radiance_;
}

RGB TriangleLight::emitted(const LightHit& hit, const Vec3f& wo) const {
    if (!emitsTowards(wo)) return RGB(0.0f);
    if (!textured_ || area_ == 0.0f) return radiance_ * shapingFactor(wo);
    // The hit's barycentric weights of p0 and p1: sub-triangle areas over the whole.
    const Vec3f twiceArea = normal_ * (2.0f * area_);
    const float b0 = dot(cross(p1_ - hit.point, p2_ - hit.point), twiceArea) / lengthSquared(twiceArea);
    const float b1 = dot(cross(p2_ - hit.point, p0_ - hit.point), twiceArea) / lengthSquared(twiceArea);
    return radianceAt({b0, b1}) * shapingFactor(wo);
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
    if (!emitsTowards(-wi)) return std::nullopt;
    float pdf = areaToSolidAngle(1.0f / area_, dist2, std::abs(dot(normal_, wi)));
    if (pdf == 0.0f) return std::nullopt;
    return surfaceSample(radianceAt(b) * shapingFactor(-wi), wi, dist, pdf);
}

float TriangleLight::pdf(const Vec3f& p, const Vec3f& wi, const LightHit& hit) const {
    return area_ > 0.0f && emitsTowards(-wi)
               ? areaToSolidAngle(1.0f / area_, lengthSquared(hit.point - p), std::abs(dot(normal_, wi)))
               : 0.0f;
}

float TriangleLight::unshapedPower() const { return luminance(radiance_) * area_ * (frontOnly_ ? kPi : 2.0f * kPi); }

float TriangleLight::power(const SceneBounds&) const {
    return unshapedPower() * (shaping_ ? shaping_->powerFraction(true) : 1.0f);
}

std::optional<LightBounds> TriangleLight::bounds() const {
    LightBounds b;
    b.lo = vmin(p0_, vmin(p1_, p2_));
    b.hi = vmax(p0_, vmax(p1_, p2_));
    b.phi = unshapedPower();  // the shaping's narrowing scales it by its peak, as a RectLight's
    b.axis = normal_;
    b.cosThetaO = 1.0f;
    b.twoSided = !frontOnly_;
    return shaping_ ? shaping_->narrow(b, true) : b;
}

std::optional<EmissionSample> TriangleLight::sampleEmission(Vec2f uPosition, Vec2f uDirection,
                                                            const SceneBounds&) const {
    if (area_ == 0.0f) return std::nullopt;
    Vec2f b = sampleUniformTriangle(uPosition);
    // The side (the front alone, or either with probability 1/2, uDirection.x rescaled to [0, 1) again).
    const bool back = !frontOnly_ && uDirection.x < 0.5f;
    if (!frontOnly_) uDirection.x = back ? 2.0f * uDirection.x : 2.0f * uDirection.x - 1.0f;
    EmissionSample e = fromSurface(p0_ * b.x + p1_ * b.y + p2_ * (1.0f - b.x - b.y), back ? -normal_ : normal_,
                                   1.0f / area_, uDirection);
    if (!frontOnly_) e.density.direction *= 0.5f;
    e.Le = radianceAt(b) * shapingFactor(e.direction);
    return e;
}

EmissionDensity TriangleLight::emissionDensity(const Vec3f&, const Vec3f& direction, const SceneBounds&) const {
    if (area_ == 0.0f || !emitsTowards(direction)) return {};
    float cosine = std::abs(dot(normal_, direction));
    return {1.0f / area_, (frontOnly_ ? 1.0f : 0.5f) * cosineHemispherePdf(cosine), cosine};
}

}  // namespace fluence::render
