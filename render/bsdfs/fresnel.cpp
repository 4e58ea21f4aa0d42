#include "render/bsdfs/fresnel.h"

#include <algorithm>
#include <cmath>

namespace fluence::render {

FresnelPolarized fresnelDielectricPolarized(float cosThetaI, float eta) {
    cosThetaI = std::clamp(cosThetaI, 0.0f, 1.0f);
    // Snell: sin t = sin i / eta.
    float sin2T = (1.0f - cosThetaI * cosThetaI) / (eta * eta);
    if (sin2T >= 1.0f) return {1.0f, 1.0f};
    float cosT = std::sqrt(1.0f - sin2T);
    // With n_i = 1 and n_t = eta: r_s = (n_i cos i - n_t cos t) / (n_i cos i + n_t cos t),
    // r_p = (n_t cos i - n_i cos t) / (n_t cos i + n_i cos t).
    float rs = (cosThetaI - eta * cosT) / (cosThetaI + eta * cosT);
    float rp = (eta * cosThetaI - cosT) / (eta * cosThetaI + cosT);
    return {rs * rs, rp * rp};
}

}  // namespace fluence::render
