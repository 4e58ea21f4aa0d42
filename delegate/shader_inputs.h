// Reading a UsdShade Shader's inputs: an input's own value, or the value of the Material or
// NodeGraph interface input it connects to (followed through any number of interface hops and
// NodeGraph outputs).
//
// An input connected to another Shader's output (a texture, a primvar reader, any node) reads as
// its own authored value (else the caller's fallback): connectedNode() names the node, and
// delegate/shading_network.h turns the supported ones into per-point bindings. Colours come back
// converted into the rendering space (honouring the attribute's colorSpace metadata).
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/rgb.h"
#include "delegate/material_adapter.h"

namespace fluence::delegate {

// A Shader's output an input connects to.
struct NodeOutput {
    const usd::PrimSpec* shader;
    std::string output;  // "outputs:rgb", ...
};

class ShaderInputs {
public:
    ShaderInputs(const usd::Stage& stage, const usd::PrimSpec& shader, double time, const ColorConverter& convertColor,
                 const Warn& warn)
        : stage_(stage), shader_(shader), time_(time), convertColor_(convertColor), warn_(warn) {}

    const usd::PrimSpec& shader() const { return shader_; }
    const usd::Stage& stage() const { return stage_; }
    double time() const { return time_; }
    const ColorConverter& convertColor() const { return convertColor_; }
    const Warn& warn() const { return warn_; }
    // The shader's info:id ("" when it has none).
    std::string id() const;
    // The inputs of another shader of the same network, read the same way.
    ShaderInputs node(const usd::PrimSpec& shader) const {
        return ShaderInputs(stage_, shader, time_, convertColor_, warn_);
    }

    // `name` without its "inputs:" prefix.
    RGB color(const std::string& name, const RGB& fallback) const;
    float number(const std::string& name, float fallback) const;
    bool flag(const std::string& name, bool fallback) const;
    // A token, string or asset path (resolved) input.
    std::string text(const std::string& name, const std::string& fallback) const;
    // A float2/float3/float4 input, `fallback.size()` components.
    std::vector<float> tuple(const std::string& name, const std::vector<float>& fallback) const;
    // A numeric input of any width as authored: nullopt when it has no value; colours (color3f,
    // color4f) converted into the rendering space, alpha as authored.
    std::optional<std::vector<float>> numbers(const std::string& name) const;

    // The Shader output the input is connected to (through interface inputs and NodeGraph
    // outputs), or nullopt when it is not connected to a Shader.
    std::optional<NodeOutput> connectedNode(const std::string& name) const;

private:
    struct Source {
        const usd::PrimSpec* prim;
        std::string property;
        bool nodeOutput;  // property is an output of the Shader `prim`
    };
    // Where the input's value comes from: the last attribute of its connection chain.
    std::optional<Source> source(const std::string& input) const;
    // The prim and attribute holding the input's value (nullopt when authored nowhere).
    std::optional<std::pair<const usd::PrimSpec*, std::string>> valueSource(const std::string& input) const;

    const usd::Stage& stage_;
    const usd::PrimSpec& shader_;
    double time_;
    const ColorConverter& convertColor_;
    const Warn& warn_;
};

}  // namespace fluence::delegate
