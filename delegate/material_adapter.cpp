#include "delegate/material_adapter.h"

#include "delegate/prim_reader.h"

namespace fluence::delegate {

namespace {

std::string parentPath(const std::string& path) {
    auto slash = path.rfind('/');
    return slash == 0 || slash == std::string::npos ? "/" : path.substr(0, slash);
}

const usd::RelationshipSpec* bindingOf(const usd::PrimSpec& prim) {
    const usd::RelationshipSpec* r = prim.relationship("material:binding:full");
    if (!r || r->targets.empty()) r = prim.relationship("material:binding");
    return r && !r->targets.empty() && !r->blocked ? r : nullptr;
}

bool strongerThanDescendants(const usd::RelationshipSpec& rel) {
    const usd::MetadataEntry* e = usd::findMetadata(rel.metadata, "bindMaterialAs");
    return e && e->value.asString().value_or("") == "strongerThanDescendants";
}

// Splits "/Prim/Path.property:name" into prim path and property name.
std::pair<std::string, std::string> splitPropertyPath(const std::string& path) {
    auto slash = path.rfind('/');
    auto dot = path.find('.', slash == std::string::npos ? 0 : slash);
    if (dot == std::string::npos) return {path, ""};
    return {path.substr(0, dot), path.substr(dot + 1)};
}

}  // namespace

std::string resolveTargetPath(const std::string& anchor, const std::string& target) {
    if (target.starts_with("/")) return target;
    std::string base = anchor;
    std::string rest = target;
    while (true) {
        if (rest.starts_with("../")) {
            base = parentPath(base);
            rest = rest.substr(3);
        } else if (rest == "..") {
            return parentPath(base);
        } else if (rest.starts_with("./")) {
            rest = rest.substr(2);
        } else {
            break;
        }
    }
    if (rest.empty()) return base;
    if (rest.starts_with(".")) return base + rest;  // a property of the anchor
    return (base == "/" ? "" : base) + "/" + rest;
}

std::string boundMaterialPath(const usd::Stage& stage, const usd::PrimSpec& prim) {
    // Walk upwards: the closest binding wins, unless a higher one is stronger than descendants
    // (the highest such one wins, being visited last).
    std::string bound;
    for (std::string path = prim.path; !path.empty() && path != "/"; path = parentPath(path)) {
        const usd::PrimSpec* p = stage.prim(path);
        const usd::RelationshipSpec* rel = p ? bindingOf(*p) : nullptr;
        if (rel && (bound.empty() || strongerThanDescendants(*rel))) bound = resolveTargetPath(path, rel->targets.front());
    }
    return bound;
}

namespace {

class PreviewSurfaceReader {
public:
    PreviewSurfaceReader(const usd::Stage& stage, double time, const Warn& warn)
        : stage_(stage), time_(time), warn_(warn) {}

    // The value of a colour input on `shader`, following connections to interface inputs.
    std::optional<std::pair<RGB, std::string>> colorInput(const usd::PrimSpec& shader, const std::string& input) const {
        auto source = valueSource(shader, input);
        if (!source || !PrimReader(*source->first, time_).value(source->second)) return std::nullopt;
        PrimReader reader(*source->first, time_);
        Vec3d v = reader.vec3({source->second.c_str()}, {0, 0, 0});
        return std::make_pair(RGB(v), reader.attributeMetadata(source->second, "colorSpace").value_or(""));
    }

    // The value of a float input on `shader`, following connections to interface inputs.
    std::optional<double> floatInput(const usd::PrimSpec& shader, const std::string& input) const {
        auto source = valueSource(shader, input);
        if (!source || !PrimReader(*source->first, time_).value(source->second)) return std::nullopt;
        return PrimReader(*source->first, time_).number({source->second.c_str()}, 0.0);
    }

private:
    // The attribute whose value `input` takes: its own, or that of the Material or NodeGraph
    // interface input it connects to (nullopt when not authored anywhere along the way).
    std::optional<std::pair<const usd::PrimSpec*, std::string>> valueSource(const usd::PrimSpec& shader,
                                                                            const std::string& input) const {
        const usd::PrimSpec* prim = &shader;
        std::string name = input;
        for (int hop = 0; hop < 16; ++hop) {
            const usd::AttributeSpec* a = prim->attribute(name);
            if (!a) return std::nullopt;
            if (a->connections.empty()) return std::make_pair(prim, name);
            auto [sourcePrim, sourceProp] = splitPropertyPath(resolveTargetPath(prim->path, a->connections.front()));
            const usd::PrimSpec* source = stage_.prim(sourcePrim);
            if (!source) {
                warn_(shader.path, "input '" + name + "' connects to missing prim " + sourcePrim + "; using its value");
                return std::make_pair(prim, name);
            }
            if (source->typeName != "Material" && source->typeName != "NodeGraph") {
                warn_(shader.path, "input '" + name + "' is connected to " + source->path + " (" + source->typeName +
                                       "); shading networks and textures are not supported yet, using the input's value");
                return std::make_pair(prim, name);
            }
            prim = source;
            name = sourceProp;
        }
        warn_(shader.path, "input '" + input + "': connection chain too long; ignored");
        return std::nullopt;
    }

    const usd::Stage& stage_;
    double time_;
    const Warn& warn_;
};

}  // namespace

render::MaterialDesc materialFromPath(const usd::Stage& stage, const std::string& materialPath, double time,
                                      const ColorConverter& convertColor, const Warn& warn) {
    render::MaterialDesc desc;
    desc.name = materialPath;
    const usd::PrimSpec* material = stage.prim(materialPath);
    if (!material) {
        warn(materialPath, "bound material does not exist; using the default material");
        return desc;
    }
    const usd::AttributeSpec* surface = material->attribute("outputs:surface");
    if (!surface || surface->connections.empty()) {
        warn(materialPath, "material has no outputs:surface connection (render-context outputs such as "
                           "outputs:mtlx:surface are not supported yet); using the default material");
        return desc;
    }
    auto [shaderPath, output] = splitPropertyPath(resolveTargetPath(materialPath, surface->connections.front()));
    const usd::PrimSpec* shader = stage.prim(shaderPath);
    if (!shader) {
        warn(materialPath, "outputs:surface connects to missing prim " + shaderPath + "; using the default material");
        return desc;
    }
    std::string id = PrimReader(*shader, time).token({"info:id"}, "");
    if (id != "UsdPreviewSurface") {
        warn(shaderPath, "surface shader '" + id + "' is not supported yet (only UsdPreviewSurface); using the default material");
        return desc;
    }
    PreviewSurfaceReader reader(stage, time, warn);
    if (auto c = reader.colorInput(*shader, "inputs:diffuseColor")) desc.diffuse = convertColor(c->first, c->second);
    if (auto c = reader.colorInput(*shader, "inputs:emissiveColor")) desc.emission = convertColor(c->first, c->second);
    if (auto d = reader.floatInput(*shader, "inputs:displacement")) desc.displacement = static_cast<float>(*d);
    return desc;
}

}  // namespace fluence::delegate
