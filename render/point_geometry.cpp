#include "render/point_geometry.h"

#include <embree3/rtcore.h>

#include <stdexcept>

#include "render/motion_geometry.h"
#include "render/render_scene.h"

namespace fluence::render {

void validatePoints(const PointsDesc& p) {
    const std::size_t n = p.positions.size();
    if (p.radii.size() != n) throw std::invalid_argument(p.name + ": expected one radius per point");
    if (p.style == PointStyle::OrientedDisc && p.normals.size() != n)
        throw std::invalid_argument(p.name + ": oriented discs need one normal per point");
    if (!p.colors.empty() && p.colors.size() != n)
        throw std::invalid_argument(p.name + ": expected one colour per point");
    for (const PointPrimvar& v : p.primvars)
        if (v.components < 1 || v.components > 4 || v.values.size() != n * std::size_t(v.components))
            throw std::invalid_argument(p.name + ": primvar " + v.name + " needs 1 to 4 values per point");
    checkMotionPositions(p.name, p.motionPositions, n);
    checkMotionRadii(p.name, p.motionRadii, p.motionPositions, n);
}

RTCGeometry pointGeometry(RTCDevice device, const PointsDesc& p) {
    const RTCGeometryType type = p.style == PointStyle::Sphere ? RTC_GEOMETRY_TYPE_SPHERE_POINT
                                 : p.style == PointStyle::Disc ? RTC_GEOMETRY_TYPE_DISC_POINT
                                                               : RTC_GEOMETRY_TYPE_ORIENTED_DISC_POINT;
    RTCGeometry geom = rtcNewGeometry(device, type);
    setPointRadiusBuffers(geom, p.positions, p.radii, p.motionPositions, p.motionRadii,
                          p.style == PointStyle::OrientedDisc ? p.normals : std::vector<Vec3f>{});
    rtcCommitGeometry(geom);
    return geom;
}

MeshDesc pointShadingMesh(const PointsDesc& p) {
    MeshDesc m;
    m.name = p.name;
    m.positions = p.positions;
    m.motionPositions = p.motionPositions;
    m.material = p.material;
    m.linkGroup = p.linkGroup;
    const std::size_t n = p.positions.size();
    m.indices.reserve(3 * n);
    for (std::size_t i = 0; i < n; ++i) m.indices.insert(m.indices.end(), 3, static_cast<std::uint32_t>(i));
    for (const RGB& c : p.colors) m.cornerColors.insert(m.cornerColors.end(), 3, c);
    for (const PointPrimvar& v : p.primvars) {
        CornerPrimvar& corners = m.primvars.emplace_back(CornerPrimvar{v.name, v.components, {}});
        const std::size_t k = std::size_t(v.components);
        corners.values.reserve(3 * v.values.size());
        for (std::size_t i = 0; i < n; ++i)
            for (int corner = 0; corner < 3; ++corner)
                corners.values.insert(corners.values.end(), v.values.begin() + std::ptrdiff_t(i * k),
                                      v.values.begin() + std::ptrdiff_t((i + 1) * k));
    }
    return m;
}

void placeOnPoint(SurfaceHit& hit, const Ray& ray, float t, const Vec3f& ng) {
    hit.point = ray.origin + ray.direction * t;
    hit.geometricNormal = lengthSquared(ng) > 0.0f ? normalize(ng) : -ray.direction;
    hit.shadingNormal = hit.geometricNormal;
    hit.tangent = Vec3f(0.0f);
}

}  // namespace fluence::render
