#include "delegate/light_adapter.h"

#include <algorithm>
#include <cmath>

#include "core/blackbody.h"
#include "texture/ies_file.h"
#include "texture/image_loader.h"

namespace fluence::delegate {

bool appliesSchema(const usd::PrimSpec& prim, const std::string& schema) {
    const usd::MetadataEntry* e = usd::findMetadata(prim.metadata, "apiSchemas");
    return e && e->op != usd::ListOpKind::Delete &&
           std::find(e->value.strings.begin(), e->value.strings.end(), schema) != e->value.strings.end();
}

namespace {

using Warn = std::function<void(const std::string&)>;

// The IES profile inputs:shaping:ies:file names, read into `shaping`; a file that cannot be read
// (missing, or not LM-63 as texture/ies_file.h reads it) warns, naming it, and is left out.
void readIesProfile(const PrimReader& prim, render::LightShapingDesc& shaping, const Warn& warn) {
    std::string file = prim.token({"inputs:shaping:ies:file", "shaping:ies:file"}, "");
    if (file.empty()) return;
    try {
        shaping.ies = std::make_shared<const texture::IesTable>(texture::readIesFile(file));
    } catch (const texture::IesFileError& e) {
        warn(std::string(e.what()) + "; the light is rendered without its IES profile");
        return;
    }
    shaping.iesAngleScale =
        static_cast<float>(prim.number({"inputs:shaping:ies:angleScale", "shaping:ies:angleScale"}, 0.0));
    shaping.iesNormalize = prim.boolean({"inputs:shaping:ies:normalize", "shaping:ies:normalize"}, false);
}

}  // namespace

render::LightShapingDesc shapingOf(const PrimReader& prim, const Warn& warn) {
    render::LightShapingDesc s;
    readIesProfile(prim, s, warn);
    s.coneAngleDegrees = static_cast<float>(prim.number({"inputs:shaping:cone:angle", "shaping:cone:angle"}, 90.0));
    s.coneSoftness = static_cast<float>(prim.number({"inputs:shaping:cone:softness", "shaping:cone:softness"}, 0.0));
    s.focus = static_cast<float>(prim.number({"inputs:shaping:focus", "shaping:focus"}, 0.0));
    s.focusTint = RGB(prim.vec3({"inputs:shaping:focusTint", "shaping:focusTint"}, {0.0, 0.0, 0.0}));
    return s;
}

namespace {

// UsdLux's colour temperature tint (OpenUSD PR 3182): the blackbody colour divided by that of
// 6500 K, so the default temperature is exactly white, then scaled to luminance 1.
RGB colorTemperatureTint(double kelvin) {
    RGB ratio = blackbodyRgb(kelvin) / blackbodyRgb(6500.0);
    return ratio / luminance(ratio);
}

// inputs:diffuse and inputs:specular scale a light's diffuse and specular reflection separately;
// Fluence lights every lobe alike, so a value other than 1 warns and is not applied.
void warnUnsupportedMultipliers(const PrimReader& prim, const Warn& warn) {
    for (const char* name : {"diffuse", "specular"}) {
        std::string input = std::string("inputs:") + name;
        double value = prim.number({input.c_str(), name}, 1.0);
        if (value != 1.0)
            warn(input + " = " + std::to_string(value) +
                 " is not supported (every reflection is lit alike); 1 is used");
    }
}

// A light input connected to a shader output (an Arnold or RenderMan light shader, say): Fluence
// evaluates no shading network on lights, so, as Storm and usdview do, the input's own value is
// used (its authored value, else the UsdLux fallback), with one warning naming the source.
void warnConnectedInputs(const usd::PrimSpec& prim, const Warn& warn) {
    for (const usd::AttributeSpec& a : prim.attributes)
        if (a.name.starts_with("inputs:") && !a.connections.empty())
            warn(a.name + " is connected to <" + a.connections.front() +
                 ">, a light shader Fluence does not evaluate; the input's own value is used");
}

// The image at `path` as rendering-space RGB, or null (with a warning) when it cannot be read.
std::shared_ptr<const render::RgbImage> loadTexture(const std::string& path, const std::string& fallback,
                                                    const Warn& warn) {
    texture::Image image;
    try {
        image = texture::loadImage(path);
    } catch (const texture::ImageLoadError& e) {
        warn(std::string(e.what()) + "; " + fallback);
        return nullptr;
    }
    auto rgb = std::make_shared<render::RgbImage>();
    rgb->width = image.width;
    rgb->height = image.height;
    rgb->texels.resize(std::size_t(image.width) * image.height);
    bool grey = image.channels < 3;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            rgb->texels[std::size_t(y) * image.width + x] =
                grey ? RGB(image.at(x, y, 0)) : RGB(image.at(x, y, 0), image.at(x, y, 1), image.at(x, y, 2));
    return rgb;
}

// The dome's lat-long texture, or null (after a warning) when it has none that can be used.
std::shared_ptr<const render::RgbImage> domeTexture(const PrimReader& prim, const Warn& warn) {
    std::string file = prim.token({"inputs:texture:file", "texture:file"}, "");
    if (file.empty()) return nullptr;
    std::string format = prim.token({"inputs:texture:format", "texture:format"}, "automatic");
    if (format != "automatic" && format != "latlong") {
        warn("texture:format '" + format + "' is not supported (only latlong); rendered with its constant colour");
        return nullptr;
    }
    auto texture = loadTexture(file, "rendered with its constant colour", warn);
    if (texture && format == "automatic" && texture->width != 2 * texture->height)
        warn("texture '" + file + "' is " + std::to_string(texture->width) + "x" + std::to_string(texture->height) +
             ", not 2:1; read as a lat-long map");
    return texture;
}

// DomeLight_1's pole axis, as a rotation of the dome applied before its transform.
Matrix4 poleRotation(const PrimReader& prim, char stageUpAxis, const Warn& warn) {
    std::string pole = prim.token({"poleAxis"}, "scene");
    if (pole == "scene") pole = std::string(1, stageUpAxis);
    if (pole == "Z") return Matrix4::rotateX(90.0);  // +Y -> +Z, +Z -> -Y
    if (pole != "Y") warn("poleAxis '" + pole + "' is not one of scene, Y, Z; Y is used");
    return Matrix4::identity();
}

}  // namespace

bool authorsShaping(const usd::PrimSpec& prim) {
    return std::any_of(prim.attributes.begin(), prim.attributes.end(), [](const usd::AttributeSpec& a) {
        return a.name.starts_with("inputs:shaping:") || a.name.starts_with("shaping:");
    });
}

RGB lightApiRadiance(const PrimReader& prim, double fallbackIntensity, const Warn& warn) {
    warnConnectedInputs(prim.prim(), warn);
    double intensity = prim.number({"inputs:intensity", "intensity"}, fallbackIntensity);
    double exposure = prim.number({"inputs:exposure", "exposure"}, 0.0);
    Vec3d color = prim.vec3({"inputs:color", "color"}, {1.0, 1.0, 1.0});
    RGB radiance(color * (intensity * std::exp2(exposure)));
    if (prim.boolean({"inputs:enableColorTemperature", "enableColorTemperature"}, false)) {
        double kelvin = prim.number({"inputs:colorTemperature", "colorTemperature"}, 6500.0);
        if (!(kelvin >= 1000.0 && kelvin <= 10000.0)) {
            warn("colorTemperature " + std::to_string(kelvin) + " K is outside UsdLux's 1000-10000 K; clamped");
            kelvin = std::clamp(std::isnan(kelvin) ? 6500.0 : kelvin, 1000.0, 10000.0);
        }
        radiance *= colorTemperatureTint(kelvin);
    }
    warnUnsupportedMultipliers(prim, warn);
    return radiance;
}

bool isLightType(const std::string& t) {
    return t == "RectLight" || t == "DiskLight" || t == "SphereLight" || t == "CylinderLight" || t == "DistantLight" ||
           t == "DomeLight" || t == "DomeLight_1";
}

std::optional<render::LightDesc> lightFromPrim(const PrimReader& prim, const Matrix4& toWorld, char stageUpAxis,
                                               const Warn& warn) {
    const std::string& type = prim.prim().typeName;
    render::LightDesc light;
    light.name = prim.path();
    light.transform = toWorld;
    light.radiance = lightApiRadiance(prim, type == "DistantLight" ? 50000.0 : 1.0, warn);
    light.normalize = prim.boolean({"inputs:normalize", "normalize"}, false);
    light.castsShadows = prim.boolean({"inputs:shadow:enable", "shadow:enable"}, true);  // UsdLux ShadowAPI
    bool shaped = appliesSchema(prim.prim(), "ShapingAPI") || authorsShaping(prim.prim());

    if (type == "RectLight") {
        light.type = render::LightType::Rect;
        light.width = static_cast<float>(prim.number({"inputs:width", "width"}, 1.0));
        light.height = static_cast<float>(prim.number({"inputs:height", "height"}, 1.0));
        std::string file = prim.token({"inputs:texture:file", "texture:file"}, "");
        if (!file.empty()) light.texture = loadTexture(file, "rendered with its constant colour", warn);
    } else if (type == "DiskLight") {
        light.type = render::LightType::Disk;
        light.radius = static_cast<float>(prim.number({"inputs:radius", "radius"}, 0.5));
    } else if (type == "SphereLight") {
        light.type = render::LightType::Sphere;
        light.radius = static_cast<float>(prim.number({"inputs:radius", "radius"}, 0.5));
        light.treatAsPoint = prim.boolean({"treatAsPoint"}, false) || light.radius == 0.0f;
    } else if (type == "CylinderLight") {
        light.type = render::LightType::Cylinder;
        light.length = static_cast<float>(prim.number({"inputs:length", "length"}, 1.0));
        light.radius = static_cast<float>(prim.number({"inputs:radius", "radius"}, 0.5));
        light.treatAsLine = prim.boolean({"treatAsLine"}, false) || light.radius == 0.0f;
        if (!(light.length > 0.0f)) {
            warn("a cylinder light of length " + std::to_string(light.length) + " emits nothing; skipped");
            return std::nullopt;
        }
    } else if (type == "DistantLight") {
        light.type = render::LightType::Distant;
        light.angleDegrees = static_cast<float>(prim.number({"inputs:angle", "angle"}, 0.53));
    } else if (type == "DomeLight" || type == "DomeLight_1") {
        light.type = render::LightType::Dome;
        light.texture = domeTexture(prim, warn);
        if (type == "DomeLight_1") light.transform = toWorld * poleRotation(prim, stageUpAxis, warn);
    } else {
        return std::nullopt;
    }

    if (light.type == render::LightType::Disk || light.type == render::LightType::Sphere ||
        light.type == render::LightType::Cylinder) {
        if (light.radius < 0.0f || (light.radius == 0.0f && light.type == render::LightType::Disk)) {
            warn("a " + type + " of radius " + std::to_string(light.radius) + " emits nothing; skipped");
            return std::nullopt;
        }
        if (light.radius == 0.0f && !light.normalize) {
            warn("a " + type + " of radius 0 emits nothing unless inputs:normalize is on; skipped");
            return std::nullopt;
        }
    }
    if (shaped) {
        if (light.type == render::LightType::Distant || light.type == render::LightType::Dome)
            warn("shaping is not applied to " + type + "s; ignored");
        else
            light.shaping = shapingOf(prim, warn);
    }
    return light;
}

}  // namespace fluence::delegate
