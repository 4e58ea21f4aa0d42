#include "delegate/render_settings_adapter.h"

#include <algorithm>
#include <cmath>

#include "core/name_table.h"
#include "delegate/material_adapter.h"
#include "delegate/prim_reader.h"

namespace fluence::delegate {

namespace {

const usd::PrimSpec& targetOfType(const usd::Stage& stage, const usd::PrimSpec& from, const std::string& target,
                                  const char* type, const char* relationship) {
    std::string path = resolveTargetPath(from.path, target);
    const usd::PrimSpec* prim = stage.prim(path);
    if (!prim || prim->typeName != type)
        throw SceneError(from.location.str() + ": " + from.path + ": " + relationship + " targets " + path +
                         ", which is " +
                         (prim ? "a " + (prim->typeName.empty() ? std::string("typeless prim") : prim->typeName)
                               : std::string("missing")) +
                         ", not a " + type);
    return *prim;
}

std::string relationshipTarget(const usd::PrimSpec& prim, const char* name) {
    const usd::RelationshipSpec* rel = prim.relationship(name);
    return rel && !rel->targets.empty() ? resolveTargetPath(prim.path, rel->targets.front()) : std::string();
}

std::optional<std::pair<int, int>> resolutionOf(const PrimReader& reader) {
    auto r = reader.value("resolution");
    if (!r) return std::nullopt;
    if (!r->isNumeric() || r->numbers.size() != 2 || r->numbers[0] < 1 || r->numbers[1] < 1)
        reader.fail("resolution must be an int2 of positive values, got " + r->toString());
    return std::make_pair(static_cast<int>(r->numbers[0]), static_cast<int>(r->numbers[1]));
}

RenderVarDesc varFromPrim(const usd::PrimSpec& prim, double time) {
    PrimReader reader(prim, time);
    RenderVarDesc var;
    var.path = prim.path;
    var.sourceName = reader.token({"sourceName"}, "");
    var.sourceType = reader.token({"sourceType"}, "raw");
    var.dataType = reader.token({"dataType"}, "color3f");
    var.aovName = reader.token({"driver:parameters:aov:name"}, primName(prim.path));
    var.filter = reader.token({"fluence:filter"}, "");
    return var;
}

// dataWindowNDC: (xmin, ymin, xmax, ymax), min < max.
std::array<float, 4> dataWindowOf(const PrimReader& reader) {
    std::array<float, 4> window{0.0f, 0.0f, 1.0f, 1.0f};
    auto v = reader.value("dataWindowNDC");
    if (!v) return window;
    if (!v->isNumeric() || v->numbers.size() != 4 || !(v->numbers[0] < v->numbers[2]) ||
        !(v->numbers[1] < v->numbers[3]))
        reader.fail("dataWindowNDC must be a float4 (xmin, ymin, xmax, ymax) with min < max, got " + v->toString());
    for (int i = 0; i < 4; ++i) window[std::size_t(i)] = static_cast<float>(v->numbers[std::size_t(i)]);
    return window;
}

// pixelAspectRatio and aspectRatioConformPolicy, each falling back to `inherited`'s.
render::ImageFraming framingOf(const PrimReader& reader, const render::ImageFraming& inherited) {
    using render::ApertureConform;
    static const std::pair<const char*, ApertureConform> kPolicies[] = {
        {"expandAperture", ApertureConform::ExpandAperture},
        {"cropAperture", ApertureConform::CropAperture},
        {"adjustApertureWidth", ApertureConform::AdjustApertureWidth},
        {"adjustApertureHeight", ApertureConform::AdjustApertureHeight},
        {"adjustPixelAspectRatio", ApertureConform::AdjustPixelAspectRatio}};
    render::ImageFraming framing = inherited;
    framing.pixelAspectRatio = static_cast<float>(reader.number({"pixelAspectRatio"}, inherited.pixelAspectRatio));
    if (!(framing.pixelAspectRatio > 0.0f) || !std::isfinite(framing.pixelAspectRatio))
        reader.fail("pixelAspectRatio must be positive, got " + std::to_string(framing.pixelAspectRatio));
    if (!reader.value("aspectRatioConformPolicy")) return framing;
    std::string policy = reader.token({"aspectRatioConformPolicy"}, "");
    for (const auto& [token, conform] : kPolicies)
        if (policy == token) {
            framing.conform = conform;
            return framing;
        }
    reader.fail("aspectRatioConformPolicy '" + policy +
                "' is not one of expandAperture, cropAperture, adjustApertureWidth, adjustApertureHeight, "
                "adjustPixelAspectRatio");
}

}  // namespace

std::optional<RenderSettingsDesc> renderSettingsFromStage(
    const usd::Stage& stage, const std::string& settingsPath, double time,
    const std::function<void(const std::string& where, const std::string& message)>& warnMissing) {
    std::string path = settingsPath;
    bool fromMetadata = path.empty();
    if (fromMetadata)
        if (const usd::MetadataEntry* e = usd::findMetadata(stage.rootLayer().metadata, "renderSettingsPrimPath"))
            path = e->value.asString().value_or("");
    if (path.empty()) return std::nullopt;
    const usd::PrimSpec* prim = stage.prim(path);
    if (!prim && fromMetadata && warnMissing) {
        warnMissing(stage.rootLayer().identifier, "renderSettingsPrimPath names " + path +
                                                      ", which is not in the scene; rendering with default settings");
        return std::nullopt;
    }
    if (!prim)
        throw SceneError(fromMetadata
                             ? "the stage's renderSettingsPrimPath names " + path + ", which is not in the scene"
                             : "render settings " + path + " do not exist in the scene");
    if (prim->typeName != "RenderSettings")
        throw SceneError("render settings " + path + " is a " +
                         (prim->typeName.empty() ? "typeless prim" : prim->typeName) + ", not a RenderSettings prim");

    PrimReader reader(*prim, time);
    RenderSettingsDesc s;
    s.path = path;
    if (auto r = resolutionOf(reader)) {
        s.resolution = *r;
        s.resolutionAuthored = true;
    }
    s.cameraPath = relationshipTarget(*prim, "camera");
    s.framing = framingOf(reader, s.framing);
    if (auto purposes = reader.strings("includedPurposes")) s.includedPurposes = *purposes;
    s.integrator = reader.token({"fluence:integrator"}, "");
    s.sampler = reader.token({"fluence:sampler"}, "");
    s.defaultLight = reader.boolean({"fluence:defaultLight"}, true);
    s.domeLightSampling = reader.token({"fluence:domeLightSampling"}, "");
    s.disableMotionBlur = reader.boolean({"disableMotionBlur", "instantaneousShutter"}, false);
    for (const usd::AttributeSpec& attribute : prim->attributes)
        if (attribute.name.starts_with("fluence:") &&
            std::count(attribute.name.begin(), attribute.name.end(), ':') == 2)
            if (reader.value(attribute.name))
                s.integratorParameters[attribute.name] = reader.number({attribute.name.c_str()}, 0.0);

    if (const usd::RelationshipSpec* products = prim->relationship("products"))
        for (const std::string& target : products->targets) {
            const usd::PrimSpec& productPrim = targetOfType(stage, *prim, target, "RenderProduct", "products");
            PrimReader pr(productPrim, time);
            RenderProductDesc product;
            product.path = productPrim.path;
            product.productName = pr.token({"productName"}, "");
            product.productType = pr.token({"productType"}, "raster");
            product.resolution = resolutionOf(pr).value_or(s.resolution);
            std::string camera = relationshipTarget(productPrim, "camera");
            product.cameraPath = camera.empty() ? s.cameraPath : camera;
            product.framing = framingOf(pr, s.framing);
            product.dataWindowNdc = dataWindowOf(pr);
            product.disableMotionBlur = pr.boolean({"disableMotionBlur", "instantaneousShutter"}, s.disableMotionBlur);
            product.compression = pr.token({"driver:parameters:OpenEXR:compression"}, "");
            if (const usd::RelationshipSpec* vars = productPrim.relationship("orderedVars"))
                for (const std::string& v : vars->targets)
                    product.vars.push_back(
                        varFromPrim(targetOfType(stage, productPrim, v, "RenderVar", "orderedVars"), time));
            s.products.push_back(std::move(product));
        }
    return s;
}

}  // namespace fluence::delegate
