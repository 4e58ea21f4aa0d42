#include "denoise/local_fit.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace fluence::denoise {

namespace {

constexpr float kEpsilon = 1e-10f;  // keeps the NL-means distance finite where the variance is 0
constexpr float kNegligibleWeight = 1e-4f;
constexpr int kLanes = 4;
constexpr int kMaxNeighbours = ((2 * kMaxRadius + 1) * (2 * kMaxRadius + 1) + kLanes - 1) / kLanes * kLanes;

// Four floats added lane by lane (SSE2 on x86-64): the sums below run over the neighbours four at
// a time, always in the same order, so they are the same at any thread count.
using Lanes = float __attribute__((vector_size(4 * sizeof(float))));

Lanes load(const float* p) {
    Lanes v;
    std::memcpy(&v, p, sizeof v);
    return v;
}

// The sum over `n` (a multiple of kLanes) neighbours of a_j b_j.
float dot(const float* a, const float* b, int n) {
    Lanes sum = {0.0f, 0.0f, 0.0f, 0.0f};
    for (int j = 0; j < n; j += kLanes) sum += load(a + j) * load(b + j);
    return (sum[0] + sum[1]) + (sum[2] + sum[3]);
}

// Solves a x = b (a symmetric positive definite, by Cholesky, in double) for `outputs` right-hand
// sides, the columns of b; writes the solutions output-major. False when a is not positive definite.
bool solve(const float a[kFeatures][kFeatures], const float b[kFeatures][kMaxOutputs], int outputs, float* out) {
    double l[kFeatures][kFeatures] = {};
    for (int r = 0; r < kFeatures; ++r)
        for (int c = 0; c <= r; ++c) {
            double s = a[c][r];
            for (int p = 0; p < c; ++p) s -= l[r][p] * l[c][p];
            if (r == c) {
                if (!(s > 0.0)) return false;
                l[r][r] = std::sqrt(s);
            } else {
                l[r][c] = s / l[c][c];
            }
        }
    for (int o = 0; o < outputs; ++o) {
        double y[kFeatures], x[kFeatures];
        for (int r = 0; r < kFeatures; ++r) {
            double s = b[r][o];
            for (int p = 0; p < r; ++p) s -= l[r][p] * y[p];
            y[r] = s / l[r][r];
        }
        for (int r = kFeatures - 1; r >= 0; --r) {
            double s = y[r];
            for (int p = r + 1; p < kFeatures; ++p) s -= l[p][r] * x[p];
            x[r] = s / l[r][r];
        }
        for (int p = 0; p < kFeatures; ++p) out[o * kFeatures + p] = static_cast<float>(x[p]);
    }
    return true;
}

}  // namespace

float colourWeight(const DenoisePlanes& planes, int guide, std::size_t i, std::size_t j, float k2) {
    float distance = 0.0f;
    for (std::size_t c = 0; c < 3; ++c) {
        const std::vector<float>& colour = planes.guide[guide][c];
        const std::vector<float>& variance = planes.guideVariance[c];
        const float d = colour[i] - colour[j], vi = variance[i], vj = variance[j];
        const float shared = vi + std::min(vi, vj);
        distance += (d * d - shared) / (kEpsilon + k2 * shared);
    }
    return std::exp(-std::max(0.0f, distance / 3.0f));
}

float fireflyWeight(const DenoisePlanes& planes, std::size_t i, std::size_t j, float ratio) {
    const float limit = ratio * planes.windowVariance[i], own = planes.pixelVariance[j];
    if (i == j || own <= limit) return 1.0f;
    const float share = limit / own;
    return share * share;
}

void centredFeatures(const DenoisePlanes& planes, std::size_t i, std::size_t j, float x[kFeatures]) {
    x[0] = 1.0f;
    for (std::size_t f = 0; f < 6; ++f) x[1 + f] = planes.features[f][j] - planes.features[f][i];
    const float depth = std::max(planes.features[6][i], 1e-6f);
    x[7] = std::clamp((planes.features[6][j] - depth) / depth, -1.0f, 1.0f);
}

void fitCentre(const DenoisePlanes& planes, const DenoiseSettings& settings, int x, int y, float* coefficients[2]) {
    const std::size_t i = std::size_t(y) * planes.width + x;
    const float k2 = settings.k * settings.k;
    const int outputs = planes.outputs();
    // The neighbours that count for either half: their index, weights and features, padded with
    // zero weights to a multiple of kLanes.
    alignas(16) float weights[2][kMaxNeighbours], features[kFeatures][kMaxNeighbours], values[kMaxNeighbours];
    std::size_t index[kMaxNeighbours];
    int n = 0;
    for (int yy = std::max(0, y - settings.radius); yy <= std::min(planes.height - 1, y + settings.radius); ++yy)
        for (int xx = std::max(0, x - settings.radius); xx <= std::min(planes.width - 1, x + settings.radius); ++xx) {
            const std::size_t j = std::size_t(yy) * planes.width + xx;
            const float firefly = fireflyWeight(planes, i, j, settings.fireflyRatio);
            const float w0 = colourWeight(planes, 1, i, j, k2) * firefly,
                        w1 = colourWeight(planes, 0, i, j, k2) * firefly;
            if (w0 < kNegligibleWeight && w1 < kNegligibleWeight) continue;
            float f[kFeatures];
            centredFeatures(planes, i, j, f);
            for (int p = 0; p < kFeatures; ++p) features[p][n] = f[p];
            weights[0][n] = w0;
            weights[1][n] = w1;
            index[n++] = j;
        }
    const int padded = (n + kLanes - 1) / kLanes * kLanes;
    for (int j = n; j < padded; ++j) {
        weights[0][j] = weights[1][j] = 0.0f;
        for (int p = 0; p < kFeatures; ++p) features[p][j] = 0.0f;
    }
    for (int h = 0; h < 2; ++h) {
        alignas(16) float weighted[kFeatures][kMaxNeighbours];
        for (int p = 0; p < kFeatures; ++p)
            for (int j = 0; j < padded; ++j) weighted[p][j] = weights[h][j] * features[p][j];
        float a[kFeatures][kFeatures], b[kFeatures][kMaxOutputs];
        for (int p = 0; p < kFeatures; ++p)
            for (int q = p; q < kFeatures; ++q) a[q][p] = a[p][q] = dot(weighted[p], features[q], padded);
        for (int o = 0; o < outputs; ++o) {
            const float* plane = planes.values[h][std::size_t(o)];
            for (int j = 0; j < n; ++j) values[j] = plane[index[j]];
            for (int j = n; j < padded; ++j) values[j] = 0.0f;
            for (int p = 0; p < kFeatures; ++p) b[p][o] = dot(weighted[p], values, padded);
        }
        // The ridge on the feature terms, relative to the weights' sum (a[0][0]).
        for (int p = 1; p < kFeatures; ++p) a[p][p] += settings.ridge * a[0][0];
        if (!solve(a, b, outputs, coefficients[h])) {  // not met with the ridge; the weighted mean then
            for (int o = 0; o < outputs; ++o) {
                std::fill_n(coefficients[h] + o * kFeatures, kFeatures, 0.0f);
                coefficients[h][o * kFeatures] = a[0][0] > 0.0f ? b[0][o] / a[0][0] : 0.0f;
            }
        }
    }
}

}  // namespace fluence::denoise
