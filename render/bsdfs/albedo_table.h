// A directional albedo of GGX microfacets, tabulated over (mu, alpha, f0) and interpolated: the
// machinery behind render/bsdfs/ggx_albedo.h (reflection) and ggx_dielectric_albedo.h
// (reflection and transmission through an interface).
//
// The table holds 32 values of mu in [0, 1] (mu = 0 as seen at 1e-4) by 32 values of
// sqrt(alpha) (a material's roughness) in [0, 1] by 33 values of sqrt(f0) in [0, 1], all evenly
// spaced. A slice of one f0 is computed on first use by `Albedo(ggx, mu, f0)` at each of its
// (mu, alpha) nodes (its widths in parallel; render/material_tables.h builds a scene's slices
// before its render starts), and the table is interpolated linearly in each of the three. Eavg is
// integrated exactly from the same piecewise-linear E, so that a lobe weighted by 1 - E(mu) has
// exactly the cosine-weighted average 1 - Eavg whatever the table's own error against the true
// albedo. Widths above 1 are clamped to 1.
//
// visibleNormalQuadrature(ggx, wo, weight) is the quadrature the albedos use: the mean of
// weight(h) over GGX's visible normals of wo (Heitz 2018), by a 32 x 32-point midpoint rule with
// u.x = 1 - (1 - t)^4, so that the points crowd towards u.x = 1, where GGX's long tail sends the
// light below the horizon (1% of the visible normals at alpha 0.1, which evenly spaced points
// would step over).
#pragma once

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <memory>
#include <mutex>

#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/task_arena.h>

#include "core/rgb.h"
#include "render/bsdfs/ggx.h"

namespace fluence::render {

namespace albedo_table {

inline constexpr int kCosines = 32, kWidths = 32, kF0s = 33;
inline constexpr int kQuadrature = 32;      // points per dimension
inline constexpr float kMinCosine = 1e-4f;  // where the mu = 0 node is evaluated

inline float cosineAt(int i) { return std::max(float(i) / (kCosines - 1), kMinCosine); }
inline float f0At(int k) {
    const float s = float(k) / (kF0s - 1);
    return s * s;
}

// The storage of a table of N slices of type Slice: one per Slice type.
template <typename Slice, int N>
struct SliceStore {
    static inline std::array<std::once_flag, N> made;
    static inline std::array<std::unique_ptr<Slice>, N> slices;
    static inline std::array<std::atomic<const Slice*>, N> built{};  // slices[k] once it is complete
};

// Slice k of a table of N, built as Slice(args...) on first use, once, by whichever thread asks
// first; later calls return it without taking a lock, and without std::call_once (which sets up
// its callable in thread-local storage and calls pthread_once on every call, twice per lookup of
// a table that every glossy hit reads several times): one acquire load of the published slice.
template <typename Slice, int N, typename... Args>
const Slice& sliceBuiltOnce(int k, const Args&... args) {
    using Store = SliceStore<Slice, N>;
    if (const Slice* slice = Store::built[k].load(std::memory_order_acquire)) return *slice;
    std::call_once(Store::made[k], [&] {
        Store::slices[k] = std::make_unique<Slice>(args...);
        Store::built[k].store(Store::slices[k].get(), std::memory_order_release);
    });
    return *Store::slices[k];
}

// A position on an evenly spaced axis of n nodes over [0, 1]: the node below and the fraction.
struct AxisPosition {
    int node;
    float fraction;
};
inline AxisPosition positionOf(float x, int n) {
    const float scaled = std::clamp(x, 0.0f, 1.0f) * float(n - 1);
    const int node = std::min(int(scaled), n - 2);
    return {node, scaled - float(node)};
}

inline float lerp(float a, float b, float t) { return a + (b - a) * t; }

// 2 integral E mu dmu of the piecewise-linear E through the kCosines nodes E(i) = at(i) (exact
// for it), with the first node's value taken down to mu = 0.
template <typename At>
float cosineWeightedAverage(At at) {
    double sum = 0.0;
    for (int i = 0; i + 1 < kCosines; ++i) {
        const double a = double(i) / (kCosines - 1), b = double(i + 1) / (kCosines - 1);
        sum += (b - a) * (at(i) * (2.0 * a + b) + at(i + 1) * (a + 2.0 * b)) / 6.0;
    }
    return float(2.0 * sum);
}

// The same per channel, of RGB values at the nodes.
inline RGB rgbCosineWeightedAverage(const std::array<RGB, kCosines>& v) {
    return {cosineWeightedAverage([&](int i) { return v[i].x; }), cosineWeightedAverage([&](int i) { return v[i].y; }),
            cosineWeightedAverage([&](int i) { return v[i].z; })};
}

}  // namespace albedo_table

// Calls visit(h, w) at each point of the quadrature above: the visible normals h of wo (wo.z > 0)
// with their weights w (float), which sum to kQuadrature^2.
template <typename Visit>
void forEachVisibleNormal(const GgxDistribution& ggx, const Vec3f& wo, Visit visit) {
    using albedo_table::kQuadrature;
    for (int a = 0; a < kQuadrature; ++a) {
        const float t = 1.0f - (a + 0.5f) / kQuadrature;  // 1 - t of the comment above
        const float ux = 1.0f - t * t * t * t, jacobian = 4.0f * t * t * t;
        for (int b = 0; b < kQuadrature; ++b)
            visit(ggx.sampleVisibleNormal(wo, Vec2f(ux, (b + 0.5f) / kQuadrature)), jacobian);
    }
}

// The mean of weight(h) (a double) over the visible normals h of wo (wo.z > 0), by the
// quadrature above.
template <typename Weight>
float visibleNormalQuadrature(const GgxDistribution& ggx, const Vec3f& wo, Weight weight) {
    using albedo_table::kQuadrature;
    double sum = 0.0;
    forEachVisibleNormal(ggx, wo, [&](const Vec3f& h, float jacobian) { sum += weight(h) * jacobian; });
    return float(sum / (double(kQuadrature) * kQuadrature));
}

// The mean over the visible normals h of wo = (sqrt(1 - mu^2), 0, mu) of
// weight(wo, h, wo.h, G1(wo)) (a double), counting 0 where wo.h <= 0: the quadrature of an
// interface's albedo at one node.
template <typename Weight>
float facetQuadrature(const GgxDistribution& ggx, float mu, Weight weight) {
    const Vec3f wo(std::sqrt(std::max(0.0f, 1.0f - mu * mu)), 0.0f, mu);
    const float g1 = ggx.G1(wo);
    return visibleNormalQuadrature(ggx, wo, [&](const Vec3f& h) {
        const float cosO = dot(wo, h);
        return cosO > 0.0f ? weight(wo, h, cosO, g1) : 0.0;
    });
}

template <float (*Albedo)(const GgxDistribution&, float mu, float f0)>
class AlbedoTable {
public:
    static float albedo(float cosTheta, float alpha, float f0) {
        const albedo_table::AxisPosition c = albedo_table::positionOf(cosTheta, albedo_table::kCosines);
        return interpolated(alpha, f0, [&](const Slice& s, int j) {
            return albedo_table::lerp(s.at(c.node, j), s.at(c.node + 1, j), c.fraction);
        });
    }
    static float average(float alpha, float f0) {
        return interpolated(alpha, f0, [](const Slice& s, int j) { return s.average[j]; });
    }

private:
    // The table of one f0: E at every (mu, alpha) node, and Eavg at every alpha node.
    struct Slice {
        std::array<float, albedo_table::kWidths * albedo_table::kCosines> albedo;
        std::array<float, albedo_table::kWidths> average;

        // The widths in parallel: each node is a pure function of its parameters, so the values do
        // not depend on the split. Isolated, so that a thread waiting for them takes no other task
        // (a render's tile that would ask for this slice again from inside its std::call_once).
        explicit Slice(float f0) {
            using namespace albedo_table;
            tbb::this_task_arena::isolate([&] {
                tbb::parallel_for(0, kWidths, [&](int j) {
                    const float r = float(j) / (kWidths - 1);
                    const GgxDistribution ggx(std::max(r * r, kGgxSmoothAlpha));
                    for (int i = 0; i < kCosines; ++i)
                        albedo[std::size_t(j) * kCosines + i] = Albedo(ggx, cosineAt(i), f0);
                    average[j] = averageOf(j);
                });
            });
        }
        float at(int i, int j) const { return albedo[std::size_t(j) * albedo_table::kCosines + i]; }

        float averageOf(int j) const {
            return albedo_table::cosineWeightedAverage([&](int i) { return at(i, j); });
        }
    };

    static const Slice& slice(int k) {
        return albedo_table::sliceBuiltOnce<Slice, albedo_table::kF0s>(k, albedo_table::f0At(k));
    }

    // g(slice, width node) interpolated linearly in width and in sqrt(f0).
    template <typename G>
    static float interpolated(float alpha, float f0, G g) {
        using namespace albedo_table;
        const AxisPosition w = positionOf(std::sqrt(std::max(alpha, 0.0f)), kWidths),
                           f = positionOf(std::sqrt(std::max(f0, 0.0f)), kF0s);
        const Slice &below = slice(f.node), &above = slice(f.node + 1);
        return lerp(lerp(g(below, w.node), g(below, w.node + 1), w.fraction),
                    lerp(g(above, w.node), g(above, w.node + 1), w.fraction), f.fraction);
    }
};

}  // namespace fluence::render
