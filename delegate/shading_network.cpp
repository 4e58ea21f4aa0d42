#include "delegate/shading_network.h"

#include <algorithm>
#include <variant>

#include "delegate/prim_reader.h"
#include "delegate/render_index.h"
#include "delegate/shading_graph.h"
#include "render/material_shader.h"

namespace fluence::delegate {

namespace {

// The channels a texture output names: {first, count}; {-1, 0} for an unknown output.
std::pair<int, int> outputChannels(const std::string& output) {
    if (output == "outputs:rgb") return {0, 3};
    if (output == "outputs:r") return {0, 1};
    if (output == "outputs:g") return {1, 1};
    if (output == "outputs:b") return {2, 1};
    if (output == "outputs:a") return {3, 1};
    return {-1, 0};
}

texture::Wrap wrapOf(const ShaderInputs& tex, const char* input) {
    std::string w = tex.text(input, "useMetadata");
    if (w == "black") return texture::Wrap::Black;
    if (w == "clamp") return texture::Wrap::Clamp;
    if (w == "mirror") return texture::Wrap::Mirror;
    if (w != "repeat" && w != "useMetadata")
        tex.warn()(tex.shader().path, std::string("inputs:") + input + " '" + w + "' is not a wrap mode; using repeat");
    return texture::Wrap::Repeat;
}

texture::SourceColorSpace colorSpaceOf(const ShaderInputs& tex) {
    std::string s = tex.text("sourceColorSpace", "auto");
    if (s == "raw") return texture::SourceColorSpace::Raw;
    if (s == "sRGB") return texture::SourceColorSpace::SRGB;
    if (s != "auto")
        tex.warn()(tex.shader().path, "inputs:sourceColorSpace '" + s + "' is not auto, raw or sRGB; using auto");
    return texture::SourceColorSpace::Auto;
}

void copyInto(const std::vector<float>& values, float* out) { std::copy(values.begin(), values.end(), out); }

// The texture coordinates a UsdUVTexture reads: its st input's primvar reader and transform.
void readTextureCoordinates(const ShaderInputs& surface, const ShaderInputs& tex, render::TextureDesc& desc) {
    std::optional<NodeOutput> node = tex.connectedNode("st");
    if (!node) {
        if (PrimReader(tex.shader(), tex.time()).value("inputs:st")) {
            desc.uvPrimvar.clear();
            copyInto(tex.tuple("st", {0.0f, 0.0f}), desc.uvFallback);
        }
        return;
    }
    if (ShaderInputs transform = surface.node(*node->shader); transform.id() == "UsdTransform2d") {
        desc.uvTransform.rotationDegrees = transform.number("rotation", 0.0f);
        copyInto(transform.tuple("scale", {1.0f, 1.0f}), desc.uvTransform.scale);
        copyInto(transform.tuple("translation", {0.0f, 0.0f}), desc.uvTransform.translation);
        node = transform.connectedNode("in");
        if (!node) {
            desc.uvPrimvar.clear();
            copyInto(transform.tuple("in", {0.0f, 0.0f}), desc.uvFallback);
            return;
        }
    }
    ShaderInputs reader = surface.node(*node->shader);
    if (reader.id() != "UsdPrimvarReader_float2") {
        surface.warn()(tex.shader().path, "inputs:st is connected to " + reader.shader().path + " ('" + reader.id() +
                                              "'), not a UsdPrimvarReader_float2; reading the primvar st");
        return;
    }
    desc.uvPrimvar = reader.text("varname", "");
    copyInto(reader.tuple("fallback", {0.0f, 0.0f}), desc.uvFallback);
}

std::optional<render::InputBinding> textureBinding(const ShaderInputs& surface, const DrivableInput& input,
                                                   const NodeOutput& node) {
    ShaderInputs tex = surface.node(*node.shader);
    auto [first, count] = outputChannels(node.output);
    if (first < 0) {
        surface.warn()(node.shader->path,
                       "UsdUVTexture has no output '" + node.output + "'; input " + input.name + " ignores it");
        return std::nullopt;
    }
    render::InputBinding b;
    b.input = input.target;
    b.firstChannel = first;
    b.channels = std::min(count, input.channels);
    render::TextureDesc& desc = b.texture.emplace();
    desc.file = tex.text("file", "");
    desc.wrapS = wrapOf(tex, "wrapS");
    desc.wrapT = wrapOf(tex, "wrapT");
    copyInto(tex.tuple("fallback", {0.0f, 0.0f, 0.0f, 1.0f}), desc.fallback);
    copyInto(tex.tuple("scale", {1.0f, 1.0f, 1.0f, 1.0f}), desc.scale);
    copyInto(tex.tuple("bias", {0.0f, 0.0f, 0.0f, 0.0f}), desc.bias);
    desc.colorSpace = colorSpaceOf(tex);
    readTextureCoordinates(surface, tex, desc);
    if (desc.file.empty())
        surface.warn()(node.shader->path, "UsdUVTexture has no inputs:file; using its fallback");
    else if (!assetFileExists(desc.file)) {
        surface.warn()(node.shader->path, "texture file " + desc.file + " not found; using its fallback");
        desc.missing = true;  // the render core then takes the fallback without trying the file again
    }
    return b;
}

// MaterialX's address modes (uaddressmode, vaddressmode) as wrap modes.
texture::Wrap addressModeOf(const ShaderInputs& image, const char* input) {
    const std::string mode = image.text(input, "periodic");
    if (mode == "constant") return texture::Wrap::Black;
    if (mode == "clamp") return texture::Wrap::Clamp;
    if (mode == "mirror") return texture::Wrap::Mirror;
    if (mode != "periodic")
        image.warn()(image.shader().path,
                     std::string("inputs:") + input + " '" + mode + "' is not an address mode; using periodic");
    return texture::Wrap::Repeat;
}

// How a MaterialX image's file becomes rendering-space values: its colorSpace metadata (set on
// colour images only, scene/mtlx_reader.h) names a colour space of the OCIO config, converted
// from when the texture is opened (an unknown one is a texture error there, named); no colour
// space means data, read as stored.
void readMtlxColorSpace(const ShaderInputs& image, render::TextureDesc& desc) {
    const std::string space =
        PrimReader(image.shader(), image.time()).attributeMetadata("inputs:file", "colorSpace").value_or("");
    desc.colorSpace = space == "srgb_texture" ? texture::SourceColorSpace::SRGB : texture::SourceColorSpace::Raw;
    if (!space.empty() && space != "srgb_texture" && space != "lin_rec709" && space != "raw")
        desc.colorSpaceName = space;
}

// MaterialX's filtertype: closest, linear (the default) or cubic.
texture::Filter filterOf(const ShaderInputs& image) {
    const std::string filter = image.text("filtertype", "linear");
    if (filter == "closest") return texture::Filter::Closest;
    if (filter == "cubic") return texture::Filter::Cubic;
    if (filter != "linear")
        image.warn()(image.shader().path,
                     "inputs:filtertype '" + filter + "' is not closest, linear or cubic; using linear");
    return texture::Filter::Linear;
}

// A MaterialX tiledimage's placement, as MaterialX's own graph for it computes it: st' = (st *
// uvtiling - uvoffset) / realworldimagesize * realworldtilesize.
void readTiling(const ShaderInputs& image, render::UvTransform& uv) {
    const std::vector<float> tiling = image.tuple("uvtiling", {1.0f, 1.0f}),
                             offset = image.tuple("uvoffset", {0.0f, 0.0f}),
                             imageSize = image.tuple("realworldimagesize", {1.0f, 1.0f}),
                             tileSize = image.tuple("realworldtilesize", {1.0f, 1.0f});
    for (int i = 0; i < 2; ++i) {
        const float size = tileSize[i] / imageSize[i];
        uv.scale[i] = tiling[i] * size;
        uv.translation[i] = -offset[i] * size;
    }
}

// A MaterialX image node (ND_image_<type>) or tiled image (ND_tiledimage_<type>): file, default,
// filtertype, uaddressmode/vaddressmode (images) or the tiling (tiled images, which repeat), and
// the mesh's primary UV set ("st") as its texcoord. Its output `out` has the node type's channels.
std::optional<render::InputBinding> mtlxImageBinding(const ShaderInputs& surface, const DrivableInput& input,
                                                     const usd::PrimSpec& node) {
    ShaderInputs image = surface.node(node);
    if (image.connectedNode("texcoord"))
        image.warn()(node.path, "inputs:texcoord is connected; reading the primary UV set st instead");
    const std::string id = image.id();
    const std::string type = id.substr(id.find_last_of('_') + 1);
    const int channels = type == "float" ? 1 : type == "vector2" ? 2 : type == "color4" || type == "vector4" ? 4 : 3;
    render::InputBinding b;
    b.input = input.target;
    b.firstChannel = 0;
    b.channels = std::min(std::min(channels, 3), input.channels);
    render::TextureDesc& desc = b.texture.emplace();
    desc.file = image.text("file", "");
    if (id.starts_with("ND_tiledimage_")) {
        readTiling(image, desc.uvTransform);
    } else {
        desc.wrapS = addressModeOf(image, "uaddressmode");
        desc.wrapT = addressModeOf(image, "vaddressmode");
    }
    desc.filter = filterOf(image);
    const std::vector<float> fallback = image.tuple("default", std::vector<float>(std::size_t(channels), 0.0f));
    for (std::size_t c = 0; c < 4; ++c)
        desc.fallback[c] = c < fallback.size() ? fallback[c] : channels == 1 ? fallback[0] : 1.0f;
    readMtlxColorSpace(image, desc);
    if (desc.file.empty())
        surface.warn()(node.path, "image has no inputs:file; using its default");
    else if (!assetFileExists(desc.file)) {
        surface.warn()(node.path, "texture file " + desc.file + " not found; using its default");
        desc.missing = true;  // the render core then takes the default without trying the file again
    }
    return b;
}

// A MaterialX normalmap (ND_normalmap) of an image: the image's binding, decoded from [0, 1] to a
// tangent-space normal, (2 t - 1) (scale, scale, 1).
std::optional<render::InputBinding> mtlxNormalMapBinding(const ShaderInputs& surface, const DrivableInput& input,
                                                         const usd::PrimSpec& node) {
    ShaderInputs normalMap = surface.node(node);
    if (const std::string space = normalMap.text("space", "tangent"); space != "tangent")
        normalMap.warn()(node.path, "inputs:space '" + space + "' is not supported; reading the map in tangent space");
    std::optional<NodeOutput> source = normalMap.connectedNode("in");
    const std::string sourceId = source ? surface.node(*source->shader).id() : "";
    if (!sourceId.starts_with("ND_image_") && !sourceId.starts_with("ND_tiledimage_")) {
        normalMap.warn()(node.path,
                         "inputs:in is not connected to an image or tiledimage node; the surface keeps its own normal");
        return std::nullopt;
    }
    std::optional<render::InputBinding> b = mtlxImageBinding(surface, input, *source->shader);
    const float s = normalMap.number("scale", 1.0f);
    const float scale[4] = {2.0f * s, 2.0f * s, 2.0f, 1.0f}, bias[4] = {-s, -s, -1.0f, 0.0f};
    std::copy(scale, scale + 4, b->texture->scale);
    std::copy(bias, bias + 4, b->texture->bias);
    return b;
}

std::optional<render::InputBinding> primvarBinding(const ShaderInputs& surface, const DrivableInput& input,
                                                   const NodeOutput& node, int components) {
    ShaderInputs reader = surface.node(*node.shader);
    render::InputBinding b;
    b.input = input.target;
    b.channels = std::min(components, input.channels);
    b.primvar = reader.text("varname", "");
    if (components == 1)
        b.primvarFallback[0] = b.primvarFallback[1] = b.primvarFallback[2] = reader.number("fallback", 0.0f);
    else
        copyInto(reader.tuple("fallback", {0.0f, 0.0f, 0.0f}), b.primvarFallback);
    return b;
}

// The binding of a node that reads a texture or a primvar (the leaves of delegate/shading_graph.h),
// or nullopt: a node Fluence does not evaluate is named, with the file it came from.
std::optional<render::InputBinding> leafBinding(const ShaderInputs& surface, const DrivableInput& input,
                                                const NodeOutput& node) {
    const std::string id = surface.node(*node.shader).id();
    if (id == "UsdUVTexture") return textureBinding(surface, input, node);
    if (id == "UsdPrimvarReader_float") return primvarBinding(surface, input, node, 1);
    if (id == "UsdPrimvarReader_float3" || id == "UsdPrimvarReader_normal" || id == "UsdPrimvarReader_vector" ||
        id == "UsdPrimvarReader_point")
        return primvarBinding(surface, input, node, 3);
    if (id.starts_with("ND_image_") || id.starts_with("ND_tiledimage_"))
        return mtlxImageBinding(surface, input, *node.shader);
    if (id == "ND_normalmap") return mtlxNormalMapBinding(surface, input, *node.shader);
    surface.warn()(surface.shader().path, std::string("input '") + input.name + "' is connected to " +
                                              node.shader->path + " ('" + id + "', from " + node.shader->location.file +
                                              "), a node Fluence does not evaluate; using the input's own value");
    return std::nullopt;
}

}  // namespace

void readBindings(const ShaderInputs& surface, const std::vector<DrivableInput>& inputs,
                  render::MaterialDesc& material) {
    for (const DrivableInput& input : inputs) {
        std::optional<NodeOutput> node = surface.connectedNode(input.name);
        if (!node) continue;
        // Leaves keep every channel they have; the input takes the ones it needs below.
        const DrivableInput leafInput{input.name, input.target, 4, 1.0f};
        const LeafReader leaf = [&](const NodeOutput& n) { return leafBinding(surface, leafInput, n); };
        DrivenValue value = readDrivenValue(surface, input.name, *node, leaf);
        if (const ConstantValue* c = std::get_if<ConstantValue>(&value)) {
            float v[4];
            for (int k = 0; k < 4; ++k) v[k] = c->value[k] * input.factor;
            render::setMaterialInput(material, input.target, v, std::min(c->channels, input.channels));
        } else if (render::InputBinding* b = std::get_if<render::InputBinding>(&value)) {
            b->input = input.target;
            b->channels = std::min(b->channels, input.channels);
            b->factor *= input.factor;
            material.bindings.push_back(std::move(*b));
        }
    }
}

}  // namespace fluence::delegate
