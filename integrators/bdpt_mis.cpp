#include "integrators/bdpt_mis.h"

#include <array>
#include <cmath>
#include <optional>

namespace fluence::integrators {

namespace {

// Per channel c, sum over the channels of [p~_{c,s'} > 0] (p~_{c,s'} / p~_{h,s})^2 divided by
// (g_s' / g_s)^2 (bdpt_mis.h, MEDIA), for every s'; in log space, since products of majorant
// transmittances under- and overflow.
class ChannelFactors {
public:
    ChannelFactors(const StrategyPath& path, int s) : x_(path.vertices), hero_(path.hero) {
        const int h = hero_;
        for (int c = 0; c < 3; ++c) {
            double base = 0.0;
            int impossibleFlights = 0;
            for (std::size_t i = 1; i < x_.size(); ++i) {
                base += double(x_[i].edge.majorantDepth[h]) - x_[i].edge.majorantDepth[c];
                base += std::log(double(x_[i].sigmaS[c])) - std::log(double(x_[i].sigmaS[h]));
                impossibleFlights += x_[i].edge.flightPossible[c] == 0.0f;
            }
            if (s >= 1) base -= x_[s].edge.majorantDepth[h];
            base_[c] = base;
            impossibleFlights_[c] = impossibleFlights;
        }
    }

    // sum_c (p~_{c,s'} / p~_{h,s})^2 / (g_s' / g_s)^2.
    double at(int sp) const {
        double sum = 0.0;
        for (int c = 0; c < 3; ++c) {
            int impossible = impossibleFlights_[c];
            double exponent = base_[c];
            if (sp >= 1) {
                const EdgeMedia& joined = x_[sp].edge;
                if (joined.joinPossible[c] == 0.0f) continue;
                impossible -= joined.flightPossible[c] == 0.0f;
                exponent += joined.majorantDepth[c];
            }
            if (impossible == 0) sum += std::exp(2.0 * exponent);
        }
        return sum;
    }

private:
    std::span<const VertexDensity> x_;
    int hero_;
    std::array<double, 3> base_{};
    std::array<int, 3> impossibleFlights_{};
};

bool joinableAt(const VertexDensity& v) { return !v.delta && v.joinable; }

}  // namespace

bool strategyExists(const StrategyPath& path, int s) {
    const auto& x = path.vertices;
    const int k = static_cast<int>(x.size()) - 1;
    if (s == k) return path.lightTracing && k >= 2 && joinableAt(x[k - 1]);  // t = 1
    if (s < 0 || s > k) return false;
    if (s == 0) return path.lightHittable;
    return (s == 1 || joinableAt(x[s - 1])) && joinableAt(x[s]);
}

float misWeight(const StrategyPath& path, int s) {
    const auto& x = path.vertices;
    const int strategies =
        static_cast<int>(x.size()) - (path.lightTracing ? 0 : 1);  // s = 0 ... k (k - 1 without t = 1)
    const bool spectral = path.hero >= 0;
    std::optional<ChannelFactors> channels;
    if (spectral) channels.emplace(path, s);
    auto channelSum = [&](int sp) { return spectral ? channels->at(sp) : 1.0; };
    // x_0's light density under strategy s' (>= 1).
    auto origin = [&](int sp) { return double(sp == 1 ? path.neeOrigin : x[0].fromLight); };
    double sum = channelSum(s);
    auto add = [&](int sp, double ratio) {
        if (strategyExists(path, sp)) sum += ratio * ratio * channelSum(sp);
    };
    // s' > s: x_s ... x_{s'-1} move to the light side.
    double chain = 1.0;  // product over x_j, j >= 1, of fromLight / fromCamera
    for (int sp = s + 1; sp < strategies; ++sp) {
        const int j = sp - 1;
        if (j >= 1) chain *= double(x[j].fromLight) / x[j].fromCamera;
        add(sp, chain * (s == 0 ? origin(sp) / x[0].fromCamera : origin(sp) / origin(s)));
    }
    // s' < s: x_{s'} ... x_{s-1} move to the camera side.
    chain = 1.0;  // product over x_j, j >= 1, of fromCamera / fromLight
    for (int sp = s - 1; sp >= 0; --sp) {
        if (sp >= 1) chain *= double(x[sp].fromCamera) / x[sp].fromLight;
        add(sp, chain * (sp == 0 ? x[0].fromCamera / origin(s) : origin(sp) / origin(s)));
    }
    return static_cast<float>((spectral ? 3.0 : 1.0) / sum);
}

}  // namespace fluence::integrators
