// The nodes behind a surface shader's inputs -> render::InputBinding (per-point parameters).
//
// A surface input connected to a Shader output becomes a binding when the node is
// | node (info:id)              | read                                                       |
// |-----------------------------|------------------------------------------------------------|
// | UsdUVTexture                | file (resolved; <UDIM> kept), st, wrapS/wrapT (black,      |
// | outputs r, g, b, a, rgb     | clamp, repeat, mirror; useMetadata -> repeat), fallback    |
// |                             | (0,0,0,1), scale (1,1,1,1), bias (0,0,0,0),                |
// |                             | sourceColorSpace (auto, raw, sRGB)                         |
// | UsdPrimvarReader_float2     | on a texture's st: varname, fallback                       |
// | UsdTransform2d              | between the two: in, rotation (degrees), scale, translation|
// | UsdPrimvarReader_float,     | straight into the input: varname, fallback                 |
// | _float3 (outputs:result)    |                                                            |
// | ND_image_<type> (MaterialX)  | file (resolved), default, uaddressmode/vaddressmode        |
// | output out                   | (constant, clamp, periodic, mirror), the file's colorSpace |
// |                              | (any of the OCIO config's; none: data, as stored)          |
// | ND_normalmap (MaterialX)     | in (an image), scale: (2 t - 1) (scale, scale, 1), tangent |
// |                              | space                                                      |
// MaterialX images read the primary UV set (the primvar st).
// An st left unconnected reads the primvar "st" (as most renderers do); an st given a value
// without a reader uses that value everywhere. Any other node warns once, naming it, and the
// input keeps its own value. A missing texture file warns, naming it, and the binding uses the
// texture's fallback. Every input of a node may itself connect to a Material or NodeGraph
// interface input (delegate/shader_inputs.h).
#pragma once

#include <vector>

#include "delegate/shader_inputs.h"
#include "render/scene_description.h"

namespace fluence::delegate {

// A surface shader input that nodes may drive.
struct DrivableInput {
    const char* name;  // without "inputs:"
    render::MaterialInput target;
    int channels;      // 3 for colours and normals, 1 for floats
};

// Appends to `bindings` one binding per input of `surface` connected to a supported node.
void readBindings(const ShaderInputs& surface, const std::vector<DrivableInput>& inputs,
                  std::vector<render::InputBinding>& bindings);

}  // namespace fluence::delegate
