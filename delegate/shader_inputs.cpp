#include "delegate/shader_inputs.h"

#include "delegate/prim_reader.h"

namespace fluence::delegate {

std::string ShaderInputs::id() const { return PrimReader(shader_, time_).token({"info:id"}, ""); }

std::optional<ShaderInputs::Source> ShaderInputs::source(const std::string& input) const {
    const usd::PrimSpec* prim = &shader_;
    std::string name = "inputs:" + input;
    for (int hop = 0; hop < 16; ++hop) {
        const usd::AttributeSpec* a = prim->attribute(name);
        if (!a) return std::nullopt;
        if (a->connections.empty()) return Source{prim, name, false};
        auto [sourcePrim, sourceProp] = splitPropertyPath(resolveTargetPath(prim->path, a->connections.front()));
        const usd::PrimSpec* next = stage_.prim(sourcePrim);
        if (!next) {
            warn_(shader_.path,
                  "input '" + name + "' connects to missing prim " + sourcePrim + "; using its own value");
            return Source{prim, name, false};
        }
        if (next->typeName != "Material" && next->typeName != "NodeGraph") return Source{next, sourceProp, true};
        prim = next;
        name = sourceProp;
    }
    warn_(shader_.path, "input 'inputs:" + input + "': connection chain too long; ignored");
    return std::nullopt;
}

std::optional<std::pair<const usd::PrimSpec*, std::string>> ShaderInputs::valueSource(const std::string& input) const {
    std::optional<Source> s = source(input);
    if (s && s->nodeOutput) {
        // The node drives the input per point; its own value (if any) stands where nothing does.
        if (PrimReader(shader_, time_).value("inputs:" + input)) return std::make_pair(&shader_, "inputs:" + input);
        return std::nullopt;
    }
    if (!s || !PrimReader(*s->prim, time_).value(s->property)) return std::nullopt;
    return std::make_pair(s->prim, s->property);
}

std::optional<NodeOutput> ShaderInputs::connectedNode(const std::string& name) const {
    std::optional<Source> s = source(name);
    if (!s || !s->nodeOutput) return std::nullopt;
    return NodeOutput{s->prim, s->property};
}

RGB ShaderInputs::color(const std::string& name, const RGB& fallback) const {
    auto source = valueSource(name);
    if (!source) return fallback;
    PrimReader reader(*source->first, time_);
    std::optional<usd::Value> v = reader.value(source->second);
    if (v && v->isNumeric() && v->numbers.size() == 1) return RGB(static_cast<float>(v->numbers[0]));  // a float input
    Vec3d c = reader.vec3({source->second.c_str()}, {0, 0, 0});
    return convertColor_(RGB(c), reader.attributeMetadata(source->second, "colorSpace").value_or(""));
}

float ShaderInputs::number(const std::string& name, float fallback) const {
    auto source = valueSource(name);
    if (!source) return fallback;
    return static_cast<float>(PrimReader(*source->first, time_).number({source->second.c_str()}, fallback));
}

bool ShaderInputs::flag(const std::string& name, bool fallback) const {
    return number(name, fallback ? 1.0f : 0.0f) != 0.0f;
}

std::string ShaderInputs::text(const std::string& name, const std::string& fallback) const {
    auto source = valueSource(name);
    if (!source) return fallback;
    return PrimReader(*source->first, time_).token({source->second.c_str()}, fallback);
}

std::vector<float> ShaderInputs::tuple(const std::string& name, const std::vector<float>& fallback) const {
    auto source = valueSource(name);
    if (!source) return fallback;
    std::optional<usd::Value> v = PrimReader(*source->first, time_).value(source->second);
    if (!v || !v->isNumeric() || v->numbers.size() != fallback.size()) return fallback;
    std::vector<float> out;
    for (double x : v->numbers) out.push_back(static_cast<float>(x));
    return out;
}

std::optional<std::vector<float>> ShaderInputs::numbers(const std::string& name) const {
    auto source = valueSource(name);
    if (!source) return std::nullopt;
    PrimReader reader(*source->first, time_);
    std::optional<usd::Value> v = reader.value(source->second);
    if (!v || !v->isNumeric()) return std::nullopt;
    std::vector<float> out(v->numbers.begin(), v->numbers.end());
    if (out.size() >= 3 && v->typeName.starts_with("color")) {
        const RGB c = convertColor_(RGB(out[0], out[1], out[2]),
                                    reader.attributeMetadata(source->second, "colorSpace").value_or(""));
        out[0] = c.x, out[1] = c.y, out[2] = c.z;
    }
    return out;
}

}  // namespace fluence::delegate
