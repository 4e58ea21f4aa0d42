#include "delegate/camera_adapter.h"

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
        if (!range->isNumeric() || range->numbers.size() != 2) prim.fail("clippingRange must be a float2, got " + range->toString());
        c.nearClip = static_cast<float>(range->numbers[0]);
        c.farClip = static_cast<float>(range->numbers[1]);
    }
    if (!(c.focalLength > 0.0f)) prim.fail("focalLength must be positive");
    if (!(c.horizontalAperture > 0.0f) || !(c.verticalAperture > 0.0f)) prim.fail("apertures must be positive");
    if (!(c.nearClip >= 0.0f) || !(c.farClip > c.nearClip)) prim.fail("clippingRange must satisfy 0 <= near < far");
    return c;
}

}  // namespace fluence::delegate
