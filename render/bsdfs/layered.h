// LayeredBsdf<Top>: a reflecting lobe laid over a base BSDF by albedo scaling: the base receives,
// and returns, only the light the top lobe does not reflect.
//
//   f(wo, wi) = f_top(wo, wi) + a(wo) a(wi) f_base(wo, wi)
//   a(w)      = (1 - A(cos theta_w)) sqrt(filter)   for w on the layer's side (w.z > 0)
//             = 1                                  for w on the other side (a transmitting base)
//   A(cos)    = Top::reflectance(cos): the share of the light arriving at cos that the top
//               reflects (per channel, in [0, 1]), or a stand-in for it (see each Top)
//
// | parameter | meaning                                                                        |
// |-----------|--------------------------------------------------------------------------------|
// | top       | a reflection-only, two-sided model with reflectance(cos) (copied into the layer)|
// | base      | any Bsdf; it must outlive the layer (both live in the same BsdfArena)          |
// | filter    | per-channel transmittance of the layer, in [0, 1]: light that reaches the base |
// |           | and comes back out is multiplied by it once (sqrt(filter) per crossing)         |
//
// The "albedo scaling" of layered production models (Kulla & Conty 2017, "Revisiting Physically
// Based Shading at Imageworks"; the `layer` operator of MaterialX and Autodesk Standard Surface),
// applied to both directions so that the result stays reciprocal: f(wo, wi) = f(wi, wo) when the
// base is reciprocal, and the generalised reciprocity of a refracting base is kept because the
// factors depend on the two directions symmetrically. Energy: the flux albedo at wo is at most
// E_top(wo) + (1 - A(wo)) E_base <= 1 whenever the top's own albedo E_top(wo) does not exceed
// A(cos theta_o) (exactly so for a smooth top, whose A is its reflectance), because the base is
// weighted by (1 - A(wo)) and by a(wi) <= 1. What it gives up against a simulation of the layer:
// light that the top reflects back down onto the base, and the base's inter-reflection with the
// top's underside, are dropped rather than returned.
//
// Sides: over a reflection-only base the layer is two-sided (wo below the surface mirrors both
// directions, render/bsdf.h "SIDES"); over a transmitting base it is one-sided, on the outside
// (+z): the top lobe reflects only there, and light that leaves on the inside crosses no layer.
//
// Sampling: the top with probability P = lobeProbability(A(cos theta_o)) (render/bsdfs/lobe_choice.h)
// when wo is on the layer's side, else the base (its uLobe rescaled to [0, 1)). A non-delta sample
// returns the whole f and the mixture's pdf, P pdf_top + (1 - P) pdf_base; a delta sample of the
// top keeps its coefficient with pdf P times its own; a delta sample of the base is multiplied by
// a(wo) a(wi) with pdf (1 - P) times its own. Flags: the union of both parts'. Path-class label:
// those of its parts.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>

#include "render/bsdf.h"
#include "render/bsdfs/local_geometry.h"
#include "render/bsdfs/lobe_choice.h"

namespace fluence::render {

template <typename Top>
class LayeredBsdf : public Bsdf {
public:
    LayeredBsdf(const Top& top, const Bsdf& base, const RGB& filter = RGB(1.0f))
        : top_(top),
          base_(&base),
          sqrtFilter_(std::sqrt(filter.x), std::sqrt(filter.y), std::sqrt(filter.z)),
          twoSided_(!(base.flags() & kBsdfTransmission)) {}

    RGB f(const Vec3f& wo, const Vec3f& wi) const override {
        if (wo.z == 0.0f) return RGB(0.0f);
        if (mirrors(wo)) return f(mirrorZ(wo), mirrorZ(wi));
        RGB value = base_->f(wo, wi) * (throughput(wo) * throughput(wi));
        if (wo.z > 0.0f && wi.z > 0.0f) value += top_.f(wo, wi);
        return value;
    }

    LobeSplit fByKind(const Vec3f& wo, const Vec3f& wi) const override {
        if (wo.z == 0.0f) return {RGB(0.0f), RGB(0.0f)};
        if (mirrors(wo)) return fByKind(mirrorZ(wo), mirrorZ(wi));
        LobeSplit split = base_->fByKind(wo, wi);
        const RGB through = throughput(wo) * throughput(wi);
        split.diffuse *= through;
        split.glossy *= through;
        if (wo.z > 0.0f && wi.z > 0.0f) {
            const LobeSplit top = top_.fByKind(wo, wi);
            split.diffuse += top.diffuse;
            split.glossy += top.glossy;
        }
        return split;
    }

    float pdf(const Vec3f& wo, const Vec3f& wi) const override {
        if (wo.z == 0.0f) return 0.0f;
        if (mirrors(wo)) return pdf(mirrorZ(wo), mirrorZ(wi));
        const float pTop = topProbability(wo);
        float p = (1.0f - pTop) * base_->pdf(wo, wi);
        if (pTop > 0.0f && wi.z > 0.0f) p += pTop * top_.pdf(wo, wi);
        return p;
    }

    std::optional<BsdfSample> sample(const Vec3f& wo, float uLobe, Vec2f u) const override {
        if (wo.z == 0.0f) return std::nullopt;
        if (mirrors(wo)) {
            std::optional<BsdfSample> s = sample(mirrorZ(wo), uLobe, u);
            if (s) s->wi = mirrorZ(s->wi);
            return s;
        }
        const float pTop = topProbability(wo);
        const bool pickTop = uLobe < pTop;
        // The chosen part's own lobe number: uLobe rescaled to [0, 1) within the choice.
        const float uPart = std::min(pickTop ? uLobe / pTop : (uLobe - pTop) / (1.0f - pTop), 0x1.fffffep-1f);
        std::optional<BsdfSample> s = pickTop ? top_.sample(wo, uPart, u) : base_->sample(wo, uPart, u);
        if (!s) return std::nullopt;
        if (s->specular) {
            if (!pickTop) s->f *= throughput(wo) * throughput(s->wi);
            s->pdf *= pickTop ? pTop : 1.0f - pTop;
            return s;
        }
        s->pdf = pdf(wo, s->wi);
        if (!(s->pdf > 0.0f)) return std::nullopt;
        s->f = f(wo, s->wi);
        return s;
    }

    unsigned flags() const override { return base_->flags() | top_.flags(); }

private:
    bool mirrors(const Vec3f& wo) const { return twoSided_ && wo.z < 0.0f; }
    // The share of the light crossing the layer at w that is neither reflected by the top nor
    // absorbed by the filter; 1 on the side without the layer.
    RGB throughput(const Vec3f& w) const {
        return w.z > 0.0f ? (RGB(1.0f) - top_.reflectance(w.z)) * sqrtFilter_ : RGB(1.0f);
    }
    float topProbability(const Vec3f& wo) const { return wo.z > 0.0f ? lobeProbability(top_.reflectance(wo.z)) : 0.0f; }

    Top top_;
    const Bsdf* base_;
    RGB sqrtFilter_;
    bool twoSided_;
};

}  // namespace fluence::render
