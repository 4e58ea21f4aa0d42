#include "render/bsdfs/sheen.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/sampling.h"

namespace fluence::render {

namespace {

// Estevez & Kulla 2017, table 1: the coefficients (a, b, c, d, e) of L fitted at r = 0 and r = 1.
constexpr std::array<float, 5> kFitR0 = {25.3245f, 3.32435f, 0.16801f, -1.27393f, -4.85967f};
constexpr std::array<float, 5> kFitR1 = {21.5473f, 3.82987f, 0.19823f, -1.97760f, -4.32054f};

float clampRoughness(float r) { return std::clamp(r, kSheenMinRoughness, 1.0f); }

// The albedo table: kCosines values of x = cbrt(cos theta) in [0, 1] by kSheenRoughnesses values
// of r (sheenRoughnessAt), both evenly spaced.
constexpr int kCosines = 32, kRoughnesses = kSheenRoughnesses;

// E(cos theta_o) of the untinted lobe: the integral of f cos theta_i over the hemisphere, by the
// tables' quadrature (forEachSheenQuadraturePoint).
float quadratureAlbedo(const CharlieSheenBsdf& lobe, float cosO) {
    const Vec3f wo(std::sqrt(std::max(0.0f, 1.0f - cosO * cosO)), 0.0f, cosO);
    double sum = 0.0;
    forEachSheenQuadraturePoint(
        [&](const Vec3f& wi, float weight) { sum += double(lobe.f(wo, wi).x) * wi.z * weight; });
    return float(sum * 2.0 * kPi / (double(kSheenQuadrature) * kSheenQuadrature));
}

struct AlbedoTable {
    std::array<float, kCosines * kRoughnesses> values;

    AlbedoTable() {
        for (int j = 0; j < kRoughnesses; ++j) {
            CharlieSheenBsdf lobe(RGB(1.0f), sheenRoughnessAt(j));
            for (int i = 0; i < kCosines; ++i) {
                float x = float(i) / (kCosines - 1);
                // cos theta = 0 scatters nothing; its node holds the limit as seen at 1e-5.
                values[std::size_t(j) * kCosines + i] = quadratureAlbedo(lobe, std::max(x * x * x, 1e-5f));
            }
        }
    }
    float at(int i, int j) const { return values[std::size_t(j) * kCosines + i]; }
};

}  // namespace

float charlieSheenAlbedo(float cosTheta, float roughness) {
    static const AlbedoTable table;
    float x = std::cbrt(std::clamp(cosTheta, 0.0f, 1.0f)) * (kCosines - 1);
    float y = (clampRoughness(roughness) - kSheenMinRoughness) / (1.0f - kSheenMinRoughness) * (kRoughnesses - 1);
    int i = std::min(int(x), kCosines - 2), j = std::min(int(y), kRoughnesses - 2);
    float fx = x - float(i), fy = y - float(j);
    return (1.0f - fy) * ((1.0f - fx) * table.at(i, j) + fx * table.at(i + 1, j)) +
           fy * ((1.0f - fx) * table.at(i, j + 1) + fx * table.at(i + 1, j + 1));
}

float charlieSheenAverageAlbedo(float roughness) {
    constexpr int kPoints = 512;
    static const std::array<float, kRoughnesses> averages = [] {
        std::array<float, kRoughnesses> a{};
        for (int j = 0; j < kRoughnesses; ++j) {
            const float r = sheenRoughnessAt(j);
            double sum = 0.0;
            for (int i = 0; i < kPoints; ++i) {
                const float mu = (i + 0.5f) / kPoints;
                sum += double(charlieSheenAlbedo(mu, r)) * mu;
            }
            a[j] = float(2.0 * sum / kPoints);
        }
        return a;
    }();
    const float y = (clampRoughness(roughness) - kSheenMinRoughness) / (1.0f - kSheenMinRoughness) * (kRoughnesses - 1);
    const int j = std::min(int(y), kRoughnesses - 2);
    return averages[j] + (averages[j + 1] - averages[j]) * (y - float(j));
}

CharlieSheenBsdf::CharlieSheenBsdf(const RGB& tint, float roughness)
    : tint_(tint), roughness_(clampRoughness(roughness)) {
    normalization_ = (2.0f + 1.0f / roughness_) / (2.0f * kPi);
    const float t = (1.0f - roughness_) * (1.0f - roughness_);
    std::array<float, 5> k;
    for (int n = 0; n < 5; ++n) k[n] = t * kFitR0[n] + (1.0f - t) * kFitR1[n];
    a_ = k[0], b_ = k[1], c_ = k[2], d_ = k[3], e_ = k[4];
    fitLHalf_ = fitL(0.5f);
}

float CharlieSheenBsdf::D(const Vec3f& h) const {
    float sin2 = std::max(0.0f, 1.0f - h.z * h.z);
    return normalization_ * std::pow(sin2, 0.5f / roughness_);
}

float CharlieSheenBsdf::lambda(float cosTheta) const {
    float c = std::abs(cosTheta);
    return std::exp(c < 0.5f ? fitL(c) : 2.0f * fitLHalf_ - fitL(1.0f - c));
}

RGB CharlieSheenBsdf::fUpper(const Vec3f& wo, const Vec3f& wi) const {
    Vec3f h = normalize(wo + wi);
    float g2 = 1.0f / (1.0f + lambda(wo.z) + lambda(wi.z));
    return tint_ * (D(h) * g2 / (4.0f * wo.z * wi.z));
}

float CharlieSheenBsdf::pdfUpper(const Vec3f&, const Vec3f&) const { return 1.0f / (2.0f * kPi); }

std::optional<BsdfSample> CharlieSheenBsdf::sampleUpper(const Vec3f& wo, float, Vec2f u) const {
    // The uniform sphere folded onto the upper hemisphere: uniform there, pdf 1 / (2 pi).
    Vec3f wi = sampleUniformSphere(u);
    wi.z = std::abs(wi.z);
    if (wi.z == 0.0f) return std::nullopt;
    return BsdfSample{fUpper(wo, wi), wi, pdfUpper(wo, wi)};
}

}  // namespace fluence::render
