#include "media/subsurface_medium.h"

#include <algorithm>
#include <cmath>

namespace fluence::media {

float singleScatteringAlbedo(float reflectance) {
    const double a = std::clamp(reflectance, 0.0f, 1.0f);
    const double root = 4.09712 + 4.20863 * a - std::sqrt(9.59217 + 41.6808 * a + 17.7126 * a * a);
    return static_cast<float>(std::clamp(1.0 - root * root, 0.0, 1.0));
}

MediumProperties subsurfaceMedium(const RGB& colour, const RGB& meanFreePath, float anisotropy) {
    MediumProperties m;
    for (int c = 0; c < 3; ++c) {
        const float sigmaT = 1.0f / std::max(meanFreePath[c], kMinMeanFreePath);
        const float alpha = singleScatteringAlbedo(colour[c]);
        m.sigmaS[c] = alpha * sigmaT;
        m.sigmaA[c] = (1.0f - alpha) * sigmaT;
    }
    m.g = std::clamp(anisotropy, -kMaxSubsurfaceAnisotropy, kMaxSubsurfaceAnisotropy);
    return m;
}

}  // namespace fluence::media
