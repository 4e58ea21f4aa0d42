#include "delegate/volume_adapter.h"

#include <algorithm>

#include "delegate/material_binding.h"
#include "delegate/prim_reader.h"
#include "delegate/shader_inputs.h"

namespace fluence::delegate {

namespace {

// The material bound to `volume`: the full or all-purpose binding, else the preview one.
std::string volumeMaterialPath(const usd::Stage& stage, const usd::PrimSpec& volume) {
    std::string bound = boundMaterialPath(stage, volume);
    if (!bound.empty()) return bound;
    for (std::string path = volume.path; !path.empty() && path != "/"; path = parentPath(path)) {
        const usd::PrimSpec* p = stage.prim(path);
        const usd::RelationshipSpec* r = p ? p->relationship("material:binding:preview") : nullptr;
        if (r && !r->targets.empty() && !r->blocked) return resolveTargetPath(path, r->targets.front());
    }
    return "";
}

// The Shader behind the material's outputs:volume (through NodeGraph outputs), or nullptr.
const usd::PrimSpec* volumeShader(const usd::Stage& stage, const usd::PrimSpec& material) {
    const usd::PrimSpec* prim = &material;
    std::string property = "outputs:volume";
    for (int hop = 0; hop < 16; ++hop) {
        const usd::AttributeSpec* a = prim->attribute(property);
        if (!a || a->connections.empty()) return nullptr;
        auto [path, next] = splitPropertyPath(resolveTargetPath(prim->path, a->connections.front()));
        prim = stage.prim(path);
        if (!prim || prim->typeName != "NodeGraph") return prim;
        property = next;
    }
    return nullptr;
}

// Reads the shader's inputs, resolving primvar readers against the Volume's constant primvars
// and field readers to field names.
class VolumeShaderReader {
public:
    VolumeShaderReader(const ShaderInputs& inputs, const usd::PrimSpec& volume, double time)
        : in_(inputs), volume_(volume), time_(time) {}

    float number(const std::string& name, float fallback) const {
        if (auto v = primvarValue(name, 1)) return static_cast<float>(v->at(0));
        return in_.number(name, fallback);
    }
    RGB color(const std::string& name, const RGB& fallback) const {
        if (auto v = primvarValue(name, 3))
            return v->size() >= 3 ? RGB(Vec3d(v->at(0), v->at(1), v->at(2))) : RGB(float(v->at(0)));
        return in_.color(name, fallback);
    }
    // The field a field reader on `name` names, or `fallback` when the input is not read from a field.
    std::string field(const std::string& name, const std::string& fallback) const {
        std::optional<NodeOutput> node = in_.connectedNode(name);
        if (!node) return fallback;
        ShaderInputs reader(in_.stage(), *node->shader, time_, in_.convertColor(), in_.warn());
        std::string fieldName = reader.text("fieldname", "");
        if (fieldName.empty())
            in_.warn()(node->shader->path,
                       "input '" + name +
                           "' is not connected to a field reader (inputs:fieldname); reading the field '" + fallback +
                           "'");
        return fieldName.empty() ? fallback : fieldName;
    }

private:
    // The value a UsdPrimvarReader on input `name` gives (the Volume's primvar, else the
    // reader's fallback), or nullopt when the input is not connected to one.
    std::optional<std::vector<double>> primvarValue(const std::string& name, int components) const {
        std::optional<NodeOutput> node = in_.connectedNode(name);
        if (!node) return std::nullopt;
        PrimReader readerPrim(*node->shader, time_);
        if (!readerPrim.token({"info:id"}, "").starts_with("UsdPrimvarReader_")) return std::nullopt;
        ShaderInputs reader(in_.stage(), *node->shader, time_, in_.convertColor(), in_.warn());
        std::string varname = reader.text("varname", "");
        std::optional<usd::Value> v = PrimReader(volume_, time_).value("primvars:" + varname);
        if (v && v->isNumeric() && !v->numbers.empty())
            return std::vector<double>(v->numbers.begin(), v->numbers.end());
        std::vector<float> fallback =
            reader.tuple("fallback", std::vector<float>(static_cast<std::size_t>(components), 0.0f));
        return std::vector<double>(fallback.begin(), fallback.end());
    }

    const ShaderInputs& in_;
    const usd::PrimSpec& volume_;
    double time_;
};

}  // namespace

VolumeMaterial volumeMaterialOf(const usd::Stage& stage, const usd::PrimSpec& volume, double time,
                                const ColorConverter& convertColor, const Warn& warn) {
    VolumeMaterial m;
    std::string path = volumeMaterialPath(stage, volume);
    if (path.empty()) return m;
    const usd::PrimSpec* material = stage.prim(path);
    const usd::PrimSpec* shader = material ? volumeShader(stage, *material) : nullptr;
    if (!shader) {
        warn(volume.path,
             "bound material " + path + " has no outputs:volume connected to a shader; using the fallback volume");
        return m;
    }
    ShaderInputs inputs(stage, *shader, time, convertColor, warn);
    VolumeShaderReader in(inputs, volume, time);
    volumes::GridMediumParams& p = m.params;
    m.densityField = in.field("density", m.densityField);
    const bool heat = shader->attribute("inputs:heat") != nullptr;  // the preview shaders' name
    m.temperatureField = in.field(heat ? "heat" : "temperature", heat ? "heat" : m.temperatureField);
    m.colorField = in.field("color", m.colorField);
    p.densityScale = in.number("densityScale", p.densityScale);
    p.albedo = in.color("albedo", p.albedo);
    p.anisotropy = in.number("anisotropy", p.anisotropy);
    p.emissionColor = in.color("emissionColor", p.emissionColor);
    p.emissionScale = in.number("emissionScale", p.emissionScale);
    p.temperatureScale = in.number(heat ? "heatScale" : "temperatureScale", p.temperatureScale);
    p.temperatureOffset = in.number("temperatureOffset", p.temperatureOffset);
    p.blackbodyIntensity = in.number("blackbodyIntensity", p.blackbodyIntensity);
    if (p.densityScale < 0.0f || !(p.anisotropy > -1.0f && p.anisotropy < 1.0f))
        warn(shader->path, "densityScale must be >= 0 and anisotropy in (-1, 1); clamped");
    p.densityScale = std::max(p.densityScale, 0.0f);
    p.anisotropy = std::clamp(p.anisotropy, -0.99f, 0.99f);
    return m;
}

}  // namespace fluence::delegate
