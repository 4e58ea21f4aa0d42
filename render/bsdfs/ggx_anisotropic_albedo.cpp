#include "render/bsdfs/ggx_anisotropic_albedo.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/sampling.h"
#include "render/bsdfs/albedo_table.h"
#include "render/bsdfs/ggx_albedo.h"

namespace fluence::render {

namespace {

using namespace albedo_table;

constexpr int kAzimuths = 16;  // phi in [0, pi / 2], evenly spaced

float widthAt(int j) {
    const float r = float(j) / (kWidths - 1);
    return std::max(r * r, kGgxSmoothAlpha);
}

// E at every (mu, phi) node for one pair of widths, and Eavg.
struct Slice {
    std::array<float, kAzimuths * kCosines> albedo;
    float average;

    Slice(int jx, int jy) {
        const GgxDistribution ggx(widthAt(jx), widthAt(jy));
        for (int a = 0; a < kAzimuths; ++a) {
            const float phi = 0.5f * kPi * float(a) / (kAzimuths - 1);
            for (int i = 0; i < kCosines; ++i) {
                const float mu = cosineAt(i), s = std::sqrt(std::max(0.0f, 1.0f - mu * mu));
                albedo[std::size_t(a) * kCosines + i] =
                    ggxReflectionQuadrature(ggx, Vec3f(s * std::cos(phi), s * std::sin(phi), mu), 1.0f);
            }
        }
        // The mean over phi of the mean over mu: the trapezoid rule is exact for E linear in phi
        // between the nodes.
        double sum = 0.0;
        for (int a = 0; a < kAzimuths; ++a) {
            const float overMu = cosineWeightedAverage([&](int i) { return at(i, a); });
            sum += (a == 0 || a == kAzimuths - 1 ? 0.5 : 1.0) * overMu;
        }
        average = float(sum / (kAzimuths - 1));
    }
    float at(int i, int a) const { return albedo[std::size_t(a) * kCosines + i]; }
};

const Slice& slice(int jx, int jy) {
    return albedo_table::sliceBuiltOnce<Slice, kWidths * kWidths>(jx * kWidths + jy, jx, jy);
}

// g(slice) interpolated bilinearly in sqrt(ax) and sqrt(ay).
template <typename G>
float interpolated(float alphaX, float alphaY, G g) {
    const AxisPosition x = positionOf(std::sqrt(std::max(alphaX, 0.0f)), kWidths),
                       y = positionOf(std::sqrt(std::max(alphaY, 0.0f)), kWidths);
    return lerp(lerp(g(slice(x.node, y.node)), g(slice(x.node, y.node + 1)), y.fraction),
                lerp(g(slice(x.node + 1, y.node)), g(slice(x.node + 1, y.node + 1)), y.fraction), x.fraction);
}

// The isotropic table's width for a distribution: 0 when smooth.
float isotropicWidth(const GgxDistribution& ggx) {
    return ggx.isSmooth() ? 0.0f : std::sqrt(ggx.alphaX() * ggx.alphaY());
}
bool anisotropic(const GgxDistribution& ggx) { return !ggx.isSmooth() && ggx.alphaX() != ggx.alphaY(); }

}  // namespace

float ggxAnisotropicAlbedo(const Vec3f& wo, float alphaX, float alphaY) {
    const AxisPosition c = positionOf(wo.z, kCosines),
                       a = positionOf(std::atan2(std::abs(wo.y), std::abs(wo.x)) / (0.5f * kPi), kAzimuths);
    return interpolated(alphaX, alphaY, [&](const Slice& s) {
        return lerp(lerp(s.at(c.node, a.node), s.at(c.node + 1, a.node), c.fraction),
                    lerp(s.at(c.node, a.node + 1), s.at(c.node + 1, a.node + 1), c.fraction), a.fraction);
    });
}

float ggxAnisotropicAverageAlbedo(float alphaX, float alphaY) {
    return interpolated(alphaX, alphaY, [](const Slice& s) { return s.average; });
}

float ggxBareAlbedo(const Vec3f& wo, const GgxDistribution& ggx) {
    if (anisotropic(ggx)) return ggxAnisotropicAlbedo(wo, ggx.alphaX(), ggx.alphaY());
    return ggxReflectionAlbedo(wo.z, isotropicWidth(ggx), 1.0f);
}

float ggxBareAverageAlbedo(const GgxDistribution& ggx) {
    if (anisotropic(ggx)) return ggxAnisotropicAverageAlbedo(ggx.alphaX(), ggx.alphaY());
    return ggxReflectionAverageAlbedo(isotropicWidth(ggx), 1.0f);
}

}  // namespace fluence::render
