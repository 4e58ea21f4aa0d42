// MixBsdf: a weighted blend of two BSDFs, (1 - w) a + w b.
//
// f and pdf blend linearly; sample() picks b with probability w (uLobe rescaled and handed on),
// then reports the blend's f and pdf for a non-delta direction, or the chosen delta lobe's
// coefficients scaled by its pick probability (so f |cos| / pdf keeps the lobe's weight). Each
// part keeps its own sidedness (render/bsdf.h, "SIDES"): a reflector blended with a transmitter
// (Standard Surface's opaque base and its glass, by `transmission`) is handed wo on either side,
// as the transmitter requires, and mirrors it itself, so from inside the glass the opaque part
// reflects back inside. Flags: the union of both. Path-class label: those of its parts.
#pragma once

#include <optional>

#include "render/bsdf.h"
#include "render/bsdfs/bsdf_checks.h"

namespace fluence::render {

class MixBsdf final : public Bsdf {
public:
    MixBsdf(const Bsdf& a, const Bsdf& b, float weightB) : a_(&a), b_(&b), w_(weightB) {}

    RGB f(const Vec3f& wo, const Vec3f& wi) const override { return a_->f(wo, wi) * (1.0f - w_) + b_->f(wo, wi) * w_; }
    float pdf(const Vec3f& wo, const Vec3f& wi) const override {
        return (1.0f - w_) * a_->pdf(wo, wi) + w_ * b_->pdf(wo, wi);
    }
    LobeSplit fByKind(const Vec3f& wo, const Vec3f& wi) const override {
        const LobeSplit a = a_->fByKind(wo, wi), b = b_->fByKind(wo, wi);
        return {a.diffuse * (1.0f - w_) + b.diffuse * w_, a.glossy * (1.0f - w_) + b.glossy * w_};
    }
    std::optional<BsdfSample> sample(const Vec3f& wo, float uLobe, Vec2f u) const override {
        const bool pickB = uLobe < w_;
        const float pick = pickB ? w_ : 1.0f - w_;
        if (!(pick > 0.0f)) return std::nullopt;
        const float rescaled = pickB ? uLobe / w_ : (uLobe - w_) / (1.0f - w_);
        std::optional<BsdfSample> s = (pickB ? b_ : a_)->sample(wo, std::min(rescaled, 0x1.fffffep-1f), u);
        if (!s) return std::nullopt;
        if (s->specular) {
            s->f = s->f * pick;
            s->pdf *= pick;
        } else {
            s->f = f(wo, s->wi);
            s->pdf = pdf(wo, s->wi);
        }
        dcheckSample(wo, s);
        return s;
    }
    unsigned flags() const override { return a_->flags() | b_->flags(); }

private:
    const Bsdf* a_;
    const Bsdf* b_;
    float w_;
};

}  // namespace fluence::render
