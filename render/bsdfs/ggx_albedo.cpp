#include "render/bsdfs/ggx_albedo.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <mutex>
#include <optional>

#include "render/bsdfs/fresnel.h"
#include "render/bsdfs/ggx.h"
#include "render/bsdfs/local_geometry.h"

namespace fluence::render {

namespace {

constexpr int kCosines = 32, kWidths = 32, kF0s = 33;
constexpr int kQuadrature = 32;      // points per dimension
constexpr float kMinCosine = 1e-4f;  // where the mu = 0 node is evaluated

float cosineAt(int i) { return std::max(float(i) / (kCosines - 1), kMinCosine); }
float f0At(int k) {
    const float s = float(k) / (kF0s - 1);
    return s * s;
}

// F(cos) of the dielectric of normal-incidence reflectance f0; 1 for f0 = 1, 0 for f0 = 0.
float reflectanceOf(float cosTheta, float f0) {
    if (f0 >= 1.0f) return 1.0f;
    if (f0 <= 0.0f) return 0.0f;
    return fresnelDielectric(cosTheta, etaFromF0(f0));
}

// E at (mu, alpha) for the reflectance f0: the integral of f cos / pdf over the visible
// normals' two sample numbers by the midpoint rule, with u.x = 1 - (1 - t)^4 so that the points
// crowd towards u.x = 1, where GGX's long tail sends the reflection below the horizon (1% of the
// visible normals at alpha 0.1, which evenly spaced points would step over).
float quadratureAlbedo(const GgxDistribution& ggx, float mu, float f0) {
    const Vec3f wo(std::sqrt(std::max(0.0f, 1.0f - mu * mu)), 0.0f, mu);
    double sum = 0.0;
    for (int a = 0; a < kQuadrature; ++a) {
        const float t = 1.0f - (a + 0.5f) / kQuadrature;  // 1 - t of the comment above
        const float ux = 1.0f - t * t * t * t, jacobian = 4.0f * t * t * t;
        for (int b = 0; b < kQuadrature; ++b) {
            const Vec3f h = ggx.sampleVisibleNormal(wo, Vec2f(ux, (b + 0.5f) / kQuadrature));
            const Vec3f wi = reflect(wo, h);
            if (wi.z <= 0.0f) continue;
            const float pdf = ggx.reflectionPdf(wo, h);
            if (!(pdf > 0.0f)) continue;
            sum += double(reflectanceOf(dot(wo, h), f0)) * ggx.reflectionTerm(wo, wi, h) * wi.z / pdf * jacobian;
        }
    }
    return float(sum / (double(kQuadrature) * kQuadrature));
}

// The table of one f0: E at every (mu, alpha) node, and Eavg at every alpha node. Computed on
// first use of that f0 (a material needs the two slices around its index, and the metals F = 1).
struct Slice {
    std::array<float, kWidths * kCosines> albedo;
    std::array<float, kWidths> average;

    explicit Slice(float f0) {
        for (int j = 0; j < kWidths; ++j) {
            const float r = float(j) / (kWidths - 1);
            const GgxDistribution ggx(std::max(r * r, kGgxSmoothAlpha));
            for (int i = 0; i < kCosines; ++i)
                albedo[std::size_t(j) * kCosines + i] = quadratureAlbedo(ggx, cosineAt(i), f0);
            average[j] = averageOf(j);
        }
    }
    float at(int i, int j) const { return albedo[std::size_t(j) * kCosines + i]; }

    // 2 integral E mu dmu of the piecewise-linear E through the nodes (exact for it), with the
    // first node's value taken down to mu = 0.
    float averageOf(int j) const {
        double sum = 0.0;
        for (int i = 0; i + 1 < kCosines; ++i) {
            const double a = double(i) / (kCosines - 1), b = double(i + 1) / (kCosines - 1);
            sum += (b - a) * (at(i, j) * (2.0 * a + b) + at(i + 1, j) * (a + 2.0 * b)) / 6.0;
        }
        return float(2.0 * sum);
    }
};

const Slice& slice(int k) {
    static std::array<std::once_flag, kF0s> made;
    static std::array<std::optional<Slice>, kF0s> slices;
    std::call_once(made[k], [k] { slices[k].emplace(f0At(k)); });
    return *slices[k];
}

// A position on an evenly spaced axis of n nodes over [0, 1]: the node below and the fraction.
struct AxisPosition {
    int node;
    float fraction;
};
AxisPosition positionOf(float x, int n) {
    const float scaled = std::clamp(x, 0.0f, 1.0f) * float(n - 1);
    const int node = std::min(int(scaled), n - 2);
    return {node, scaled - float(node)};
}

float lerp(float a, float b, float t) { return a + (b - a) * t; }

// g(slice, width node) interpolated linearly in width and in sqrt(f0).
template <typename G>
float interpolated(float alpha, float f0, G g) {
    const AxisPosition w = positionOf(std::sqrt(std::max(alpha, 0.0f)), kWidths),
                       f = positionOf(std::sqrt(std::max(f0, 0.0f)), kF0s);
    const Slice &below = slice(f.node), &above = slice(f.node + 1);
    return lerp(lerp(g(below, w.node), g(below, w.node + 1), w.fraction),
                lerp(g(above, w.node), g(above, w.node + 1), w.fraction), f.fraction);
}

}  // namespace

float ggxReflectionAlbedo(float cosTheta, float alpha, float f0) {
    const AxisPosition c = positionOf(cosTheta, kCosines);
    return interpolated(alpha, f0,
                        [&](const Slice& s, int j) { return lerp(s.at(c.node, j), s.at(c.node + 1, j), c.fraction); });
}

float ggxReflectionAverageAlbedo(float alpha, float f0) {
    return interpolated(alpha, f0, [](const Slice& s, int j) { return s.average[j]; });
}

}  // namespace fluence::render
