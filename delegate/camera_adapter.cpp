#include "delegate/camera_adapter.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace fluence::delegate {

render::CameraDesc cameraFromPrim(const PrimReader& prim, const Matrix4& toWorld) {
    render::CameraDesc c;
    c.name = prim.path();
    c.transform = toWorld;
    std::string projection = prim.token({"projection"}, "perspective");
    if (projection == "orthographic")
        c.projection = render::Projection::Orthographic;
    else if (projection != "perspective")
        prim.fail("unknown camera projection '" + projection + "'");
    c.focalLength = static_cast<float>(prim.number({"focalLength"}, 50.0));
    c.horizontalAperture = static_cast<float>(prim.number({"horizontalAperture"}, 20.955));
    c.verticalAperture = static_cast<float>(prim.number({"verticalAperture"}, 15.2908));
    c.horizontalApertureOffset = static_cast<float>(prim.number({"horizontalApertureOffset"}, 0.0));
    c.verticalApertureOffset = static_cast<float>(prim.number({"verticalApertureOffset"}, 0.0));
    if (auto range = prim.value("clippingRange")) {
        if (!range->isNumeric() || range->numbers.size() != 2)
            prim.fail("clippingRange must be a float2, got " + range->toString());
        c.nearClip = static_cast<float>(range->numbers[0]);
        c.farClip = static_cast<float>(range->numbers[1]);
    }
    c.fStop = static_cast<float>(prim.number({"fStop"}, 0.0));
    c.focusDistance = static_cast<float>(prim.number({"focusDistance"}, 0.0));
    const double blades = prim.number({"fluence:camera:apertureBlades"}, 0.0);
    c.apertureRotation = static_cast<float>(prim.number({"fluence:camera:apertureRotation"}, 0.0));
    if (!(c.fStop >= 0.0f) || !(c.focusDistance >= 0.0f)) prim.fail("fStop and focusDistance must not be negative");
    if (!(blades == 0.0 || (blades >= 3.0 && blades <= 64.0 && blades == std::floor(blades))))
        prim.fail("fluence:camera:apertureBlades must be 0 (round) or a whole number from 3 to 64, got " +
                  std::to_string(blades));
    if (!std::isfinite(c.apertureRotation)) prim.fail("fluence:camera:apertureRotation must be finite");
    c.apertureBlades = static_cast<int>(blades);
    c.shutterOpen = prim.number({"shutter:open"}, 0.0);
    c.shutterClose = prim.number({"shutter:close"}, 0.0);
    if (!std::isfinite(c.shutterOpen) || !std::isfinite(c.shutterClose) || c.shutterClose < c.shutterOpen)
        prim.fail("shutter:close must not be before shutter:open (time codes relative to the frame)");
    if (!(c.focalLength > 0.0f)) prim.fail("focalLength must be positive");
    if (!(c.horizontalAperture > 0.0f) || !(c.verticalAperture > 0.0f)) prim.fail("apertures must be positive");
    if (!(c.nearClip >= 0.0f) || !(c.farClip > c.nearClip)) prim.fail("clippingRange must satisfy 0 <= near < far");
    return c;
}

namespace {

struct Bounds {
    Vec3d lo{std::numeric_limits<double>::max()}, hi{-std::numeric_limits<double>::max()};
    void add(const Vec3d& p) {
        lo = Vec3d(std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z));
        hi = Vec3d(std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z));
    }
    bool empty() const { return lo.x > hi.x; }
};

}  // namespace

render::CameraDesc framingCamera(const render::SceneDescription& scene, char upAxis) {
    Bounds world;
    for (const render::MeshDesc& m : scene.meshes)
        for (const Vec3f& p : m.positions) world.add(Vec3d(p));
    for (const render::PointsDesc& points : scene.points)
        for (const Vec3f& p : points.positions) world.add(Vec3d(p));
    std::vector<Bounds> prototypes(scene.prototypes.size());
    for (std::size_t i = 0; i < scene.prototypes.size(); ++i) {
        for (const render::MeshDesc& m : scene.prototypes[i].meshes)
            for (const Vec3f& p : m.positions) prototypes[i].add(Vec3d(p));
        for (const render::CurvesDesc& c : scene.prototypes[i].curves)
            for (const Vec3f& p : c.points) prototypes[i].add(Vec3d(p));
        for (const render::PointsDesc& points : scene.prototypes[i].points)
            for (const Vec3f& p : points.positions) prototypes[i].add(Vec3d(p));
    }
    for (const render::InstanceDesc& instance : scene.instances) {
        const Bounds& b = prototypes.at(static_cast<std::size_t>(instance.prototype));
        if (b.empty()) continue;
        for (int corner = 0; corner < 8; ++corner)
            world.add(instance.transform.transformPoint(
                Vec3d(corner & 1 ? b.hi.x : b.lo.x, corner & 2 ? b.hi.y : b.lo.y, corner & 4 ? b.hi.z : b.lo.z)));
    }
    Vec3d centre(0.0), extent(1.0);
    if (!world.empty()) {
        centre = (world.lo + world.hi) * 0.5;
        extent = (world.hi - world.lo) * 0.5;
    }
    const double radius = std::max(length(extent), 1e-6);
    render::CameraDesc camera;  // UsdGeomCamera's fallback lens
    const double halfAngle =
        std::atan(0.5 * std::min(camera.horizontalAperture, camera.verticalAperture) / camera.focalLength);
    const double distance = radius / std::sin(halfAngle);
    Matrix4 orient = upAxis == 'Z' ? Matrix4::rotateX(90.0) : Matrix4::identity();  // local -Z -> +Y, +Y -> +Z
    Vec3d back = upAxis == 'Z' ? Vec3d(0.0, -1.0, 0.0) : Vec3d(0.0, 0.0, 1.0);
    camera.name = "(default camera)";
    camera.transform = Matrix4::translate(centre + back * distance) * orient;
    camera.nearClip = static_cast<float>(std::max(1e-4 * distance, 0.5 * (distance - radius)));
    camera.farClip = static_cast<float>(2.0 * (distance + radius));
    return camera;
}

}  // namespace fluence::delegate
