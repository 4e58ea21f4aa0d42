// LayeredBsdf<Top>: a reflecting lobe laid over a base BSDF by albedo scaling: the base receives,
// and returns, only the light the top lobe does not reflect.
//
//   f(wo, wi) = f_top(wo, wi) + a(wo) a(wi) f_base(wo, wi)
//   a(w)      = (1 - A(w)) sqrt(filter)           for w on the layer's side (w.z > 0)
//             = 1                                  for w on the other side (a transmitting base)
//   A(w)      = Top::reflectance(w): the share of the light arriving from w that the top
//               reflects (per channel, in [0, 1]), or a stand-in for it (see each Top)
//
// | parameter | meaning                                                                        |
// |-----------|--------------------------------------------------------------------------------|
// | top       | a reflection-only, two-sided model with reflectance(w) (copied into the layer)  |
// | base      | any Bsdf; it must outlive the layer (both live in the same BsdfArena)          |
// | filter    | per-channel transmittance of the layer, in [0, 1]: light that reaches the base |
// |           | and comes back out is multiplied by it once (sqrt(filter) per crossing)         |
// | diffuse   | optional: the base is diffuse (Lambertian-like, direction-independent), with   |
// |           | the share `transmitted` of the light it sends to the other side (0 if opaque)  |
//
// The "albedo scaling" of layered production models (Kulla & Conty 2017, "Revisiting Physically
// Based Shading at Imageworks"; the `layer` operator of MaterialX and Autodesk Standard Surface),
// applied to both directions so that the result stays reciprocal: f(wo, wi) = f(wi, wo) when the
// base is reciprocal, and the generalised reciprocity of a refracting base is kept because the
// factors depend on the two directions symmetrically. Energy: the flux albedo at wo is at most
// E_top(wo) + (1 - A(wo)) E_base <= 1 whenever the top's own albedo E_top(wo) does not exceed
// A(wo) (exactly so for a smooth top, whose A is its reflectance), because the base is
// weighted by (1 - A(wo)) and by a(wi) <= 1. What it gives up against a simulation of the layer:
// light that the top reflects back down onto the base, and the base's inter-reflection with the
// top's underside, are dropped rather than returned.
//
// ENERGY-PRESERVING LAYERING over a diffuse base (Kulla & Conty 2017, section "energy
// compensation" applied to layering; Tops whose reflectance is the lobe's directional albedo E):
//
//   f(wo, wi) = f_top + (1 - A(wo)) (1 - A(wi)) f_base / (1 - Aavg)   wo, wi on the layer's side
//   f(wo, wi) = T Aavg / pi                                           wo, wi on the other side
//   Aavg      = 1/pi integral A(w) cos theta dw (Top::averageReflectance()), T = the base's transmitted share
//
// The base's reflection, which is direction-independent, loses 1 - Aavg of its light on the way
// out; dividing by it returns exactly what the top did not reflect: a base of albedo R and
// transmittance T gives the flux albedo A(wo) + (1 - A(wo)) (R + T), 1 for a lossless base,
// at every angle. Seen from the other side (light leaving a subsurface object), the share T Aavg
// that the layer sends back is reflected diffusely back in (the light a real interface returns by
// internal reflection), so that R + T (1 - Aavg) + T Aavg = 1 there too. Over other layers
// (a coat over the specular lobe over subsurface) only what they let through reaches the layer,
// and it sends back T times its reflectance averaged over that light
// (DiffuseBase::reachingAverage): with T Aavg each, a specular lobe and a coat reflected up to
// 1.020 of the light from inside, 1.048 with a sheen beneath them. Both terms are symmetric in
// wo and wi, so the layer stays reciprocal. What it approximates: the returned light
// leaves as the top's complement, not with the angular shape a simulation of the layer would give.
// Over a base that is not diffuse (a metal, glass, a blend with them) the division is not made:
// a glossy base concentrated where A is small could then reflect more than it receives.
//
// Sides: over a reflection-only base the layer is two-sided (wo below the surface mirrors both
// directions, render/bsdf.h "SIDES"); over a transmitting base it is one-sided, on the outside
// (+z): the top lobe reflects only there, and light that leaves on the inside crosses no layer.
//
// Sampling: the top with probability P = lobeProbability(A(wo)) (render/bsdfs/lobe_choice.h)
// when wo is on the layer's side, the inner diffuse reflection (cosine-weighted) with probability
// lobeProbability(T Aavg) when it is on the other side, else the base (its uLobe rescaled to
// [0, 1)). A non-delta sample
// returns the whole f and the mixture's pdf, P pdf_top + (1 - P) pdf_base; a delta sample of the
// top keeps its coefficient with pdf P times its own; a delta sample of the base is multiplied by
// a(wo) a(wi) with pdf (1 - P) times its own. Flags: the union of both parts'. Path-class label:
// those of its parts.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>

#include "core/sampling.h"
#include "render/bsdf.h"
#include "render/bsdfs/local_geometry.h"
#include "render/bsdfs/lobe_choice.h"

namespace fluence::render {

// What a layer may know of its base beyond its Bsdf: that it is diffuse, and the share of the
// light it transmits diffusely to the other side (per channel; 0 for an opaque base).
struct DiffuseBase {
    RGB transmitted = RGB(0.0f);
    // false when the base's reflection on the layer's side is not diffuse (a glossy layer lies
    // over the diffuse base, and the light lost to it is returned another way,
    // render/bsdfs/coat_return.h): the layer then keeps only the inner reflection of the
    // transmitted share, and does not normalise the reflection.
    bool reflectsDiffusely = true;
    // The top's reflectance averaged over the light that reaches it from the other side, per unit
    // of `transmitted`: unset when the base lets that light out diffusely (Aavg); over other
    // layers, the average weighted by what they let through (render/material_bsdf.cpp), so that
    // the layers together send back in exactly what none of them lets out.
    std::optional<RGB> reachingAverage = std::nullopt;
};

template <typename Top>
class LayeredBsdf : public Bsdf {
public:
    LayeredBsdf(const Top& top, const Bsdf& base, const RGB& filter = RGB(1.0f),
                const std::optional<DiffuseBase>& diffuse = std::nullopt)
        : top_(top),
          base_(&base),
          sqrtFilter_(std::sqrt(filter.x), std::sqrt(filter.y), std::sqrt(filter.z)),
          twoSided_(!(base.flags() & kBsdfTransmission)) {
        if (!diffuse) return;
        const RGB average = top_.averageReflectance();
        if (diffuse->reflectsDiffusely)
            reflectionScale_ =
                RGB(1.0f / (1.0f - std::min(average.x, kMaxAverage)), 1.0f / (1.0f - std::min(average.y, kMaxAverage)),
                    1.0f / (1.0f - std::min(average.z, kMaxAverage)));
        if (!twoSided_) innerReflection_ = diffuse->transmitted * diffuse->reachingAverage.value_or(average);
    }

    RGB f(const Vec3f& wo, const Vec3f& wi) const final {
        if (wo.z == 0.0f) return RGB(0.0f);
        if (mirrors(wo)) return f(mirrorZ(wo), mirrorZ(wi));
        return f(outgoing(wo), wi);
    }

    std::pair<RGB, float> fAndPdf(const Vec3f& wo, const Vec3f& wi) const final {
        if (wo.z == 0.0f) return {RGB(0.0f), 0.0f};
        if (mirrors(wo)) return fAndPdf(mirrorZ(wo), mirrorZ(wi));
        const Outgoing o = outgoing(wo);
        return {f(o, wi), pdf(o, wi)};
    }

    LobeSplit fByKind(const Vec3f& wo, const Vec3f& wi) const override {
        if (wo.z == 0.0f) return {RGB(0.0f), RGB(0.0f)};
        if (mirrors(wo)) return fByKind(mirrorZ(wo), mirrorZ(wi));
        LobeSplit split = base_->fByKind(wo, wi);
        const RGB weight = baseWeight(outgoing(wo), wi);
        split.diffuse *= weight;
        split.glossy *= weight;
        if (wo.z > 0.0f && wi.z > 0.0f) {
            const LobeSplit top = top_.fByKind(wo, wi);
            split.diffuse += top.diffuse;
            split.glossy += top.glossy;
        }
        if (wo.z < 0.0f && wi.z < 0.0f) split.diffuse += innerReflection_ * kInvPi;
        return split;
    }

    float pdf(const Vec3f& wo, const Vec3f& wi) const final {
        if (wo.z == 0.0f) return 0.0f;
        if (mirrors(wo)) return pdf(mirrorZ(wo), mirrorZ(wi));
        return pdf(outgoing(wo), wi);
    }

    std::optional<BsdfSample> sample(const Vec3f& wo, float uLobe, Vec2f u) const override {
        if (wo.z == 0.0f) return std::nullopt;
        if (mirrors(wo)) {
            std::optional<BsdfSample> s = sample(mirrorZ(wo), uLobe, u);
            if (s) s->wi = mirrorZ(s->wi);
            return s;
        }
        const Outgoing o = outgoing(wo);
        const float pOwn = ownProbability(o);
        const bool pickOwn = uLobe < pOwn;
        // The chosen part's own lobe number: uLobe rescaled to [0, 1) within the choice.
        const float uPart = std::min(pickOwn ? uLobe / pOwn : (uLobe - pOwn) / (1.0f - pOwn), 0x1.fffffep-1f);
        std::optional<BsdfSample> s = !pickOwn      ? base_->sample(wo, uPart, u)
                                      : wo.z > 0.0f ? top_.sample(wo, uPart, u)
                                                    : innerSample(u);
        if (!s) return std::nullopt;
        if (s->specular) {
            if (!pickOwn) s->f *= baseWeight(o, s->wi);
            s->pdf *= pickOwn ? pOwn : 1.0f - pOwn;
            return s;
        }
        s->pdf = pdf(o, s->wi);
        if (!(s->pdf > 0.0f)) return std::nullopt;
        s->f = f(o, s->wi);
        return s;
    }

    unsigned flags() const override { return base_->flags() | top_.flags(); }

private:
    // Keeps 1 / (1 - Aavg) finite for a top that reflects (almost) everything.
    static constexpr float kMaxAverage = 0.999f;

    bool mirrors(const Vec3f& wo) const { return twoSided_ && wo.z < 0.0f; }
    // wo (not 0, not mirrored) with the top's reflectance there, 0 below the layer (read only
    // above it): f, pdf and sample all read it, so sample() computes it once for its own choice,
    // the pdf and the f of the direction it samples, and fAndPdf() once for both (a table lookup
    // per channel).
    struct Outgoing {
        Vec3f w;
        RGB reflectance;
    };
    Outgoing outgoing(const Vec3f& wo) const { return {wo, wo.z > 0.0f ? top_.reflectance(wo) : RGB(0.0f)}; }
    RGB f(const Outgoing& o, const Vec3f& wi) const {
        const Vec3f& wo = o.w;
        RGB value = base_->f(wo, wi) * baseWeight(o, wi);
        if (wo.z > 0.0f && wi.z > 0.0f) value += top_.f(wo, wi);
        if (wo.z < 0.0f && wi.z < 0.0f) value += innerReflection_ * kInvPi;
        return value;
    }
    float pdf(const Outgoing& o, const Vec3f& wi) const {
        const Vec3f& wo = o.w;
        const float pOwn = ownProbability(o);
        float p = (1.0f - pOwn) * base_->pdf(wo, wi);
        if (pOwn > 0.0f && wo.z > 0.0f && wi.z > 0.0f) p += pOwn * top_.pdf(wo, wi);
        if (pOwn > 0.0f && wo.z < 0.0f && wi.z < 0.0f) p += pOwn * cosineHemispherePdf(-wi.z);
        return p;
    }
    // The share of the light crossing the layer at w, whose top reflectance is `reflectance`,
    // that is neither reflected by the top nor absorbed by the filter; 1 on the side without the
    // layer.
    RGB throughput(const Vec3f& w, const RGB& reflectance) const {
        return w.z > 0.0f ? (RGB(1.0f) - reflectance) * sqrtFilter_ : RGB(1.0f);
    }
    // The factor on the base's f: the throughputs both ways, and the normalisation of a diffuse
    // base's reflection on the layer's side.
    RGB baseWeight(const Outgoing& o, const Vec3f& wi) const {
        const RGB through = throughput(o.w, o.reflectance) * throughput(wi, outgoing(wi).reflectance);
        return o.w.z > 0.0f && wi.z > 0.0f ? through * reflectionScale_ : through;
    }
    // The probability of sampling the layer's own lobe: the top on its side, the inner
    // reflection on the other.
    float ownProbability(const Outgoing& o) const {
        return lobeProbability(o.w.z > 0.0f ? o.reflectance : innerReflection_);
    }
    std::optional<BsdfSample> innerSample(Vec2f u) const {
        const Vec3f wi = mirrorZ(sampleCosineHemisphere(u));
        return BsdfSample{innerReflection_ * kInvPi, wi, cosineHemispherePdf(-wi.z)};
    }

    Top top_;
    const Bsdf* base_;
    RGB sqrtFilter_;
    bool twoSided_;
    RGB reflectionScale_ = RGB(1.0f);
    RGB innerReflection_ = RGB(0.0f);
};

}  // namespace fluence::render
