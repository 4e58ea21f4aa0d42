// MaterialX documents (.mtlx) as USD layers, the way USD's MaterialX file format plugin (usdMtlx)
// presents them, so that a reference such as @./Bishop_mat.mtlx@</MaterialX/Materials> composes
// like any other layer.
//
// The document (read with pugixml) becomes:
//     def Scope "MaterialX" { def Scope "Materials" {
//         def Material "<surfacematerial name>" {
//             token outputs:mtlx:surface.connect = <./<shader>.outputs:out>
//             def Shader "<shader>" { uniform token info:id = "ND_standard_surface_surfaceshader" ... }
//             def NodeGraph "<nodegraph>" { <type> outputs:<name>.connect = <./<node>.outputs:out>
//                                           def Shader "<node>" { info:id = "ND_<category>_<type>" ... } }
//             def Shader "<node>" { ... }   (document-level nodes the shader reads)
//     } } }
// Each material holds everything its shader reads (its node graphs and nodes, copied in), so
// that the connections stay inside the prim a reference brings in. Node definitions: a node's
// `nodedef` attribute, else ND_<category>_<type> (ND_standard_surface_surfaceshader,
// ND_normalmap for normalmap). Inputs keep their names under `inputs:` with the MaterialX type
// mapped to USD's (float, int, bool, color3f, color4f, float2, vector3f, float4, string, asset for
// filename, matrix3d, matrix4d); `nodename`, `nodegraph` + `output` and graph-interface
// `interfacename` become connections. A `colorspace` (on the input, else inherited from its node,
// node graph or the document) becomes the attribute's colorSpace metadata on colour values and
// on the file input of colour images (data images -- float and vector types -- keep none, as
// MaterialX applies colour spaces to colour types only).
// What the document has that this model does not carry (looks, geometry info, custom nodedefs,
// `unit` conversions) is reported once per element kind as a ParseWarning naming the document.
#pragma once

#include <memory>
#include <string>

#include "scene/layer.h"

namespace fluence::usd {

// Reads the MaterialX document at `path`. Throws FileError when it cannot be read and ParseError
// (naming the file and the XML's byte offset) when it is not a MaterialX document.
std::unique_ptr<Layer> readMaterialXFile(const std::string& path);

// The same from text in memory; `identifier` names it in messages and anchors its asset paths.
std::unique_ptr<Layer> readMaterialX(const std::string& text, const std::string& identifier);

}  // namespace fluence::usd
