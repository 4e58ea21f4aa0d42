#include "render/material_shader.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace fluence::render {

void interpolateCorners(const CornerPrimvar& primvar, const ShadingPatch& patch, float* out) {
    const std::size_t k = static_cast<std::size_t>(primvar.components);
    const float* c0 = &primvar.values[patch.corner * k];
    for (std::size_t i = 0; i < k; ++i) out[i] = c0[i] * patch.b0 + c0[k + i] * patch.b1 + c0[2 * k + i] * patch.b2;
}

TriangleParameterisation stParameterisation(const CornerPrimvar& primvar, const ShadingPatch& patch) {
    const float* c0 = &primvar.values[patch.corner * 2];
    return {patch.e1, patch.e2, {c0[2] - c0[0], c0[3] - c0[1]}, {c0[4] - c0[0], c0[5] - c0[1]}};
}

namespace {

bool isTextureSlot(const InputBinding& b) { return b.texture.has_value(); }

// Slot `slot`'s primvar at the patch: evaluated already (curves), or interpolated over the corners.
void primvarAtPatch(const CornerPrimvar& primvar, const ShadingPatch& patch, std::size_t slot, float* out) {
    if (patch.atPoint)
        std::copy(patch.atPoint[slot], patch.atPoint[slot] + primvar.components, out);
    else
        interpolateCorners(primvar, patch, out);
}

// UsdTransform2d's linear part (scale, then rotation) applied to a 2-vector.
void transformLinear(const UvTransform& x, float v[2]) {
    float a = x.rotationDegrees * std::numbers::pi_v<float> / 180.0f;
    float s = v[0] * x.scale[0], t = v[1] * x.scale[1];
    v[0] = std::cos(a) * s - std::sin(a) * t;
    v[1] = std::sin(a) * s + std::cos(a) * t;
}

// A graph source's value as the graph sees it: its channels from firstChannel, one replicated.
void graphChannels(const InputBinding& b, const float v[4], float out[4]) {
    const int first = b.firstChannel;
    for (int c = 0; c < 4; ++c) out[c] = b.channels == 1 ? v[first] : first + c < 4 ? v[first + c] : 0.0f;
}

}  // namespace

void setMaterialInput(MaterialParams& p, MaterialInput input, const float* v, int channels) {
    RGB colour = channels == 1 ? RGB(v[0]) : RGB(v[0], v[1], v[2]);
    switch (input) {
        case MaterialInput::Diffuse: p.diffuse = colour; break;
        case MaterialInput::Emission: p.emission = colour; break;
        case MaterialInput::SpecularColor: p.specularColor = colour; break;
        case MaterialInput::CoatColor: p.coatColor = colour; break;
        case MaterialInput::TransmissionColor: p.transmissionColor = colour; break;
        case MaterialInput::SheenColor: p.sheenColor = colour; break;
        case MaterialInput::Specular: p.specular = v[0]; break;
        case MaterialInput::Metallic: p.metallic = v[0]; break;
        case MaterialInput::Roughness: p.roughness = v[0]; break;
        case MaterialInput::Ior: p.ior = v[0]; break;
        case MaterialInput::Coat: p.coat = v[0]; break;
        case MaterialInput::CoatRoughness: p.coatRoughness = v[0]; break;
        case MaterialInput::Transmission: p.transmission = v[0]; break;
        case MaterialInput::Sheen: p.sheen = v[0]; break;
        case MaterialInput::Opacity: p.opacity = v[0]; break;
        case MaterialInput::Normal: break;  // not a parameter: evaluate() perturbs the normal
        case MaterialInput::Displacement: p.displacement = v[0]; break;
    }
}

namespace {

// Checks that a graph can be evaluated in order on the stack.
void checkGraph(const MaterialDesc& material, const InputBinding& b) {
    auto fail = [&](const std::string& why) { throw std::invalid_argument(material.name + ": shading graph " + why); };
    if (b.nodes.size() > kMaxShadingNodes) fail("has more than " + std::to_string(kMaxShadingNodes) + " nodes");
    for (const InputBinding& source : b.sources)
        if (!source.nodes.empty() || source.firstChannel < 0 || source.firstChannel > 3 || source.channels < 1 ||
            source.channels > 4)
            fail("has a source that is not one texture or primvar with channels from 0 to 3");
    const int operandCount[] = {0, 0, 2, 3};  // by ShadingNode::Op
    for (std::size_t n = 0; n < b.nodes.size(); ++n) {
        const ShadingNode& node = b.nodes[n];
        if (node.op == ShadingNode::Op::Source && (node.source < 0 || std::size_t(node.source) >= b.sources.size()))
            fail("node " + std::to_string(n) + " reads a source that is not there");
        for (int k = 0; k < operandCount[static_cast<int>(node.op)]; ++k)
            if (node.operands[k] < 0 || std::size_t(node.operands[k]) >= n)
                fail("node " + std::to_string(n) + " has an operand that is not an earlier node");
    }
}

}  // namespace

MaterialShader::MaterialShader(const MaterialDesc& material, texture::TextureSystem* textures,
                               std::vector<Warning>& warnings)
    : material_(&material), textures_(textures) {
    for (const InputBinding& binding : material.bindings) {
        checkGraph(material, binding);
        firstSource_.push_back(sources_.size());
        forEachSource(binding, [&](const InputBinding& b) {
            const texture::TextureSystem::Texture* opened = nullptr;
            if (b.texture && textures && !b.texture->file.empty() && !b.texture->missing) {
                std::string error;
                opened = textures->open(b.texture->file, b.texture->colorSpace, error, b.texture->colorSpaceName);
                if (!opened) warnings.push_back({material.name, error + "; using the texture's fallback"});
            }
            sources_.push_back({&b, opened});
            slots_.push_back(b.texture ? b.texture->uvPrimvar : b.primvar);
            if (tangentSlot_ < 0 && isTextureSlot(b) && !slots_.back().empty())
                tangentSlot_ = static_cast<int>(slots_.size()) - 1;
        });
    }
}

bool MaterialShader::mayBeTransparent() const { return material_->opacity < 1.0f || drives(MaterialInput::Opacity); }

void MaterialShader::bindingValue(std::size_t i, const ShadingPatch& patch, const CornerPrimvar* const* primvars,
                                  float value[4]) const {
    const InputBinding& b = material_->bindings[i];
    const std::size_t first = firstSource_[i];
    if (b.nodes.empty()) {
        sourceValue(first, patch, primvars[first], value);
    } else {
        float values[kMaxShadingNodes][4];
        for (std::size_t n = 0; n < b.nodes.size(); ++n) {
            const ShadingNode& node = b.nodes[n];
            float* out = values[n];
            const float *x = values[std::max(node.operands[0], 0)], *y = values[std::max(node.operands[1], 0)],
                        *m = values[std::max(node.operands[2], 0)];
            switch (node.op) {
                case ShadingNode::Op::Constant: std::copy(node.constant, node.constant + 4, out); break;
                case ShadingNode::Op::Source: {
                    const std::size_t s = first + std::size_t(node.source);
                    float v[4];
                    sourceValue(s, patch, primvars[s], v);
                    graphChannels(*sources_[s].binding, v, out);
                    for (int c = 0; c < 4; ++c) out[c] *= sources_[s].binding->factor;
                    break;
                }
                case ShadingNode::Op::Multiply:
                    for (int c = 0; c < 4; ++c) out[c] = x[c] * y[c];
                    break;
                case ShadingNode::Op::Mix:  // x the foreground, y the background, m the amount of x
                    for (int c = 0; c < 4; ++c) out[c] = y[c] * (1.0f - m[c]) + x[c] * m[c];
                    break;
            }
        }
        std::copy(values[b.nodes.size() - 1], values[b.nodes.size() - 1] + 4, value);
    }
    for (int c = 0; c < 4; ++c) value[c] *= b.factor;
}

void MaterialShader::sourceValue(std::size_t s, const ShadingPatch& patch, const CornerPrimvar* primvar,
                                 float value[4]) const {
    const InputBinding& b = *sources_[s].binding;
    if (!b.texture) {
        value[3] = 1.0f;
        if (!primvar) {
            std::copy(b.primvarFallback, b.primvarFallback + 3, value);
            return;
        }
        primvarAtPatch(*primvar, patch, s, value);
        for (int c = primvar->components; c < 3; ++c) value[c] = primvar->components == 1 ? value[0] : 0.0f;
        return;
    }
    const TextureDesc& t = *b.texture;
    const texture::TextureSystem::Texture* opened = sources_[s].opened;
    std::array<float, 4> texel{};
    bool found = false;
    if (opened) {
        const bool hasSt = primvar && primvar->components == 2;
        float st[2] = {t.uvFallback[0], t.uvFallback[1]};
        if (hasSt) primvarAtPatch(*primvar, patch, s, st);
        transformLinear(t.uvTransform, st);
        st[0] += t.uvTransform.translation[0];
        st[1] += t.uvTransform.translation[1];
        texture::Footprint f;
        if (hasSt && patch.footprint.valid && !patch.atPoint) {
            TriangleParameterisation tri = stParameterisation(*primvar, patch);
            float dx[2], dy[2];
            stAlong(tri, patch.footprint.dpdx, dx);
            stAlong(tri, patch.footprint.dpdy, dy);
            transformLinear(t.uvTransform, dx);
            transformLinear(t.uvTransform, dy);
            f = {dx[0], dx[1], dy[0], dy[1]};
        }
        found = textures_->lookup(*opened, st[0], st[1], f, t.wrapS, t.wrapT, texel, t.filter);
    }
    for (int c = 0; c < 4; ++c) value[c] = found ? texel[c] * t.scale[c] + t.bias[c] : t.fallback[c];
}

namespace {

// The unit component of v perpendicular to unit n (zero when v is parallel to n or zero).
Vec3f perpendicularTo(const Vec3f& v, const Vec3f& n) {
    Vec3f p = v - n * dot(v, n);
    return lengthSquared(p) > 1e-20f ? normalize(p) : Vec3f(0.0f);
}

}  // namespace

void MaterialShader::evaluate(const ShadingPatch& patch, const CornerPrimvar* const* primvars, MaterialParams& out,
                              Vec3f& shadingNormal, Vec3f& tangent) const {
    out = *material_;
    tangent = Vec3f(0.0f);
    Vec3f bitangent(0.0f);
    const CornerPrimvar* tangentSt = tangentSlot_ >= 0 ? primvars[tangentSlot_] : nullptr;
    if (tangentSt && tangentSt->components == 2 && !patch.atPoint) {
        TriangleParameterisation tri = stParameterisation(*tangentSt, patch);
        tangent = perpendicularTo(dpds(tri), shadingNormal);
        bitangent = dpdt(tri);
    }
    for (std::size_t i = 0; i < material_->bindings.size(); ++i) {
        const InputBinding& b = material_->bindings[i];
        float value[4];
        bindingValue(i, patch, primvars, value);
        const float* v = value + std::clamp(b.nodes.empty() ? b.firstChannel : 0, 0, 4 - b.channels);
        if (b.input != MaterialInput::Normal) {
            setMaterialInput(out, b.input, v, b.channels);
            continue;
        }
        // A tangent-space normal: x along dp/ds, y along dp/dt (mirrored st flips it), z along the normal.
        if (b.channels != 3 || lengthSquared(tangent) <= 0.0f) continue;
        Vec3f side = cross(shadingNormal, tangent);
        if (dot(side, bitangent) < 0.0f) side = -side;
        Vec3f n = tangent * v[0] + side * v[1] + shadingNormal * v[2];
        if (lengthSquared(n) > 0.0f) shadingNormal = normalize(n);
    }
    if (lengthSquared(tangent) > 0.0f) tangent = perpendicularTo(tangent, shadingNormal);
}

const InputBinding* MaterialShader::drivenValue(MaterialInput input, const ShadingPatch& patch,
                                                const CornerPrimvar* const* primvars, float value[4]) const {
    const InputBinding* driving = nullptr;
    for (std::size_t i = 0; i < material_->bindings.size(); ++i) {
        const InputBinding& b = material_->bindings[i];
        if (b.input != input) continue;
        float all[4];
        bindingValue(i, patch, primvars, all);
        const int first = std::clamp(b.nodes.empty() ? b.firstChannel : 0, 0, 4 - b.channels);
        for (int c = 0; c < 4; ++c) value[c] = first + c < 4 ? all[first + c] : 0.0f;
        driving = &b;
    }
    return driving;
}

float MaterialShader::presence(const ShadingPatch& patch, const CornerPrimvar* const* primvars) const {
    float value[4];
    const float opacity = drivenValue(MaterialInput::Opacity, patch, primvars, value) ? value[0] : material_->opacity;
    if (material_->opacityThreshold > 0.0f) return opacity >= material_->opacityThreshold ? 1.0f : 0.0f;
    return std::clamp(opacity, 0.0f, 1.0f);
}

bool MaterialShader::drives(MaterialInput input) const {
    return std::any_of(material_->bindings.begin(), material_->bindings.end(),
                       [input](const InputBinding& b) { return b.input == input; });
}

RGB MaterialShader::emission(const ShadingPatch& patch, const CornerPrimvar* const* primvars) const {
    float value[4];
    const InputBinding* driving = drivenValue(MaterialInput::Emission, patch, primvars, value);
    if (!driving) return material_->emission;
    MaterialParams p;
    setMaterialInput(p, MaterialInput::Emission, value, driving->channels);
    return p.emission;
}

}  // namespace fluence::render
