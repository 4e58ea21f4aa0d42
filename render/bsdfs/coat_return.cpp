#include "render/bsdfs/coat_return.h"

#include <optional>

#include "render/bsdfs/ggx_redistribution.h"
#include "render/bsdfs/lambertian.h"
#include "render/bsdfs/layered.h"

namespace fluence::render {

namespace {

using namespace albedo_table;

// 2 integral v(mu) mu dmu of the piecewise-linear v through the nodes, per channel.
RGB averageOf(const CoatReturn::NodeValues& v) {
    return {cosineWeightedAverage([&](int i) { return v[i].x; }), cosineWeightedAverage([&](int i) { return v[i].y; }),
            cosineWeightedAverage([&](int i) { return v[i].z; })};
}

// The coated stack as the top of a LayeredBsdf: itself, with reflectance 1 - loss.
class LossyStack {
public:
    LossyStack(const Bsdf& stack, const CoatReturn::NodeValues& loss)
        : stack_(&stack), loss_(loss), average_(averageOf(loss)) {}

    unsigned flags() const { return stack_->flags(); }
    RGB f(const Vec3f& wo, const Vec3f& wi) const { return stack_->f(wo, wi); }
    LobeSplit fByKind(const Vec3f& wo, const Vec3f& wi) const { return stack_->fByKind(wo, wi); }
    float pdf(const Vec3f& wo, const Vec3f& wi) const { return stack_->pdf(wo, wi); }
    std::optional<BsdfSample> sample(const Vec3f& wo, float uLobe, Vec2f u) const {
        return stack_->sample(wo, uLobe, u);
    }
    RGB reflectance(const Vec3f& w) const {
        const AxisPosition p = positionOf(w.z, kCosines);
        return RGB(1.0f) - (loss_[p.node] + (loss_[p.node + 1] - loss_[p.node]) * p.fraction);
    }
    RGB averageReflectance() const { return RGB(1.0f) - average_; }

private:
    const Bsdf* stack_;
    CoatReturn::NodeValues loss_;
    RGB average_;
};

}  // namespace

CoatReturn::CoatReturn(const std::array<float, kCosines>& coatAlbedo) : coatAlbedo_(coatAlbedo) {}

void CoatReturn::addPart(float weight, float alpha, float f0, const NodeValues& lobe, const NodeValues& g,
                         const RGB& scale) {
    NodeValues coatTimesG;
    for (int i = 0; i < kCosines; ++i) coatTimesG[i] = g[i] * coatAlbedo_[i];
    const RGB diffuseShare = scale * averageOf(coatTimesG);
    for (int i = 0; i < kCosines; ++i) {
        const ElevationWeights spread = ggxReflectionSpread(i, alpha, f0);
        float meetsCoat = 0.0f;
        for (int k = 0; k < kCosines; ++k) meetsCoat += spread[k] * coatAlbedo_[k];
        returned_[i] += (lobe[i] * meetsCoat + g[i] * diffuseShare) * weight;
    }
}

const Bsdf& CoatReturn::compensate(const Bsdf& coated, const RGB& filter, BsdfArena& arena) const {
    NodeValues loss;
    for (int i = 0; i < kCosines; ++i) loss[i] = returned_[i] * (1.0f - coatAlbedo_[i]);
    return arena.make<LayeredBsdf<LossyStack>>(LossyStack(coated, loss), arena.make<LambertianBsdf>(filter), RGB(1.0f),
                                               DiffuseBase{});
}

}  // namespace fluence::render
