#include "delegate/light_adapter.h"

#include <cmath>

namespace fluence::delegate {

bool isLightType(const std::string& t) {
    return t == "RectLight" || t == "SphereLight" || t == "DistantLight" || t == "DomeLight";
}

std::optional<render::LightDesc> lightFromPrim(const PrimReader& prim, const Matrix4& toWorld,
                                               const std::function<void(const std::string&)>& warn) {
    const std::string& type = prim.prim().typeName;
    render::LightDesc light;
    light.name = prim.path();
    light.transform = toWorld;

    double intensity = prim.number({"inputs:intensity", "intensity"}, type == "DistantLight" ? 50000.0 : 1.0);
    double exposure = prim.number({"inputs:exposure", "exposure"}, 0.0);
    Vec3d color = prim.vec3({"inputs:color", "color"}, {1.0, 1.0, 1.0});
    light.radiance = RGB(color * (intensity * std::exp2(exposure)));
    light.normalize = prim.boolean({"inputs:normalize", "normalize"}, false);
    if (prim.boolean({"inputs:enableColorTemperature", "enableColorTemperature"}, false))
        warn("colour temperature is not supported yet; ignored");

    if (type == "RectLight") {
        light.type = render::LightType::Rect;
        light.width = static_cast<float>(prim.number({"inputs:width", "width"}, 1.0));
        light.height = static_cast<float>(prim.number({"inputs:height", "height"}, 1.0));
        if (prim.value({"inputs:texture:file", "texture:file"})) warn("rect light textures are not supported yet; ignored");
    } else if (type == "SphereLight") {
        light.type = render::LightType::Sphere;
        light.radius = static_cast<float>(prim.number({"inputs:radius", "radius"}, 0.5));
        if (!(light.radius > 0.0f)) {
            warn("a sphere light of radius 0 (a point light) is not supported yet; skipped");
            return std::nullopt;
        }
        if (prim.boolean({"treatAsPoint"}, false)) warn("treatAsPoint is not supported yet; the light keeps its radius");
    } else if (type == "DistantLight") {
        light.type = render::LightType::Distant;
        light.angleDegrees = static_cast<float>(prim.number({"inputs:angle", "angle"}, 0.53));
    } else if (type == "DomeLight") {
        light.type = render::LightType::Dome;
        if (prim.value({"inputs:texture:file", "texture:file"}))
            warn("dome light textures are not supported yet; rendered with its constant colour");
    } else {
        return std::nullopt;
    }
    return light;
}

}  // namespace fluence::delegate
