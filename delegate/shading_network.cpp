#include "delegate/shading_network.h"

#include <algorithm>

#include "delegate/prim_reader.h"
#include "delegate/render_index.h"

namespace fluence::delegate {

namespace {

std::string idOf(const ShaderInputs& node) { return PrimReader(node.shader(), node.time()).token({"info:id"}, ""); }

ShaderInputs nodeInputs(const ShaderInputs& surface, const usd::PrimSpec& node) {
    return ShaderInputs(surface.stage(), node, surface.time(), surface.convertColor(), surface.warn());
}

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
    if (ShaderInputs transform = nodeInputs(surface, *node->shader); idOf(transform) == "UsdTransform2d") {
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
    ShaderInputs reader = nodeInputs(surface, *node->shader);
    if (idOf(reader) != "UsdPrimvarReader_float2") {
        surface.warn()(tex.shader().path, "inputs:st is connected to " + reader.shader().path + " ('" + idOf(reader) +
                                              "'), not a UsdPrimvarReader_float2; reading the primvar st");
        return;
    }
    desc.uvPrimvar = reader.text("varname", "");
    copyInto(reader.tuple("fallback", {0.0f, 0.0f}), desc.uvFallback);
}

std::optional<render::InputBinding> textureBinding(const ShaderInputs& surface, const DrivableInput& input,
                                                   const NodeOutput& node) {
    ShaderInputs tex = nodeInputs(surface, *node.shader);
    auto [first, count] = outputChannels(node.output);
    if (first < 0) {
        surface.warn()(node.shader->path, "UsdUVTexture has no output '" + node.output + "'; input " + input.name + " ignores it");
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
    else if (!assetFileExists(desc.file))
        surface.warn()(node.shader->path, "texture file " + desc.file + " not found; using its fallback");
    return b;
}

// MaterialX's address modes (uaddressmode, vaddressmode) as wrap modes.
texture::Wrap addressModeOf(const ShaderInputs& image, const char* input) {
    const std::string mode = image.text(input, "periodic");
    if (mode == "constant") return texture::Wrap::Black;
    if (mode == "clamp") return texture::Wrap::Clamp;
    if (mode == "mirror") return texture::Wrap::Mirror;
    if (mode != "periodic")
        image.warn()(image.shader().path, std::string("inputs:") + input + " '" + mode + "' is not an address mode; using periodic");
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
    if (!space.empty() && space != "srgb_texture" && space != "lin_rec709" && space != "raw") desc.colorSpaceName = space;
}

// A MaterialX image node (ND_image_<type>): file, default, uaddressmode/vaddressmode, and the
// mesh's primary UV set ("st") as its texcoord. Its output `out` has the node type's channels.
std::optional<render::InputBinding> mtlxImageBinding(const ShaderInputs& surface, const DrivableInput& input,
                                                     const usd::PrimSpec& node) {
    ShaderInputs image = nodeInputs(surface, node);
    if (image.connectedNode("texcoord"))
        image.warn()(node.path, "inputs:texcoord is connected; reading the primary UV set st instead");
    const std::string id = idOf(image);
    const std::string type = id.substr(id.find_last_of('_') + 1);
    const int channels = type == "float" ? 1 : type == "vector2" ? 2 : type == "color4" || type == "vector4" ? 4 : 3;
    render::InputBinding b;
    b.input = input.target;
    b.firstChannel = 0;
    b.channels = std::min(std::min(channels, 3), input.channels);
    render::TextureDesc& desc = b.texture.emplace();
    desc.file = image.text("file", "");
    desc.wrapS = addressModeOf(image, "uaddressmode");
    desc.wrapT = addressModeOf(image, "vaddressmode");
    const std::vector<float> fallback = image.tuple("default", std::vector<float>(std::size_t(channels), 0.0f));
    for (std::size_t c = 0; c < 4; ++c) desc.fallback[c] = c < fallback.size() ? fallback[c] : channels == 1 ? fallback[0] : 1.0f;
    readMtlxColorSpace(image, desc);
    if (desc.file.empty())
        surface.warn()(node.path, "image has no inputs:file; using its default");
    else if (!assetFileExists(desc.file))
        surface.warn()(node.path, "texture file " + desc.file + " not found; using its default");
    return b;
}

// A MaterialX normalmap (ND_normalmap) of an image: the image's binding, decoded from [0, 1] to a
// tangent-space normal, (2 t - 1) (scale, scale, 1).
std::optional<render::InputBinding> mtlxNormalMapBinding(const ShaderInputs& surface, const DrivableInput& input,
                                                         const usd::PrimSpec& node) {
    ShaderInputs normalMap = nodeInputs(surface, node);
    if (const std::string space = normalMap.text("space", "tangent"); space != "tangent")
        normalMap.warn()(node.path, "inputs:space '" + space + "' is not supported; reading the map in tangent space");
    std::optional<NodeOutput> source = normalMap.connectedNode("in");
    if (!source || !idOf(nodeInputs(surface, *source->shader)).starts_with("ND_image_")) {
        normalMap.warn()(node.path, "inputs:in is not connected to an image node; the surface keeps its own normal");
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
    ShaderInputs reader = nodeInputs(surface, *node.shader);
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

}  // namespace

void readBindings(const ShaderInputs& surface, const std::vector<DrivableInput>& inputs,
                  std::vector<render::InputBinding>& bindings) {
    for (const DrivableInput& input : inputs) {
        std::optional<NodeOutput> node = surface.connectedNode(input.name);
        if (!node) continue;
        std::string id = idOf(nodeInputs(surface, *node->shader));
        std::optional<render::InputBinding> b;
        if (id == "UsdUVTexture")
            b = textureBinding(surface, input, *node);
        else if (id == "UsdPrimvarReader_float")
            b = primvarBinding(surface, input, *node, 1);
        else if (id == "UsdPrimvarReader_float3" || id == "UsdPrimvarReader_normal" || id == "UsdPrimvarReader_vector" ||
                 id == "UsdPrimvarReader_point")
            b = primvarBinding(surface, input, *node, 3);
        else if (id.starts_with("ND_image_"))
            b = mtlxImageBinding(surface, input, *node->shader);
        else if (id == "ND_normalmap")
            b = mtlxNormalMapBinding(surface, input, *node->shader);
        else
            surface.warn()(surface.shader().path, std::string("input '") + input.name + "' is connected to " +
                                                      node->shader->path + " ('" + id + "', from " +
                                                      node->shader->location.file +
                                                      "), a node Fluence does not evaluate; using the input's own value");
        if (b) bindings.push_back(std::move(*b));
    }
}

}  // namespace fluence::delegate
