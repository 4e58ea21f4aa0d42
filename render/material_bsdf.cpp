#include "render/material_bsdf.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <type_traits>

#include "render/bsdfs/albedo_table.h"
#include "render/bsdfs/coat_return.h"
#include "render/bsdfs/coated.h"
#include "render/bsdfs/fresnel.h"
#include "render/bsdfs/ggx_albedo.h"
#include "render/bsdfs/ggx_conductor.h"
#include "render/bsdfs/ggx_dielectric_albedo.h"
#include "render/bsdfs/ggx_dielectric_multiple_scattering.h"
#include "render/bsdfs/ggx_redistribution.h"
#include "render/bsdfs/ggx_multiple_scattering.h"
#include "render/bsdfs/hair.h"
#include "render/bsdfs/lambertian.h"
#include "render/bsdfs/lambertian_transmission.h"
#include "render/bsdfs/oren_nayar.h"
#include "render/bsdfs/layered.h"
#include "render/bsdfs/mix.h"
#include "render/bsdfs/sheen.h"
#include "render/bsdfs/sheen_redistribution.h"
#include "render/bsdfs/thin_dielectric.h"
#include "render/bsdfs/thin_dielectric_albedo.h"
#include "render/bsdfs/thin_dielectric_multiple_scattering.h"

namespace fluence::render {

namespace {

// Below this index difference an interface reflects nothing worth a layer (F0 < 2e-9).
constexpr float kMinIndexContrast = 1e-4f;

RGB clamp01(const RGB& c) {
    return {std::clamp(c.x, 0.0f, 1.0f), std::clamp(c.y, 0.0f, 1.0f), std::clamp(c.z, 0.0f, 1.0f)};
}

// The sheen's colour (sheen x sheenColor, clamped): black when the sheen layer is off.
RGB sheenTint(const MaterialParams& m) { return clamp01(m.sheenColor * m.sheen); }
// Whether the clear coat is laid over the rest (weight above 0, and an interface that reflects).
bool coatOn(const MaterialParams& m) { return m.coat > 0.0f && m.coatIor > 1.0f + kMinIndexContrast; }
RGB sqrtOf(const RGB& c) { return {std::sqrt(c.x), std::sqrt(c.y), std::sqrt(c.z)}; }

// `weight` of `b` blended over `a`: a alone at 0, b alone at 1.
const Bsdf& blend(const Bsdf& a, const Bsdf& b, float weight, BsdfArena& arena) {
    return weight >= 1.0f ? b : arena.make<MixBsdf>(a, b, weight);
}

// The dielectric specular lobe: its index per channel and the tint on its reflection.
struct SpecularLobe {
    RGB eta;
    RGB tint;
    bool reflects() const { return maxComponent(eta) > 1.0f + kMinIndexContrast && !isBlack(tint); }
};
SpecularLobe specularLobe(const MaterialParams& m) {
    // A black F0 is an index of 1 (what etaFromF0 gives), found without the square roots.
    if (m.specularWorkflow && !(maxComponent(m.specularColor) > 0.0f)) return {RGB(1.0f), RGB(1.0f)};
    if (m.specularWorkflow)  // specularColor is F0: one index per channel, no further tint
        return {RGB(etaFromF0(m.specularColor.x), etaFromF0(m.specularColor.y), etaFromF0(m.specularColor.z)),
                RGB(1.0f)};
    return {RGB(m.ior), clamp01(m.specularColor * m.specular)};
}

// The microfacet distribution of the specular, glass and metal lobes; made only by the lobes
// that are on (a plain diffuse material needs none).
GgxDistribution specularGgx(const MaterialParams& m) {
    return GgxDistribution::fromRoughness(m.roughness, m.anisotropy);
}

// The tint on the glass's reflection: the specular lobe's (none in the specular workflow).
RGB glassReflectionTint(const MaterialParams& m) {
    return m.specularWorkflow ? RGB(1.0f) : clamp01(m.specularColor * m.specular);
}

// The transmissive dielectric that replaces the opaque base by `transmission`: a solid interface
// of index ior (the transmission colour split over its two crossings; rough, it keeps its
// multiple scattering), or a thin sheet.
const Bsdf& transmissionBsdf(const MaterialParams& m, BsdfArena& arena) {
    const GgxDistribution ggx = specularGgx(m);
    const RGB colour = clamp01(m.transmissionColor);
    const RGB reflection = glassReflectionTint(m);
    if (m.thinWalled) return energyCompensatedThinDielectric(m.ior, ggx, DielectricTints{reflection, colour}, arena);
    return energyCompensatedDielectric(m.ior, ggx, DielectricTints{reflection, sqrtOf(colour)}, arena);
}

// A direction at the mu node i of the albedo tables, in the xz plane.
Vec3f nodeDirection(int i) {
    const float mu = albedo_table::cosineAt(i);
    return {std::sqrt(std::max(0.0f, 1.0f - mu * mu)), 0.0f, mu};
}

// Each thread's last four results of a pure function of `key` (one cache per call site: the
// lambda's type makes the instance): neighbouring hits of one object share their parameters, so a
// result worth tens of table reads per hit is computed once per object and thread. Pure functions
// only, so the images do not depend on what a thread has seen.
template <typename Key, typename Compute>
const auto& remembered(const Key& key, Compute&& compute) {
    using Value = std::invoke_result_t<Compute>;
    struct Entry {
        Key key;
        Value value;
    };
    thread_local std::array<std::optional<Entry>, 4> entries;
    thread_local std::size_t next = 0;
    for (const std::optional<Entry>& e : entries)
        if (e && e->key == key) return e->value;
    std::optional<Entry>& slot = entries[next];
    next = (next + 1) % entries.size();
    slot.emplace(Entry{key, compute()});
    return slot->value;
}

// The light the diffuse base lets through to the other side (subsurface), as the layers laid over
// it see it (render/bsdfs/layered.h, DiffuseBase::reachingAverage): it leaves the base
// diffusely, and each layer passes on, at each mu node, the share 1 - A(mu) it does not reflect.
// Each layer sends back in T times its reflectance averaged over what reaches it, so that the
// layers together send back T minus what they all let out, however many they are.
//
// The layers of a material are laid in one order (sheen, specular lobe, coat: sheenAndSpecular,
// clearCoat), each a function of the material's parameters, so the n-th layer's average and what
// passes it are a function of (those parameters, n): remembered by that key, as a table read at 32
// nodes per layer is too much to redo at every hit.
class LightFromBelow {
public:
    LightFromBelow(const DiffuseBase& base, const MaterialParams& m) : base_(base) {
        if (isBlack(base_.transmitted)) return;  // nothing reaches the layers from below: no key needed
        key_ = {0.0f,
                m.sheen,
                m.sheenColor.x,
                m.sheenColor.y,
                m.sheenColor.z,
                m.sheenRoughness,
                m.ior,
                m.specular,
                m.specularColor.x,
                m.specularColor.y,
                m.specularColor.z,
                float(m.specularWorkflow),
                m.roughness,
                m.anisotropy,
                m.coatIor,
                m.coatRoughness};
    }

    // The DiffuseBase of the layer `top` laid next (the material's next layer, in the order above);
    // what it lets through reaches the next one.
    template <typename Top>
    DiffuseBase under(const Top& top) {
        DiffuseBase layer = base_;
        if (isBlack(base_.transmitted)) return layer;
        key_[0] = float(layers_);
        const Passed& passed = remembered(key_, [&] {
            Passed p;
            if (reaching_)
                p.reaching = *reaching_;
            else
                p.reaching.fill(RGB(1.0f));  // what the base lets out reaches the first layer whole
            std::array<RGB, albedo_table::kCosines> reflected;
            for (int i = 0; i < albedo_table::kCosines; ++i) {
                const RGB a = top.reflectance(nodeDirection(i));
                reflected[i] = p.reaching[i] * a;
                p.reaching[i] *= RGB(1.0f) - a;
            }
            p.average = albedo_table::rgbCosineWeightedAverage(reflected);
            return p;
        });
        // The remembered entry is read by the next layer's computation only, before remembered()
        // replaces any entry with that layer's: it outlives the read.
        reaching_ = &passed.reaching;
        ++layers_;
        layer.reachingAverage = passed.average;
        return layer;
    }

private:
    struct Passed {
        RGB average;                                         // the layer's reachingAverage
        std::array<RGB, albedo_table::kCosines> reaching{};  // what reaches the next layer, per node
    };
    DiffuseBase base_;
    // The number of layers laid so far, then the parameters every layer's Passed depends on.
    std::array<float, 16> key_{};
    int layers_ = 0;
    const std::array<RGB, albedo_table::kCosines>* reaching_ = nullptr;  // what passed the last layer laid
};

// The layers over the diffuse base, as far as the specular coating: the sheen, then the
// dielectric lobe, each conserving energy over it (render/bsdfs/layered.h).
const Bsdf& sheenAndSpecular(const Bsdf& base, LightFromBelow& light, const MaterialParams& m, BsdfArena& arena) {
    const Bsdf* bsdf = &base;
    const RGB sheen = sheenTint(m);
    if (!isBlack(sheen)) {
        const CharlieSheenBsdf top(sheen, m.sheenRoughness);
        bsdf = &arena.make<LayeredBsdf<CharlieSheenBsdf>>(top, *bsdf, RGB(1.0f), light.under(top));
    }
    if (const SpecularLobe specular = specularLobe(m); specular.reflects()) {
        const GgxDistribution ggx = specularGgx(m);
        const DiffuseBase layer =
            light.under(DielectricReflectionBsdf(DielectricFresnel(specular.eta, specular.tint), ggx));
        bsdf = &arena.make<CoatedBsdf>(*bsdf, specular.eta, ggx, specular.tint, RGB(1.0f), layer);
    }
    return *bsdf;
}

// The albedo at each mu node of a reflecting lobe with reflectance(w), and its complement.
template <typename Lobe>
void nodeAlbedos(const Lobe& lobe, CoatReturn::NodeValues& albedo, CoatReturn::NodeValues& complement) {
    for (int i = 0; i < albedo_table::kCosines; ++i) {
        albedo[i] = lobe.reflectance(nodeDirection(i));
        complement[i] = RGB(1.0f) - albedo[i];
    }
}

// The opaque base's part (render/bsdfs/coat_return.h): the diffuse base's reflection (the share
// subsurface does not transmit) under the specular layer, or under the sheen when no specular
// layer reflects, or alone.
void addLayeredDiffusePart(CoatReturn& coatReturn, float weight, const MaterialParams& m, float alpha) {
    const RGB reflected = clamp01(m.diffuse) * (1.0f - std::min(m.subsurface, 1.0f));
    const SpecularLobe specular = specularLobe(m);
    const RGB sheen = sheenTint(m);
    CoatReturn::NodeValues lobe, complement;
    if (specular.reflects()) {
        const DielectricFresnel fresnel(specular.eta, specular.tint);
        const DielectricReflectionBsdf layer(fresnel, specularGgx(m));
        nodeAlbedos(layer, lobe, complement);
        coatReturn.addPart(
            weight, [&](int i) { return ggxReflectionSpread(i, alpha, fresnel.f0.x); }, lobe, complement,
            reflected / (RGB(1.0f) - layer.averageReflectance()), CoatReturn::ShapedLobe::Diffuse);
    } else if (!isBlack(sheen)) {
        const CharlieSheenBsdf layer(sheen, m.sheenRoughness);
        nodeAlbedos(layer, lobe, complement);
        coatReturn.addPart(
            weight, [&](int i) { return sheenReflectionSpread(i, m.sheenRoughness); }, lobe, complement,
            reflected / (RGB(1.0f) - layer.averageReflectance()), CoatReturn::ShapedLobe::Diffuse);
    } else {
        lobe.fill(RGB(0.0f));
        complement.fill(RGB(1.0f));
        coatReturn.addPart(
            weight, [](int) { return ElevationWeights{}; }, lobe, complement, reflected,
            CoatReturn::ShapedLobe::Diffuse);
    }
}

// Solid glass's part: its reflection from outside, single-scattering and, rough, the reflected
// part of its multiple-scattering lobe (render/bsdfs/ggx_dielectric_multiple_scattering.h).
void addGlassPart(CoatReturn& coatReturn, float weight, const MaterialParams& m, float alpha) {
    const GgxDistribution ggx = specularGgx(m);
    const RGB reflection = glassReflectionTint(m);
    const DielectricFresnel fresnel(RGB(m.ior), reflection);
    CoatReturn::NodeValues lobe, complement;
    nodeAlbedos(DielectricReflectionBsdf(fresnel, ggx), lobe, complement);
    RGB scale(0.0f);
    if (!ggx.isSmooth() && m.ior != 1.0f) {
        scale = reflection * CompensatedGgxDielectricBsdf(m.ior, ggx).outsideReflectionScale();
        for (int i = 0; i < albedo_table::kCosines; ++i)
            complement[i] = RGB(1.0f - ggxDielectricAlbedo(albedo_table::cosineAt(i), alpha, m.ior));
    }
    coatReturn.addPart(
        weight, [&](int i) { return ggxReflectionSpread(i, alpha, fresnel.f0.x); }, lobe, complement, scale,
        CoatReturn::ShapedLobe::Glossy);
}

// A thin-walled sheet's part: its reflection, single-scattering and, rough, the reflected part of
// its multiple-scattering lobe, and what it lets through from its other side, straight and, rough,
// by the transmitted part of that lobe (render/bsdfs/thin_dielectric_multiple_scattering.h).
void addSheetPart(CoatReturn& coatReturn, float weight, const MaterialParams& m, float alpha) {
    const bool smooth = specularGgx(m).isSmooth() || m.ior == 1.0f;
    const DielectricTints tints{glassReflectionTint(m), clamp01(m.transmissionColor)};
    CoatReturn::NodeValues reflected, straight, g;
    for (int i = 0; i < albedo_table::kCosines; ++i) {
        const float mu = albedo_table::cosineAt(i);
        // S and E (render/bsdfs/thin_dielectric_albedo.h); a smooth sheet scatters once, by R_s.
        const float through = smooth ? 1.0f - slabReflectance(mu, m.ior) : thinSheetStraightThrough(mu, alpha, m.ior);
        const float single = smooth ? 1.0f : thinSheetAlbedo(mu, alpha, m.ior);
        reflected[i] = tints.reflection * (single - through);
        straight[i] = tints.transmission * (RGB(1.0f) - tints.reflection * (1.0f - through));
        g[i] = RGB(1.0f - single);
    }
    const ThinSheetMultipleScattering lobe =
        smooth ? ThinSheetMultipleScattering{RGB(0.0f), RGB(0.0f)} : thinSheetMultipleScattering(m.ior, alpha, tints);
    coatReturn.addSheetPart(
        weight, [&](int i) { return ggxReflectionSpread(i, alpha, f0FromEta(m.ior)); }, reflected, straight, g,
        lobe.reflected, lobe.transmitted);
}

// The metal's part: its single scattering and its multiple-scattering lobe.
void addMetalPart(CoatReturn& coatReturn, float weight, const MaterialParams& m, float alpha, bool smooth) {
    const RGB f0 = m.diffuse, fAvg = (f0 * 20.0f + RGB(1.0f)) * (1.0f / 21.0f);
    CoatReturn::NodeValues lobe, complement;
    for (int i = 0; i < albedo_table::kCosines; ++i) {
        const float bare = ggxReflectionAlbedo(albedo_table::cosineAt(i), alpha, 1.0f);
        lobe[i] = fAvg * bare;
        complement[i] = RGB(1.0f - bare);
    }
    const float eAvg = ggxReflectionAverageAlbedo(alpha, 1.0f);
    coatReturn.addPart(
        weight, [&](int i) { return ggxReflectionSpread(i, alpha, 1.0f); }, lobe, complement,
        smooth ? RGB(0.0f) : multipleScatteringAlbedo(f0, eAvg) / (1.0f - eAvg), CoatReturn::ShapedLobe::Glossy);
}

// What the clear coat's underside returns to a base with a glossy part (a plastic's specular
// layer, a sheen, a metal, solid glass or a thin-walled sheet; render/bsdfs/coat_return.h), or
// nothing when the base is diffuse (the layer's normalisation returns it).
std::optional<CoatReturn> coatReturn(const MaterialParams& m, const DielectricReflectionBsdf& coat) {
    const bool layer = specularLobe(m).reflects() || !isBlack(sheenTint(m));
    const float metallic = std::min(m.metallic, 1.0f), transmission = std::min(m.transmission, 1.0f);
    if (!layer && !(metallic > 0.0f) && !(transmission > 0.0f)) return std::nullopt;
    std::array<float, albedo_table::kCosines> coatAlbedo;
    for (int i = 0; i < albedo_table::kCosines; ++i) coatAlbedo[i] = coat.reflectance(nodeDirection(i)).x;
    CoatReturn coatReturn(coatAlbedo);
    const GgxDistribution ggx = specularGgx(m);
    const float alpha = ggx.isSmooth() ? 0.0f : std::sqrt(ggx.alphaX() * ggx.alphaY());
    const float opaque = (1.0f - metallic) * (1.0f - transmission), glass = (1.0f - metallic) * transmission;
    if (opaque > 0.0f) addLayeredDiffusePart(coatReturn, opaque, m, alpha);
    if (glass > 0.0f && m.thinWalled) addSheetPart(coatReturn, glass, m, alpha);
    if (glass > 0.0f && !m.thinWalled) addGlassPart(coatReturn, glass, m, alpha);
    if (metallic > 0.0f) addMetalPart(coatReturn, metallic, m, alpha, ggx.isSmooth());
    return coatReturn;
}

// coatReturn(m, coat), remembered by the parameters it depends on: it costs some 30 microseconds
// (a few thousand table reads).
const std::optional<CoatReturn>& rememberedCoatReturn(const MaterialParams& m, const DielectricReflectionBsdf& coat) {
    using Key = std::array<float, 25>;
    const Key key = {m.coatIor,
                     m.coatRoughness,
                     m.ior,
                     m.specular,
                     m.specularColor.x,
                     m.specularColor.y,
                     m.specularColor.z,
                     m.roughness,
                     m.anisotropy,
                     m.metallic,
                     m.diffuse.x,
                     m.diffuse.y,
                     m.diffuse.z,
                     m.transmission,
                     m.subsurface,
                     float(m.specularWorkflow),
                     m.sheen,
                     m.sheenColor.x,
                     m.sheenColor.y,
                     m.sheenColor.z,
                     m.thinWalled ? 1.0f : 0.0f,
                     m.sheenRoughness,
                     m.transmissionColor.x,
                     m.transmissionColor.y,
                     m.transmissionColor.z};
    return remembered(key, [&] { return coatReturn(m, coat); });
}

// The clear coat over everything, by weight `coat`; `light` when what lies under it is the
// diffuse base and its layers alone (no metal, no glass). Over a glossy base (a specular layer, a
// sheen, a metal, glass) the light the coat returns is added back (render/bsdfs/coat_return.h).
const Bsdf& clearCoat(const Bsdf& under, LightFromBelow* light, const MaterialParams& m, BsdfArena& arena) {
    if (!coatOn(m)) return under;
    const GgxDistribution ggx = GgxDistribution::fromRoughness(m.coatRoughness);
    const RGB filter = clamp01(m.coatColor);
    const DielectricReflectionBsdf coat(RGB(m.coatIor), ggx);
    const std::optional<CoatReturn>& returned = rememberedCoatReturn(m, coat);
    std::optional<DiffuseBase> layer;
    if (light) layer = light->under(coat);
    // With the light returned, a diffuse base keeps only the coat's inner reflection.
    if (layer && returned) layer->reflectsDiffusely = false;
    const Bsdf& coated = arena.make<CoatedBsdf>(under, RGB(m.coatIor), ggx, RGB(1.0f), filter, layer);
    return blend(under, returned ? returned->compensate(coated, filter, arena) : coated, m.coat, arena);
}

// Whether every lobe over the diffuse base is off (no subsurface, sheen, specular lobe, glass,
// metal or coat): the material is its diffuse base alone, and materialBsdf() returns that base
// without laying the (empty) layers over it. A plain Lambertian wall is the common case, and
// the layers' bookkeeping cost it more than the BSDF itself (bench/results/2026-12-05-throughput-2.md).
bool diffuseBaseOnly(const MaterialParams& m) {
    return !(m.subsurface > 0.0f) && !(m.transmission > 0.0f) && !(m.metallic > 0.0f) && !coatOn(m) &&
           isBlack(sheenTint(m)) && !specularLobe(m).reflects();
}

}  // namespace

const Bsdf& materialBsdf(const MaterialParams& m, BsdfArena& arena, SubsurfaceShare subsurface) {
    if (m.hair) return arena.make<HairBsdf>(*m.hair);
    const Bsdf* bsdf = m.diffuseRoughness > 0.0f
                           ? static_cast<const Bsdf*>(&arena.make<OrenNayarBsdf>(m.diffuse, m.diffuseRoughness))
                           : &arena.make<LambertianBsdf>(m.diffuse);
    if (diffuseBaseOnly(m)) return *bsdf;
    DiffuseBase diffuse;
    if (m.subsurface > 0.0f) {  // a solid's walk inside gives the colour; a thin wall is tinted once
        const float weight = std::min(m.subsurface, 1.0f);
        if (subsurface == SubsurfaceShare::Diffuse && !m.thinWalled) {
            bsdf = &blend(*bsdf, arena.make<LambertianBsdf>(clamp01(m.subsurfaceColor)), weight, arena);
        } else {
            const RGB transmittance = m.thinWalled ? clamp01(m.subsurfaceColor) : RGB(1.0f);
            bsdf = &blend(*bsdf, arena.make<LambertianTransmissionBsdf>(transmittance), weight, arena);
            diffuse.transmitted = transmittance * weight;
        }
    }
    LightFromBelow light(diffuse, m);
    bsdf = &sheenAndSpecular(*bsdf, light, m, arena);
    if (m.transmission > 0.0f) bsdf = &blend(*bsdf, transmissionBsdf(m, arena), m.transmission, arena);
    if (m.metallic > 0.0f)
        bsdf = &blend(*bsdf, energyCompensatedConductor(m.diffuse, specularGgx(m), arena), m.metallic, arena);
    const bool diffuseUnder = !(m.transmission > 0.0f) && !(m.metallic > 0.0f);
    return clearCoat(*bsdf, diffuseUnder ? &light : nullptr, m, arena);
}

const Bsdf& subsurfaceExitBsdf(const MaterialParams& m, BsdfArena& arena) {
    const Bsdf& boundary = arena.make<LambertianTransmissionBsdf>(RGB(1.0f));
    LightFromBelow light(DiffuseBase{RGB(1.0f)}, m);
    return clearCoat(sheenAndSpecular(boundary, light, m, arena), &light, m, arena);
}

}  // namespace fluence::render
