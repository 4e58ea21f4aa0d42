// The nodes behind a surface shader's inputs -> render::InputBinding (per-point parameters).
//
// A surface input connected to a Shader output becomes a binding when the node is
// | node (info:id)               | read                                                       |
// |------------------------------|------------------------------------------------------------|
// | UsdUVTexture                 | file (resolved; <UDIM> kept), st, wrapS/wrapT (black,      |
// | outputs r, g, b, a, rgb      | clamp, repeat, mirror; useMetadata -> repeat), fallback    |
// |                              | (0,0,0,1), scale (1,1,1,1), bias (0,0,0,0),                |
// |                              | sourceColorSpace (auto, raw, sRGB)                         |
// | UsdPrimvarReader_float2      | on a texture's st: varname, fallback                       |
// | UsdTransform2d               | between the two: in, rotation (degrees), scale, translation|
// | UsdPrimvarReader_float,      | straight into the input: varname, fallback                 |
// | _float3 (outputs:result)     |                                                            |
// | ND_image_<type> (MaterialX)  | file (resolved), default, uaddressmode/vaddressmode        |
// | output out                   | (constant, clamp, periodic, mirror), the file's colorSpace |
// |                              | (any of the OCIO config's; none: data, as stored),         |
// |                              | filtertype (closest, linear, cubic)                        |
// | ND_tiledimage_<type>         | as an image, repeating, placed by uvtiling, uvoffset,      |
// |                              | realworldimagesize and realworldtilesize                   |
// | ND_normalmap (MaterialX)     | in (an image or tiled image), scale: (2 t - 1) (scale,     |
// |                              | scale, 1), tangent space                                   |
// | ND_constant_, ND_multiply_,  | over any of the nodes above and each other, nested:        |
// | ND_mix_<type> (MaterialX)    | delegate/shading_graph.h (folded to a constant where they  |
// |                              | are constant, else a render::ShadingNode graph)            |
// MaterialX images read the primary UV set (the primvar st); their frame ranges are not read.
// An st left unconnected reads the primvar "st" (as most renderers do); an st given a value
// without a reader uses that value everywhere. Any other node, anywhere beneath the input, warns,
// naming it and the file it came from, and the input keeps its own value. A missing texture file
// warns, naming it, and the binding uses the texture's fallback. Every input of a node may itself
// connect to a Material or NodeGraph interface input (delegate/shader_inputs.h).
#pragma once

#include <vector>

#include "delegate/shader_inputs.h"
#include "render/scene_description.h"

namespace fluence::delegate {

// A surface shader input that nodes may drive.
struct DrivableInput {
    const char* name;  // without "inputs:"
    render::MaterialInput target;
    int channels;         // 3 for colours and normals, 1 for floats
    float factor = 1.0f;  // the driven value is multiplied by it (Standard Surface: base for base_color)
};

// For each input of `surface` connected to nodes Fluence evaluates: appends a binding to
// `material.bindings`, or, where the nodes compute a constant, sets the parameter to it.
void readBindings(const ShaderInputs& surface, const std::vector<DrivableInput>& inputs,
                  render::MaterialDesc& material);

}  // namespace fluence::delegate
