#include "render/curve_geometry.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>

#include "core/frame.h"
#include "render/curve_primvars.h"
#include "render/hair_material.h"
#include "render/motion_geometry.h"
#include "render/render_scene.h"

namespace fluence::render {

namespace {

RTCGeometryType embreeType(CurveBasis basis, CurveStyle style) {
    const bool round = style == CurveStyle::Round, flat = style == CurveStyle::Flat;
    switch (basis) {
        case CurveBasis::Linear:
            return round ? RTC_GEOMETRY_TYPE_ROUND_LINEAR_CURVE : RTC_GEOMETRY_TYPE_FLAT_LINEAR_CURVE;
        case CurveBasis::Bezier:
            return round  ? RTC_GEOMETRY_TYPE_ROUND_BEZIER_CURVE
                   : flat ? RTC_GEOMETRY_TYPE_FLAT_BEZIER_CURVE
                          : RTC_GEOMETRY_TYPE_NORMAL_ORIENTED_BEZIER_CURVE;
        case CurveBasis::BSpline:
            return round  ? RTC_GEOMETRY_TYPE_ROUND_BSPLINE_CURVE
                   : flat ? RTC_GEOMETRY_TYPE_FLAT_BSPLINE_CURVE
                          : RTC_GEOMETRY_TYPE_NORMAL_ORIENTED_BSPLINE_CURVE;
        case CurveBasis::CatmullRom:
            return round  ? RTC_GEOMETRY_TYPE_ROUND_CATMULL_ROM_CURVE
                   : flat ? RTC_GEOMETRY_TYPE_FLAT_CATMULL_ROM_CURVE
                          : RTC_GEOMETRY_TYPE_NORMAL_ORIENTED_CATMULL_ROM_CURVE;
    }
    return RTC_GEOMETRY_TYPE_ROUND_LINEAR_CURVE;
}

int controlPointsPerSegment(CurveBasis basis) { return basis == CurveBasis::Linear ? 2 : 4; }

// `values` of linear segments (`k` per control point) at the four control points of the same
// segments as Bezier curves: at thirds of the way along each.
template <typename T>
std::vector<T> atThirds(const std::vector<T>& values, const std::vector<std::uint32_t>& segments, std::size_t k = 1) {
    std::vector<T> out;
    if (values.empty()) return out;
    for (std::uint32_t s : segments)
        for (int j = 0; j < 4; ++j) {
            const float w = j / 3.0f;
            for (std::size_t c = 0; c < k; ++c)
                out.push_back(values[s * k + c] * (1.0f - w) + values[(s + 1) * k + c] * w);
        }
    return out;
}

// Linear segments as Bezier segments with their control points at thirds (Embree has no
// normal-oriented linear curve): the same straight pieces, with radii and normals varying linearly.
CurvesDesc asBezier(const CurvesDesc& linear) {
    CurvesDesc out = linear;
    out.basis = CurveBasis::Bezier;
    out.points = atThirds(linear.points, linear.segments);
    out.radii = atThirds(linear.radii, linear.segments);
    out.normals = atThirds(linear.normals, linear.segments);
    out.colors = atThirds(linear.colors, linear.segments);
    for (CurvePrimvar& pv : out.primvars)
        if (!pv.perSegment) pv.values = atThirds(pv.values, linear.segments, static_cast<std::size_t>(pv.components));
    for (std::size_t step = 0; step < linear.motionPoints.size(); ++step)
        out.motionPoints[step] = atThirds(linear.motionPoints[step], linear.segments);
    for (std::size_t step = 0; step < linear.motionRadii.size(); ++step)
        out.motionRadii[step] = atThirds(linear.motionRadii[step], linear.segments);
    out.segments.clear();
    for (std::size_t s = 0; s < linear.segments.size(); ++s) out.segments.push_back(static_cast<std::uint32_t>(4 * s));
    return out;
}

void validate(const CurvesDesc& desc, std::size_t materials) {
    const std::size_t n = desc.points.size();
    if (desc.radii.size() != n) throw std::invalid_argument(desc.name + ": expected one radius per control point");
    if (desc.style == CurveStyle::Oriented && desc.normals.size() != n)
        throw std::invalid_argument(desc.name + ": an oriented ribbon needs one normal per control point");
    if (!desc.colors.empty() && desc.colors.size() != n)
        throw std::invalid_argument(desc.name + ": expected one colour per control point");
    const std::size_t last = static_cast<std::size_t>(controlPointsPerSegment(desc.basis)) - 1;
    for (std::uint32_t s : desc.segments)
        if (s + last >= n) throw std::invalid_argument(desc.name + ": a segment reads control points past the last");
    validateCurvePrimvars(desc, n, desc.segments.size());
    if (desc.material >= static_cast<int>(materials))
        throw std::invalid_argument(desc.name + ": material index out of range");
    checkMotionPositions(desc.name, desc.motionPoints, n);
    checkMotionRadii(desc.name, desc.motionRadii, desc.motionPoints, n);
}

// Embree filter function of round tubes: drops a hit where the ray leaves the tube (see the header).
void seenFromOutside(const RTCFilterFunctionNArguments* args) {
    if (args->N != 1 || !args->valid[0]) return;  // the scenes are only traced one ray at a time
    const float leaving = RTCRayN_dir_x(args->ray, 1, 0) * RTCHitN_Ng_x(args->hit, 1, 0) +
                          RTCRayN_dir_y(args->ray, 1, 0) * RTCHitN_Ng_y(args->hit, 1, 0) +
                          RTCRayN_dir_z(args->ray, 1, 0) * RTCHitN_Ng_z(args->hit, 1, 0);
    if (leaving > 0.0f) args->valid[0] = 0;
}

template <typename T>
T* newBuffer(RTCGeometry geom, RTCBufferType type, unsigned slot, RTCFormat format, std::size_t components,
             std::size_t count) {
    return static_cast<T*>(rtcSetNewGeometryBuffer(geom, type, slot, format, components * sizeof(T), count));
}

}  // namespace

struct CurveGeometry::Curves {
    RTCGeometry geometry = nullptr;  // retained, for rtcInterpolate
    std::size_t steps = 1;           // time steps of its vertex buffers (CurvesDesc::motionPoints)
    CurveStyle style = CurveStyle::Round;
    bool colored = false;                   // displayColor as vertex attribute 0
    std::unique_ptr<CurveShading> shading;  // the material's primvars, when it reads any
    MaterialParams material;
    Vec3f boundsLo{std::numeric_limits<float>::max()}, boundsHi{-std::numeric_limits<float>::max()};
    std::uint32_t objectName = kNoName, materialName = kNoName;
    int linkGroup = 0;  // CurvesDesc::linkGroup
};

CurveGeometry::CurveGeometry() = default;

CurveGeometry::~CurveGeometry() {
    for (Curves& c : curves_) rtcReleaseGeometry(c.geometry);
}

void CurveGeometry::add(RTCDeviceTy* device, RTCSceneTy* scene, unsigned geomID, const CurvesDesc& original,
                        const std::vector<MaterialDesc>& materials, const std::vector<MaterialShader>& shaders,
                        std::uint32_t objectName, std::uint32_t materialName) {
    validate(original, materials.size());
    const CurvesDesc desc =
        original.basis == CurveBasis::Linear && original.style == CurveStyle::Oriented ? asBezier(original) : original;
    const std::size_t n = desc.points.size();
    RTCGeometry geom = rtcNewGeometry(device, embreeType(desc.basis, desc.style));
    setPointRadiusBuffers(geom, desc.points, desc.radii, desc.motionPoints, desc.motionRadii,
                          desc.style == CurveStyle::Oriented ? desc.normals : std::vector<Vec3f>{});
    Curves curves;
    curves.steps = std::max<std::size_t>(desc.motionPoints.size(), 1);
    for (std::size_t step = 0; step < curves.steps; ++step)
        for (std::size_t i = 0; i < n; ++i) {
            const Vec3f& p = desc.motionPoints.empty() ? desc.points[i] : desc.motionPoints[step][i];
            const float r = std::max(desc.motionRadii.empty() ? desc.radii[i] : desc.motionRadii[step][i], 0.0f);
            curves.boundsLo = vmin(curves.boundsLo, p - Vec3f(r));
            curves.boundsHi = vmax(curves.boundsHi, p + Vec3f(r));
        }
    unsigned* index = newBuffer<unsigned>(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT, 1, desc.segments.size());
    std::copy(desc.segments.begin(), desc.segments.end(), index);
    curves.colored = !desc.colors.empty() && desc.material < 0;
    if (desc.material >= 0 && shaders[static_cast<std::size_t>(desc.material)].hasBindings())
        curves.shading = std::make_unique<CurveShading>(desc, shaders[static_cast<std::size_t>(desc.material)],
                                                        curves.colored ? 1u : 0u);
    const unsigned attributes = (curves.colored ? 1u : 0u) + (curves.shading ? curves.shading->attributeCount() : 0u);
    if (attributes > 0) rtcSetGeometryVertexAttributeCount(geom, attributes);
    if (curves.shading) curves.shading->setAttributes(geom);
    if (curves.colored) {
        float* colors = newBuffer<float>(geom, RTC_BUFFER_TYPE_VERTEX_ATTRIBUTE, 0, RTC_FORMAT_FLOAT3, 3, n);
        for (std::size_t i = 0; i < n; ++i)
            for (int k = 0; k < 3; ++k) colors[3 * i + k] = desc.colors[i][k];
    }
    if (desc.style == CurveStyle::Round) {
        rtcSetGeometryIntersectFilterFunction(geom, seenFromOutside);
        rtcSetGeometryOccludedFilterFunction(geom, seenFromOutside);
    }
    rtcCommitGeometry(geom);
    rtcAttachGeometryByID(scene, geom, geomID);
    curves.geometry = geom;  // the scene holds its own reference; this one is released with us
    curves.style = desc.style;
    curves.material = desc.material >= 0
                          ? static_cast<const MaterialParams&>(materials[static_cast<std::size_t>(desc.material)])
                          : MaterialParams{};
    curves.objectName = objectName;
    curves.materialName = materialName;
    curves.linkGroup = desc.linkGroup;
    if (byGeomID_.size() <= geomID) byGeomID_.resize(geomID + 1, -1);
    byGeomID_[geomID] = static_cast<int>(curves_.size());
    curves_.push_back(std::move(curves));
    segments_ += desc.segments.size();
}

bool CurveGeometry::contains(unsigned geomID) const { return geomID < byGeomID_.size() && byGeomID_[geomID] >= 0; }

void CurveGeometry::growBounds(Vec3f& lo, Vec3f& hi) const {
    for (const Curves& c : curves_) {
        lo = vmin(lo, c.boundsLo);
        hi = vmax(hi, c.boundsHi);
    }
}

void CurveGeometry::interpolate(const Curves& curves, unsigned primID, float u, float time, float centre[4],
                                float derivative[4]) {
    RTCInterpolateArguments args{};
    args.geometry = curves.geometry;
    args.primID = primID;
    args.u = u;
    args.bufferType = RTC_BUFFER_TYPE_VERTEX;
    args.P = centre;
    args.dPdu = derivative;
    args.valueCount = 4;
    if (curves.steps < 2) {
        rtcInterpolate(&args);
        return;
    }
    // Embree moves the control points linearly between time steps; the curve is linear in them.
    const MotionSegment segment = motionSegment(curves.steps, time);
    float nextCentre[4], nextDerivative[4];
    args.bufferSlot = static_cast<unsigned>(segment.step);
    rtcInterpolate(&args);
    args.bufferSlot += 1;
    args.P = nextCentre;
    args.dPdu = nextDerivative;
    rtcInterpolate(&args);
    const float f = segment.fraction;
    for (int k = 0; k < 4; ++k) {
        centre[k] = centre[k] * (1.0f - f) + nextCentre[k] * f;
        derivative[k] = derivative[k] * (1.0f - f) + nextDerivative[k] * f;
    }
}

Vec3f CurveGeometry::centreAt(unsigned geomID, unsigned primID, float u, float time) const {
    float centre[4], derivative[4];
    interpolate(curves_[static_cast<std::size_t>(byGeomID_[geomID])], primID, u, time, centre, derivative);
    return Vec3f(centre[0], centre[1], centre[2]);
}

std::optional<SurfaceHit> CurveGeometry::shade(unsigned geomID, unsigned primID, float u, const Ray& ray, float t,
                                               const Vec3f& ng) const {
    const Curves& curves = curves_[static_cast<std::size_t>(byGeomID_[geomID])];
    float centre[4], derivative[4];
    interpolate(curves, primID, u, ray.time, centre, derivative);

    std::optional<SurfaceHit> result(std::in_place, curves.material);
    SurfaceHit& hit = *result;
    hit.t = t;
    hit.time = ray.time;
    hit.point = ray.origin + ray.direction * t;
    hit.curveGeometry = static_cast<int>(geomID);
    hit.triangle = primID;
    hit.b1 = u;
    const Vec3f wo = -ray.direction;
    Vec3f tangent(derivative[0], derivative[1], derivative[2]);
    tangent = lengthSquared(tangent) > 0.0f ? normalize(tangent) : Frame::fromNormal(wo).s;
    // The ribbon's normal: facing the ray, or the oriented ribbon's own; perpendicular to the tangent.
    const Vec3f facing = curves.style == CurveStyle::Oriented && lengthSquared(ng) > 0.0f ? ng : wo;
    Vec3f normal = facing - tangent * dot(facing, tangent);
    normal = lengthSquared(normal) > 0.0f ? normalize(normal) : Frame::fromNormal(tangent).s;
    if (dot(normal, wo) < 0.0f) normal = -normal;
    hit.geometricNormal = hit.shadingNormal = normal;
    hit.tangent = tangent;

    if (curves.shading) curves.shading->evaluate(curves.geometry, primID, u, hit.material);
    RGB colour = hit.material.diffuse;
    if (curves.colored) {
        float c[3];
        RTCInterpolateArguments args{};
        args.geometry = curves.geometry;
        args.primID = primID;
        args.u = u;
        args.bufferType = RTC_BUFFER_TYPE_VERTEX_ATTRIBUTE;
        args.bufferSlot = 0;
        args.P = c;
        args.valueCount = 3;
        rtcInterpolate(&args);
        colour = RGB(c[0], c[1], c[2]);
    }
    HairParams hair = hairFromMaterial(hit.material, colour);
    const float radius = centre[3];
    const Vec3f across = cross(normal, tangent);
    hair.offset = radius > 0.0f ? std::clamp(dot(hit.point - Vec3f(centre[0], centre[1], centre[2]), across) / radius,
                                             -1.0f, 1.0f)
                                : 0.0f;
    hit.material.hair = hair;
    hit.material.diffuse = colour;
    hit.objectName = curves.objectName;
    hit.materialName = curves.materialName;
    hit.linkGroup = curves.linkGroup;
    return result;
}

}  // namespace fluence::render
