#include "delegate/dicing.h"

#include <algorithm>
#include <cmath>

namespace fluence::delegate {

std::vector<int> edgeSegments(const render::Camera& camera, const DicingSettings& settings, float rate,
                              const std::vector<std::pair<Vec3f, Vec3f>>& edges, float scale) {
    std::vector<int> segments;
    segments.reserve(edges.size());
    for (const auto& [a, b] : edges) {
        float pixelsPerUnit = 0.0f;
        bool inView = false;
        for (float t : {0.0f, 0.25f, 0.5f, 0.75f, 1.0f}) {
            // The same points from either end (t and 1 - t), so that (a, b) and (b, a) agree.
            Vec3f p = t <= 0.5f ? a + (b - a) * t : b + (a - b) * (1.0f - t);
            pixelsPerUnit = std::max(pixelsPerUnit, camera.pixelsPerUnitAt(p));
            inView = inView || camera.sees(p, settings.margin);
        }
        float pixels = length(b - a) * pixelsPerUnit;
        float edgeRate = rate * (inView ? 1.0f : settings.offscreenFactor);
        float wanted = std::ceil(scale * pixels / edgeRate);
        segments.push_back(
            std::isfinite(wanted) ? std::clamp(static_cast<int>(std::min(wanted, 1e6f)), 1, settings.maxSegments) : 1);
    }
    return segments;
}

}  // namespace fluence::delegate
