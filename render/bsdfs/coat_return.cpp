#include "render/bsdfs/coat_return.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "core/sampling.h"
#include "render/bsdfs/lobe_choice.h"
#include "render/bsdfs/local_geometry.h"

namespace fluence::render {

namespace {

using namespace albedo_table;

// 2 integral v(mu) mu dmu of the piecewise-linear v through the nodes, per channel.
RGB averageOf(const CoatReturn::NodeValues& v) {
    return {cosineWeightedAverage([&](int i) { return v[i].x; }), cosineWeightedAverage([&](int i) { return v[i].y; }),
            cosineWeightedAverage([&](int i) { return v[i].z; })};
}

// The coated stack with the light it loses returned as a lobe symmetric in wo and wi, on the
// coated side (+z, and its mirror when the stack is two-sided); what the stack transmits, and
// the inside of a transmitting stack, are the stack's alone.
class ReturnedLightBsdf final : public Bsdf {
public:
    ReturnedLightBsdf(const Bsdf& stack, const CoatReturn::NodeValues& loss, const RGB& filter)
        : stack_(&stack), loss_(loss), twoSided_(!(stack.flags() & kBsdfTransmission)) {
        const RGB average = averageOf(loss);
        scale_ = filter *
                 RGB(1.0f / std::max(average.x, kMinAverage), 1.0f / std::max(average.y, kMinAverage),
                     1.0f / std::max(average.z, kMinAverage)) *
                 kInvPi;
    }

    unsigned flags() const override { return stack_->flags() | kBsdfReflection | kBsdfDiffuse; }
    RGB f(const Vec3f& wo, const Vec3f& wi) const override { return stack_->f(wo, wi) + returned(wo, wi); }
    LobeSplit fByKind(const Vec3f& wo, const Vec3f& wi) const override {
        LobeSplit split = stack_->fByKind(wo, wi);
        split.diffuse += returned(wo, wi);
        return split;
    }
    float pdf(const Vec3f& wo, const Vec3f& wi) const override {
        const float p = returnProbability(wo);
        const Vec3f up = upper(wo, wi);
        return (1.0f - p) * stack_->pdf(wo, wi) + (up.z > 0.0f ? p * cosineHemispherePdf(up.z) : 0.0f);
    }
    std::optional<BsdfSample> sample(const Vec3f& wo, float uLobe, Vec2f u) const override {
        if (wo.z == 0.0f) return std::nullopt;
        const float p = returnProbability(wo);
        if (uLobe >= p) {
            std::optional<BsdfSample> s = stack_->sample(wo, std::min((uLobe - p) / (1.0f - p), 0x1.fffffep-1f), u);
            if (!s) return std::nullopt;
            if (s->specular) {
                s->pdf *= 1.0f - p;
                return s;
            }
            return whole(wo, s->wi, s->eta);
        }
        const Vec3f wi = sampleCosineHemisphere(u);
        return whole(wo, wo.z > 0.0f ? wi : mirrorZ(wi), 1.0f);
    }

private:
    // Keeps 1 / Lavg finite for a stack that loses (almost) nothing.
    static constexpr float kMinAverage = 0.001f;

    // wi seen from wo's side: mirrored when wo is below a two-sided stack; (0, 0, -1) when the
    // pair has no returned light (wo or wi on the uncoated side, or on different sides).
    Vec3f upper(const Vec3f& wo, const Vec3f& wi) const {
        const float sign = wo.z < 0.0f && twoSided_ ? -1.0f : 1.0f;
        return wo.z * sign > 0.0f && wi.z * sign > 0.0f ? Vec3f(wi.x, wi.y, wi.z * sign) : Vec3f(0.0f, 0.0f, -1.0f);
    }
    RGB lossAt(float mu) const {
        const AxisPosition p = positionOf(mu, kCosines);
        return loss_[p.node] + (loss_[p.node + 1] - loss_[p.node]) * p.fraction;
    }
    RGB returned(const Vec3f& wo, const Vec3f& wi) const {
        if (!(upper(wo, wi).z > 0.0f)) return RGB(0.0f);
        return scale_ * lossAt(std::abs(wo.z)) * lossAt(std::abs(wi.z));
    }
    float returnProbability(const Vec3f& wo) const {
        return wo.z > 0.0f || twoSided_ ? lobeProbability(lossAt(std::abs(wo.z))) : 0.0f;
    }
    std::optional<BsdfSample> whole(const Vec3f& wo, const Vec3f& wi, float eta) const {
        const float density = pdf(wo, wi);
        if (!(density > 0.0f)) return std::nullopt;
        return BsdfSample{f(wo, wi), wi, density, false, eta};
    }

    const Bsdf* stack_;
    CoatReturn::NodeValues loss_;
    bool twoSided_;
    RGB scale_;  // filter / (pi Lavg)
};

}  // namespace

CoatReturn::CoatReturn(const std::array<float, kCosines>& coatAlbedo) : coatAlbedo_(coatAlbedo) {}

void CoatReturn::addPart(float weight, FunctionRef<ElevationWeights(int)> spreadFrom, const NodeValues& lobe,
                         const NodeValues& g, const RGB& scale) {
    NodeValues coatTimesG;
    for (int i = 0; i < kCosines; ++i) coatTimesG[i] = g[i] * coatAlbedo_[i];
    const RGB diffuseShare = scale * averageOf(coatTimesG);
    for (int i = 0; i < kCosines; ++i) {
        const ElevationWeights spread = spreadFrom(i);
        float meetsCoat = 0.0f;
        for (int k = 0; k < kCosines; ++k) meetsCoat += spread[k] * coatAlbedo_[k];
        returned_[i] += (lobe[i] * meetsCoat + g[i] * diffuseShare) * weight;
    }
}

const Bsdf& CoatReturn::compensate(const Bsdf& coated, const RGB& filter, BsdfArena& arena) const {
    NodeValues loss;
    for (int i = 0; i < kCosines; ++i) loss[i] = returned_[i] * (1.0f - coatAlbedo_[i]);
    return arena.make<ReturnedLightBsdf>(coated, loss, filter);
}

}  // namespace fluence::render
