#include "render/material_shader.h"

#include <algorithm>
#include <cmath>
#include <numbers>

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

// UsdTransform2d's linear part (scale, then rotation) applied to a 2-vector.
void transformLinear(const UvTransform& x, float v[2]) {
    float a = x.rotationDegrees * std::numbers::pi_v<float> / 180.0f;
    float s = v[0] * x.scale[0], t = v[1] * x.scale[1];
    v[0] = std::cos(a) * s - std::sin(a) * t;
    v[1] = std::sin(a) * s + std::cos(a) * t;
}

void writeInput(MaterialParams& p, MaterialInput input, const float* v, int channels) {
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
    }
}

}  // namespace

MaterialShader::MaterialShader(const MaterialDesc& material, texture::TextureSystem* textures,
                               std::vector<Warning>& warnings)
    : material_(&material), textures_(textures) {
    for (const InputBinding& b : material.bindings) {
        const texture::TextureSystem::Texture* opened = nullptr;
        if (b.texture && textures && !b.texture->file.empty()) {
            std::string error;
            opened = textures->open(b.texture->file, b.texture->colorSpace, error, b.texture->colorSpaceName);
            if (!opened) warnings.push_back({material.name, error + "; using the texture's fallback"});
        }
        opened_.push_back(opened);
        slots_.push_back(b.texture ? b.texture->uvPrimvar : b.primvar);
        if (tangentSlot_ < 0 && isTextureSlot(b) && !slots_.back().empty()) tangentSlot_ = static_cast<int>(slots_.size()) - 1;
    }
}

bool MaterialShader::mayBeTransparent() const {
    if (material_->opacity < 1.0f) return true;
    return std::any_of(material_->bindings.begin(), material_->bindings.end(),
                       [](const InputBinding& b) { return b.input == MaterialInput::Opacity; });
}

void MaterialShader::bindingValue(std::size_t i, const ShadingPatch& patch, const CornerPrimvar* primvar,
                                  float value[4]) const {
    const InputBinding& b = material_->bindings[i];
    if (!b.texture) {
        value[3] = 1.0f;
        if (!primvar) {
            std::copy(b.primvarFallback, b.primvarFallback + 3, value);
            return;
        }
        interpolateCorners(*primvar, patch, value);
        for (int c = primvar->components; c < 3; ++c) value[c] = primvar->components == 1 ? value[0] : 0.0f;
        return;
    }
    const TextureDesc& t = *b.texture;
    const texture::TextureSystem::Texture* opened = opened_[i];
    std::array<float, 4> texel{};
    bool found = false;
    if (opened) {
        const bool hasSt = primvar && primvar->components == 2;
        float st[2] = {t.uvFallback[0], t.uvFallback[1]};
        if (hasSt) interpolateCorners(*primvar, patch, st);
        transformLinear(t.uvTransform, st);
        st[0] += t.uvTransform.translation[0];
        st[1] += t.uvTransform.translation[1];
        texture::Footprint f;
        if (hasSt && patch.footprint.valid) {
            TriangleParameterisation tri = stParameterisation(*primvar, patch);
            float dx[2], dy[2];
            stAlong(tri, patch.footprint.dpdx, dx);
            stAlong(tri, patch.footprint.dpdy, dy);
            transformLinear(t.uvTransform, dx);
            transformLinear(t.uvTransform, dy);
            f = {dx[0], dx[1], dy[0], dy[1]};
        }
        found = textures_->lookup(*opened, st[0], st[1], f, t.wrapS, t.wrapT, texel);
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
    if (tangentSt && tangentSt->components == 2) {
        TriangleParameterisation tri = stParameterisation(*tangentSt, patch);
        tangent = perpendicularTo(dpds(tri), shadingNormal);
        bitangent = dpdt(tri);
    }
    for (std::size_t i = 0; i < material_->bindings.size(); ++i) {
        const InputBinding& b = material_->bindings[i];
        float value[4];
        bindingValue(i, patch, primvars[i], value);
        for (float& x : value) x *= b.factor;
        const float* v = value + std::clamp(b.firstChannel, 0, 4 - b.channels);
        if (b.input != MaterialInput::Normal) {
            writeInput(out, b.input, v, b.channels);
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

float MaterialShader::presence(const ShadingPatch& patch, const CornerPrimvar* const* primvars) const {
    float opacity = material_->opacity;
    for (std::size_t i = 0; i < material_->bindings.size(); ++i) {
        const InputBinding& b = material_->bindings[i];
        if (b.input != MaterialInput::Opacity) continue;
        float value[4];
        bindingValue(i, patch, primvars[i], value);
        opacity = value[std::clamp(b.firstChannel, 0, 3)];
    }
    if (material_->opacityThreshold > 0.0f) return opacity >= material_->opacityThreshold ? 1.0f : 0.0f;
    return std::clamp(opacity, 0.0f, 1.0f);
}

}  // namespace fluence::render
