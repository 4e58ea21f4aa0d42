#include "delegate/shader_inputs.h"

#include "delegate/prim_reader.h"

namespace fluence::delegate {

std::optional<std::pair<const usd::PrimSpec*, std::string>> ShaderInputs::valueSource(const std::string& input) const {
    const usd::PrimSpec* prim = &shader_;
    std::string name = "inputs:" + input;
    for (int hop = 0; hop < 16; ++hop) {
        const usd::AttributeSpec* a = prim->attribute(name);
        if (!a) return std::nullopt;
        auto own = [&]() -> std::optional<std::pair<const usd::PrimSpec*, std::string>> {
            if (!PrimReader(*prim, time_).value(name)) return std::nullopt;
            return std::make_pair(prim, name);
        };
        if (a->connections.empty()) return own();
        auto [sourcePrim, sourceProp] = splitPropertyPath(resolveTargetPath(prim->path, a->connections.front()));
        const usd::PrimSpec* source = stage_.prim(sourcePrim);
        if (!source) {
            warn_(shader_.path, "input '" + name + "' connects to missing prim " + sourcePrim + "; using its own value");
            return own();
        }
        if (source->typeName != "Material" && source->typeName != "NodeGraph") {
            warn_(shader_.path, "input '" + name + "' is connected to " + source->path + " (" + source->typeName +
                                    "); shading networks and textures are not supported yet, using the input's own value");
            return own();
        }
        prim = source;
        name = sourceProp;
    }
    warn_(shader_.path, "input 'inputs:" + input + "': connection chain too long; ignored");
    return std::nullopt;
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

bool ShaderInputs::flag(const std::string& name, bool fallback) const { return number(name, fallback ? 1.0f : 0.0f) != 0.0f; }

}  // namespace fluence::delegate
