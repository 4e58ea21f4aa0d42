// Reading a UsdShade Shader's inputs: an input's own value, or the value of the Material or
// NodeGraph interface input it connects to (followed through any number of interface hops).
//
// An input connected to another Shader's output (a texture, a primvar reader, any node) is not
// evaluated yet: it warns once per input and uses the input's own authored value, else the
// caller's fallback. Colours come back converted into the rendering space (honouring the
// attribute's colorSpace metadata).
#pragma once

#include <optional>
#include <string>
#include <utility>

#include "core/rgb.h"
#include "delegate/material_adapter.h"

namespace fluence::delegate {

class ShaderInputs {
public:
    ShaderInputs(const usd::Stage& stage, const usd::PrimSpec& shader, double time, const ColorConverter& convertColor,
                 const Warn& warn)
        : stage_(stage), shader_(shader), time_(time), convertColor_(convertColor), warn_(warn) {}

    const usd::PrimSpec& shader() const { return shader_; }
    // `name` without its "inputs:" prefix.
    RGB color(const std::string& name, const RGB& fallback) const;
    float number(const std::string& name, float fallback) const;
    bool flag(const std::string& name, bool fallback) const;

private:
    // The prim and attribute holding the input's value (nullopt when authored nowhere).
    std::optional<std::pair<const usd::PrimSpec*, std::string>> valueSource(const std::string& input) const;

    const usd::Stage& stage_;
    const usd::PrimSpec& shader_;
    double time_;
    const ColorConverter& convertColor_;
    const Warn& warn_;
};

}  // namespace fluence::delegate
