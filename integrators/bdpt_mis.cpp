#include "integrators/bdpt_mis.h"

namespace fluence::integrators {

bool strategyExists(const StrategyPath& path, int s) {
    const auto& x = path.vertices;
    if (s < 0 || s + 2 > static_cast<int>(x.size())) return false;
    if (s == 0) return path.lightHittable;
    return (s == 1 || !x[s - 1].delta) && !x[s].delta;
}

float misWeight(const StrategyPath& path, int s) {
    const auto& x = path.vertices;
    const int strategies = static_cast<int>(x.size()) - 1;  // s = 0 ... k - 1
    // x_0's light density under strategy s' (>= 1).
    auto origin = [&](int sp) { return double(sp == 1 ? path.neeOrigin : x[0].fromLight); };
    double sum = 0.0;
    auto add = [&](int sp, double ratio) {
        if (strategyExists(path, sp)) sum += ratio * ratio;
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
    return static_cast<float>(1.0 / (1.0 + sum));
}

}  // namespace fluence::integrators
