#include "render/material_bsdf.h"

#include <algorithm>
#include <cmath>

#include "render/bsdfs/coated.h"
#include "render/bsdfs/ggx_conductor.h"
#include "render/bsdfs/lambertian.h"
#include "render/bsdfs/mix.h"

namespace fluence::render {

namespace {

// The relative IOR whose normal-incidence Fresnel reflectance is f0 (clamped away from 1).
float etaFromF0(float f0) {
    float s = std::sqrt(std::clamp(f0, 0.0f, 0.99f));
    return (1.0f + s) / (1.0f - s);
}

float alphaOf(float roughness) { return std::clamp(roughness, 0.0f, 1.0f) * std::clamp(roughness, 0.0f, 1.0f); }

}  // namespace

const Bsdf& materialBsdf(const MaterialParams& m, BsdfArena& arena) {
    const RGB& albedo = m.diffuse;
    const Bsdf* bsdf = &arena.make<LambertianBsdf>(albedo);
    const float alpha = alphaOf(m.roughness);
    const bool dielectricSpecular = m.specularWorkflow ? !isBlack(m.specularColor) : m.specular > 0.0f;
    if (dielectricSpecular) {
        float eta = m.specularWorkflow ? etaFromF0(luminance(m.specularColor)) : m.ior;
        if (eta > 1.0f + 1e-4f) bsdf = &arena.make<CoatedBsdf>(*bsdf, eta, alpha);
    }
    if (m.metallic > 0.0f) {
        const Bsdf& metal = arena.make<GgxConductorBsdf>(albedo, alpha);
        bsdf = m.metallic >= 1.0f ? &metal : &arena.make<MixBsdf>(*bsdf, metal, m.metallic);
    }
    if (m.coat > 0.0f && m.coatIor > 1.0f + 1e-4f) {
        const Bsdf& coated = arena.make<CoatedBsdf>(*bsdf, m.coatIor, alphaOf(m.coatRoughness));
        bsdf = m.coat >= 1.0f ? &coated : &arena.make<MixBsdf>(*bsdf, coated, m.coat);
    }
    return *bsdf;
}

}  // namespace fluence::render
