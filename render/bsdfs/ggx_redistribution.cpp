#include "render/bsdfs/ggx_redistribution.h"

#include <cmath>

#include "render/bsdfs/albedo_table.h"
#include "render/bsdfs/ggx_albedo.h"
#include "render/bsdfs/local_geometry.h"

namespace fluence::render {

namespace {

using namespace albedo_table;

// The spreads of one (width, f0) node: kCosines x kCosines weights.
struct Slice {
    std::array<ElevationWeights, kCosines> spread{};

    Slice(int j, int f) {
        const float r = float(j) / (kWidths - 1);
        const GgxDistribution ggx(std::max(r * r, kGgxSmoothAlpha));
        for (int i = 0; i < kCosines; ++i) {
            const float mu = cosineAt(i);
            const Vec3f wo(std::sqrt(std::max(0.0f, 1.0f - mu * mu)), 0.0f, mu);
            ElevationBins bins;
            forEachVisibleNormal(ggx, wo, [&](const Vec3f& h, float jacobian) {
                const Vec3f wi = reflect(wo, h);
                if (wi.z <= 0.0f) return;
                const float pdf = ggx.reflectionPdf(wo, h);
                if (!(pdf > 0.0f)) return;
                bins.add(wi.z, double(ggxFacetReflectance(dot(wo, h), f0At(f))) * ggx.reflectionTerm(wo, wi, h) * wi.z /
                                   pdf * jacobian);
            });
            spread[i] = bins.spread(i);
        }
    }
};

const Slice& slice(int j, int f) { return albedo_table::sliceBuiltOnce<Slice, kWidths * kF0s>(j * kF0s + f, j, f); }

}  // namespace

ElevationWeights ggxReflectionSpread(int i, float alpha, float f0) {
    const AxisPosition w = positionOf(std::sqrt(std::max(alpha, 0.0f)), kWidths),
                       f = positionOf(std::sqrt(std::max(f0, 0.0f)), kF0s);
    const ElevationWeights &a = slice(w.node, f.node).spread[i], &b = slice(w.node + 1, f.node).spread[i],
                           &c = slice(w.node, f.node + 1).spread[i], &d = slice(w.node + 1, f.node + 1).spread[i];
    ElevationWeights spread;
    for (int k = 0; k < kCosines; ++k)
        spread[k] = lerp(lerp(a[k], b[k], w.fraction), lerp(c[k], d[k], w.fraction), f.fraction);
    return spread;
}

}  // namespace fluence::render
