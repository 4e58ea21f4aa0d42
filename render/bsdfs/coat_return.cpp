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

// The coated stack with the light it loses returned as lobes symmetric in wo and wi; what the
// stack transmits is the stack's own, and the inside of a stack over an interior is left as is.
class ReturnedLightBsdf final : public Bsdf {
public:
    ReturnedLightBsdf(const Bsdf& stack, const CoatReturn::Lobes& lobes)
        : stack_(&stack), lobes_(lobes), twoSided_(!(stack.flags() & kBsdfTransmission)) {}

    unsigned flags() const override { return stack_->flags() | kBsdfReflection | lobes_.kinds; }
    RGB f(const Vec3f& wo, const Vec3f& wi) const override { return stack_->f(wo, wi) + returned(wo, wi); }
    LobeSplit fByKind(const Vec3f& wo, const Vec3f& wi) const override {
        LobeSplit split = stack_->fByKind(wo, wi);
        const RGB light = returned(wo, wi);
        if (isBlack(light)) return split;
        const RGB diffuse = light * diffuseShare(wo, wi);
        split.diffuse += diffuse;
        split.glossy += light - diffuse;
        return split;
    }
    float pdf(const Vec3f& wo, const Vec3f& wi) const override {
        const float p = returnProbability(wo);
        const float stack = (1.0f - p) * stack_->pdf(wo, wi);
        if (wo.z == 0.0f || wi.z == 0.0f || (twoSided_ && wo.z * wi.z < 0.0f)) return stack;
        const float crossing = lobes_.crossingProbability[sideOf(wo)];
        return stack + p * (wo.z * wi.z > 0.0f ? 1.0f - crossing : crossing) * cosineHemispherePdf(std::abs(wi.z));
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
        // On wo's side, or (a sheet's returned light) on the other with the crossing probability.
        const bool crosses = uLobe / p < lobes_.crossingProbability[sideOf(wo)];
        const Vec3f wi = sampleCosineHemisphere(u);
        return whole(wo, (wo.z > 0.0f) != crosses ? wi : mirrorZ(wi), 1.0f);
    }

private:
    // The side of the stack w is on, as the returned lobes see it: 0 on the coat's side (+z, and
    // both sides of a two-sided stack), 1 on the other.
    int sideOf(const Vec3f& w) const { return w.z > 0.0f || twoSided_ ? 0 : 1; }
    RGB lossAt(int side, float mu) const {
        const CoatReturn::NodeValues& loss = lobes_.loss[side];
        const AxisPosition p = positionOf(mu, kCosines);
        return loss[p.node] + (loss[p.node + 1] - loss[p.node]) * p.fraction;
    }
    RGB returned(const Vec3f& wo, const Vec3f& wi) const {
        if (wo.z == 0.0f || wi.z == 0.0f) return RGB(0.0f);
        const bool sameSide = wo.z * wi.z > 0.0f;
        if (twoSided_ && !sameSide) return RGB(0.0f);
        const int side = sideOf(wo), exit = sameSide ? side : 1 - side;
        return (sameSide ? lobes_.same[side] : lobes_.crossed) * lossAt(side, std::abs(wo.z)) *
               lossAt(exit, std::abs(wi.z));
    }
    // The share of the returned light between wo and wi labelled diffuse (coat_return.h, LABELS).
    RGB diffuseShare(const Vec3f& wo, const Vec3f& wi) const {
        const int side = sideOf(wo), exit = wo.z * wi.z > 0.0f ? side : 1 - side;
        return side == exit ? lobes_.diffuseShare[side] : (lobes_.diffuseShare[0] + lobes_.diffuseShare[1]) * 0.5f;
    }
    float returnProbability(const Vec3f& wo) const { return lobeProbability(lossAt(sideOf(wo), std::abs(wo.z))); }
    std::optional<BsdfSample> whole(const Vec3f& wo, const Vec3f& wi, float eta) const {
        const float density = pdf(wo, wi);
        if (!(density > 0.0f)) return std::nullopt;
        return BsdfSample{f(wo, wi), wi, density, false, eta};
    }

    const Bsdf* stack_;
    CoatReturn::Lobes lobes_;
    bool twoSided_;
};

}  // namespace

CoatReturn::CoatReturn(const std::array<float, kCosines>& coatAlbedo) : coatAlbedo_(coatAlbedo) {}

void CoatReturn::addMeetingCoat(NodeValues& into, NodeValues* shapedInto, float weight,
                                FunctionRef<ElevationWeights(int)> spreadFrom, const NodeValues& lobe,
                                const NodeValues& g, const RGB& scale) const {
    NodeValues coatTimesG;
    for (int i = 0; i < kCosines; ++i) coatTimesG[i] = g[i] * coatAlbedo_[i];
    const RGB diffuseShare = scale * rgbCosineWeightedAverage(coatTimesG);
    for (int i = 0; i < kCosines; ++i) {
        const ElevationWeights spread = spreadFrom(i);
        float meetsCoat = 0.0f;
        for (int k = 0; k < kCosines; ++k) meetsCoat += spread[k] * coatAlbedo_[k];
        into[i] += (lobe[i] * meetsCoat + g[i] * diffuseShare) * weight;
        if (shapedInto) (*shapedInto)[i] += g[i] * diffuseShare * weight;
    }
}

void CoatReturn::addPart(float weight, FunctionRef<ElevationWeights(int)> spreadFrom, const NodeValues& lobe,
                         const NodeValues& g, const RGB& scale, ShapedLobe shaped) {
    addMeetingCoat(returned_, shaped == ShapedLobe::Diffuse ? &returnedDiffuse_ : nullptr, weight, spreadFrom, lobe, g,
                   scale);
    const RGB gAverage = rgbCosineWeightedAverage(g);
    for (int i = 0; i < kCosines; ++i) reflectance_[i] += (lobe[i] + scale * g[i] * gAverage) * weight;
    updateLobes();
}

void CoatReturn::addSheetPart(float weight, FunctionRef<ElevationWeights(int)> spreadFrom, const NodeValues& reflected,
                              const NodeValues& straight, const NodeValues& g, const RGB& reflectedScale,
                              const RGB& transmittedScale) {
    addPart(weight, spreadFrom, reflected, g, reflectedScale, ShapedLobe::Glossy);
    const auto atItsOwnElevation = [](int i) {
        ElevationWeights spread{};
        spread[i] = 1.0f;
        return spread;
    };
    addMeetingCoat(returnedBelow_, nullptr, weight, atItsOwnElevation, straight, g, transmittedScale);
    const RGB gAverage = rgbCosineWeightedAverage(g);
    for (int i = 0; i < kCosines; ++i) transmittance_[i] += (straight[i] + transmittedScale * g[i] * gAverage) * weight;
    updateLobes();
}

void CoatReturn::updateLobes() {
    // Keeps 1 / L finite for a side that loses (almost) nothing.
    constexpr float kMinAverage = 0.001f;
    for (int i = 0; i < kCosines; ++i) lobes_.loss[0][i] = returned_[i] * (1.0f - coatAlbedo_[i]);
    lobes_.loss[1] = returnedBelow_;
    NodeValues crossing;  // the front loss that leaves through the sheet, at each elevation
    for (int i = 0; i < kCosines; ++i)
        crossing[i] = lobes_.loss[0][i] * transmittance_[i] / (RGB(1.0f) - reflectance_[i] * coatAlbedo_[i]);
    const RGB front = rgbCosineWeightedAverage(lobes_.loss[0]), back = rgbCosineWeightedAverage(lobes_.loss[1]);
    const RGB exchanged = vmin(vmin(rgbCosineWeightedAverage(crossing), front), back);
    const RGB l0 = vmax(front, RGB(kMinAverage)), l1 = vmax(back, RGB(kMinAverage));
    // c_same = (1 - X / L) / L and c_crossed = X / (L L').
    lobes_.same = {(RGB(1.0f) - exchanged / l0) / l0, (RGB(1.0f) - exchanged / l1) / l1};
    lobes_.crossed = exchanged / (l0 * l1);
    NodeValues diffuseLoss;
    for (int i = 0; i < kCosines; ++i) diffuseLoss[i] = returnedDiffuse_[i] * (1.0f - coatAlbedo_[i]);
    const RGB share = vmin(rgbCosineWeightedAverage(diffuseLoss) / l0, RGB(1.0f));
    lobes_.diffuseShare = {share, RGB(0.0f)};
    const bool allDiffuse = share.x == 1.0f && share.y == 1.0f && share.z == 1.0f && isBlack(back);
    lobes_.kinds = (isBlack(share) ? 0u : kBsdfDiffuse) | (allDiffuse ? 0u : kBsdfGlossy);
    lobes_.crossingProbability = {std::clamp(lobeProbability(exchanged / l0), 0.0f, 1.0f),
                                  std::clamp(lobeProbability(exchanged / l1), 0.0f, 1.0f)};
}

const Bsdf& CoatReturn::compensate(const Bsdf& coated, const RGB& filter, BsdfArena& arena) const {
    CoatReturn::Lobes lobes = lobes_;
    for (RGB& c : lobes.same) c = filter * c * kInvPi;
    lobes.crossed = filter * lobes.crossed * kInvPi;
    return arena.make<ReturnedLightBsdf>(coated, lobes);
}

}  // namespace fluence::render
