// MaterialX's arithmetic nodes between a surface shader's input and the nodes it reads, read into
// what drives the input: a constant, one texture or primvar binding, or a render::ShadingNode
// graph over several (render/material_shader.h evaluates it per point).
//
// | node (info:id)              | value, per channel (unconnected, unauthored inputs in brackets)  |
// |-----------------------------|------------------------------------------------------------------|
// | ND_constant_<type>          | value (0)                                                        |
// | ND_multiply_<type>[FA]      | in1 (0) * in2 (1)                                                |
// | ND_mix_<type>[_<type>]      | bg (0) * (1 - mix (0)) + fg (0) * mix                            |
// for the float, color3/4 and vector2/3/4 types. A one-component operand of a wider node is
// replicated (MaterialX's FA variants, and a float mix); colour values are converted into the
// rendering space. Every other node is a leaf the caller reads (LeafReader: images, tiled images,
// UsdUVTexture, primvar readers, normal maps), and it warns about the nodes it does not evaluate.
//
// The graph is folded as it is read: a node of constants becomes a constant, and a texture or
// primvar times a constant becomes that source with its factor (a uniform constant) or its
// texture's scale, bias and fallback (per channel) multiplied, so graph nodes remain only where
// two sources meet or a mix blends a source. A node output read twice is read once. A node Fluence
// does not evaluate anywhere beneath the input, a graph deeper than kMaxGraphDepth (a cycle) or
// larger than render::kMaxShadingNodes leaves the input with its own value, with a warning.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <variant>

#include "delegate/shader_inputs.h"
#include "render/scene_description.h"

namespace fluence::delegate {

inline constexpr int kMaxGraphDepth = 32;

// A value the same at every point: four channels, a one-component value replicated into all of
// them; `channels` as authored (1 to 4).
struct ConstantValue {
    float value[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    int channels = 1;
};

// What drives a surface input: nothing Fluence evaluates (monostate; already warned), a
// constant, or a binding whose `channels` are the value's (its `input` left for the caller).
using DrivenValue = std::variant<std::monostate, ConstantValue, render::InputBinding>;

// Reads a leaf node's output into a texture or primvar binding with all the channels it has;
// nullopt (after a warning naming it) when the node is not one Fluence evaluates.
using LeafReader = std::function<std::optional<render::InputBinding>(const NodeOutput&)>;

// What `output`, connected to the input `inputName` of `surface` (named in warnings), computes.
DrivenValue readDrivenValue(const ShaderInputs& surface, const std::string& inputName, const NodeOutput& output,
                            const LeafReader& leaf);

}  // namespace fluence::delegate
