#include "delegate/material_adapter.h"

#include "delegate/prim_reader.h"
#include "delegate/shader_inputs.h"
#include "delegate/surface_shaders.h"

namespace fluence::delegate {

std::pair<std::string, std::string> splitPropertyPath(const std::string& path) {
    auto slash = path.rfind('/');
    auto dot = path.find('.', slash == std::string::npos ? 0 : slash);
    if (dot == std::string::npos) return {path, ""};
    return {path.substr(0, dot), path.substr(dot + 1)};
}

std::string parentPath(const std::string& path) {
    auto slash = path.rfind('/');
    return slash == 0 || slash == std::string::npos ? "/" : path.substr(0, slash);
}

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

namespace {

// The Shader a material output leads to, through NodeGraph outputs (nullptr when none).
const usd::PrimSpec* shaderBehind(const usd::Stage& stage, const usd::PrimSpec& material, const std::string& output) {
    const usd::PrimSpec* prim = &material;
    std::string property = output;
    for (int hop = 0; hop < 16; ++hop) {
        const usd::AttributeSpec* a = prim->attribute(property);
        if (!a || a->connections.empty()) return nullptr;
        auto [path, next] = splitPropertyPath(resolveTargetPath(prim->path, a->connections.front()));
        prim = stage.prim(path);
        if (!prim) return nullptr;
        if (prim->typeName != "NodeGraph") return prim;
        property = next;
    }
    return nullptr;
}

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
    // The MaterialX render context first (Standard Surface), then the universal one.
    std::string unsupported;
    for (const char* output : {"outputs:mtlx:surface", "outputs:surface"}) {
        const usd::PrimSpec* shader = shaderBehind(stage, *material, output);
        if (!shader) continue;
        std::string id = PrimReader(*shader, time).token({"info:id"}, "");
        ShaderInputs inputs(stage, *shader, time, convertColor, warn);
        if (id == "UsdPreviewSurface" || id == kStandardSurfaceId)
            return id == kStandardSurfaceId ? standardSurface(inputs, materialPath)
                                            : previewSurface(inputs, materialPath);
        if (unsupported.empty()) unsupported = shader->path + " ('" + id + "')";
    }
    warn(materialPath, unsupported.empty()
                           ? "material has no outputs:surface or outputs:mtlx:surface connected to a shader; using the "
                             "default material"
                           : "surface shader " + unsupported +
                                 " is not supported (UsdPreviewSurface and ND_standard_surface_surfaceshader are); "
                                 "using the default material");
    return desc;
}

}  // namespace fluence::delegate
