#include "render/bsdfs/sheen_redistribution.h"

#include <algorithm>
#include <cmath>

#include "render/bsdfs/albedo_table.h"
#include "render/bsdfs/sheen.h"

namespace fluence::render {

namespace {

using namespace albedo_table;

// The spreads of one roughness node: kCosines x kCosines weights.
struct Slice {
    std::array<ElevationWeights, kCosines> spread{};

    explicit Slice(int j) {
        const CharlieSheenBsdf lobe(RGB(1.0f), sheenRoughnessAt(j));
        for (int i = 0; i < kCosines; ++i) {
            const float mu = cosineAt(i);
            const Vec3f wo(std::sqrt(std::max(0.0f, 1.0f - mu * mu)), 0.0f, mu);
            ElevationBins bins;
            forEachSheenQuadraturePoint(
                [&](const Vec3f& wi, float weight) { bins.add(wi.z, double(lobe.f(wo, wi).x) * wi.z * weight); });
            spread[i] = bins.spread(i);
        }
    }
};

const Slice& slice(int j) { return sliceBuiltOnce<Slice, kSheenRoughnesses>(j, j); }

}  // namespace

ElevationWeights sheenReflectionSpread(int i, float roughness) {
    const float r = std::clamp(roughness, kSheenMinRoughness, 1.0f);
    const AxisPosition p = positionOf((r - kSheenMinRoughness) / (1.0f - kSheenMinRoughness), kSheenRoughnesses);
    const ElevationWeights &a = slice(p.node).spread[i], &b = slice(p.node + 1).spread[i];
    ElevationWeights spread;
    for (int k = 0; k < kCosines; ++k) spread[k] = lerp(a[k], b[k], p.fraction);
    return spread;
}

}  // namespace fluence::render
