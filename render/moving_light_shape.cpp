#include "render/moving_light_shape.h"

#include <embree3/rtcore.h>

#include <cmath>

#include "render/embree_ray.h"

namespace fluence::render {

namespace {

// The distance along o + t d to triangle (a, b, c), t in (tMin, tMax) (Moller-Trumbore).
std::optional<float> triangleDistance(const Vec3f& o, const Vec3f& d, const Vec3f& a, const Vec3f& b, const Vec3f& c,
                                      float tMin, float tMax) {
    const Vec3f e1 = b - a, e2 = c - a, q = cross(d, e2);
    const float det = dot(e1, q);
    if (det == 0.0f) return std::nullopt;
    const float inv = 1.0f / det;
    const Vec3f s = o - a;
    const float u = dot(s, q) * inv;
    if (u < 0.0f || u > 1.0f) return std::nullopt;
    const Vec3f r = cross(s, e1);
    const float v = dot(d, r) * inv;
    if (v < 0.0f || u + v > 1.0f) return std::nullopt;
    const float t = dot(e2, r) * inv;
    if (!(t > tMin && t < tMax)) return std::nullopt;
    return t;
}

// The distance along o + t d at which the ray enters the sphere, t in (tMin, tMax): the only
// root where it can meet the sphere's outside (the other is where it leaves).
std::optional<float> sphereEntry(const Vec3f& o, const Vec3f& d, const Vec3f& centre, float radius, float tMin,
                                 float tMax) {
    const Vec3f oc = o - centre;
    const float a = dot(d, d), b = dot(oc, d), c = dot(oc, oc) - radius * radius;
    const float discriminant = b * b - a * c;
    if (!(discriminant >= 0.0f) || a == 0.0f) return std::nullopt;
    const float t = (-b - std::sqrt(discriminant)) / a;
    if (!(t > tMin && t < tMax)) return std::nullopt;
    return t;
}

void boundsOfShape(const RTCBoundsFunctionArguments* args) {
    const auto* shape = static_cast<const MovingLightShape*>(args->geometryUserPtr);
    *args->bounds_o =
        RTCBounds{shape->lo().x, shape->lo().y, shape->lo().z, 0.0f, shape->hi().x, shape->hi().y, shape->hi().z, 0.0f};
}

void intersectShape(const RTCIntersectFunctionNArguments* args) {
    if (args->N != 1 || !args->valid[0]) return;  // the scene is only traced with rtcIntersect1
    const RTCRay& r = reinterpret_cast<const RTCRayHit*>(args->rayhit)->ray;
    const std::optional<ShapeHit> hit =
        static_cast<const MovingLightShape*>(args->geometryUserPtr)
            ->intersect({r.org_x, r.org_y, r.org_z}, {r.dir_x, r.dir_y, r.dir_z}, r.tnear, r.tfar, r.time);
    if (hit) storeUserHit(args, hit->t, hit->normal);
}

}  // namespace

MovingLightShape::MovingLightShape(const LightSurface& frame, const LightMotion& motion)
    : frame_(frame), motion_(&motion) {
    LightBounds still;
    switch (frame.kind) {
        case LightSurface::Kind::Quad:
            still.lo = vmin(vmin(frame.corners[0], frame.corners[1]), vmin(frame.corners[2], frame.corners[3]));
            still.hi = vmax(vmax(frame.corners[0], frame.corners[1]), vmax(frame.corners[2], frame.corners[3]));
            break;
        case LightSurface::Kind::Sphere:
            still.lo = frame.centre - Vec3f(frame.radius);
            still.hi = frame.centre + Vec3f(frame.radius);
            break;
        case LightSurface::Kind::Analytic: frame.shape->shapeBounds(still.lo, still.hi); break;
        case LightSurface::Kind::None: break;
    }
    const LightBounds swept = motion.sweptBounds(still);
    // Padded by far more than the rounding of a hit on the surface.
    const Vec3f pad(1e-4f * (maxComponent(swept.hi - swept.lo) + maxComponent(vmax(swept.hi, -swept.lo))) + 1e-20f);
    lo_ = swept.lo - pad;
    hi_ = swept.hi + pad;
}

std::optional<ShapeHit> MovingLightShape::intersectFrame(const Vec3f& o, const Vec3f& d, float tMin, float tMax) const {
    switch (frame_.kind) {
        case LightSurface::Kind::Quad: {
            if (!meetsFront(d, frame_.front)) return std::nullopt;
            const auto& c = frame_.corners;
            std::optional<float> t = triangleDistance(o, d, c[0], c[1], c[2], tMin, tMax);
            if (!t) t = triangleDistance(o, d, c[0], c[2], c[3], tMin, tMax);
            if (!t) return std::nullopt;
            return ShapeHit{*t, normalize(frame_.front)};
        }
        case LightSurface::Kind::Sphere: {
            // It emits outwards only: a ray from inside passes through it, as through a still
            // sphere light (render_scene.cpp's filter; render/light_shape.h, THE BACK OF A LIGHT).
            const std::optional<float> t = sphereEntry(o, d, frame_.centre, frame_.radius, tMin, tMax);
            if (!t) return std::nullopt;
            const Vec3f outwards = normalize(o + d * *t - frame_.centre);
            if (!meetsFront(d, outwards)) return std::nullopt;
            return ShapeHit{*t, outwards};
        }
        case LightSurface::Kind::Analytic: return frame_.shape->intersect(o, d, tMin, tMax);
        case LightSurface::Kind::None: break;
    }
    return std::nullopt;
}

std::optional<ShapeHit> MovingLightShape::intersect(const Vec3f& o, const Vec3f& d, float tMin, float tMax,
                                                    float time) const {
    const RigidMotion motion = motion_->at(time);
    // A rigid motion keeps lengths, so t along the mapped ray is t along the world ray.
    std::optional<ShapeHit> hit = intersectFrame(motion.pointBack(o), motion.vectorBack(d), tMin, tMax);
    if (hit) hit->normal = normalize(motion.vector(hit->normal));
    return hit;
}

RTCGeometryTy* MovingLightShape::newGeometry(RTCDeviceTy* device) const {
    RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(geom, 1);
    rtcSetGeometryUserData(geom, const_cast<MovingLightShape*>(this));
    rtcSetGeometryBoundsFunction(geom, boundsOfShape, nullptr);
    rtcSetGeometryIntersectFunction(geom, intersectShape);
    rtcCommitGeometry(geom);
    return geom;
}

}  // namespace fluence::render
