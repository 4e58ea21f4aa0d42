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

std::vector<int> placedEdgeSegments(const render::Camera& camera, const DicingSettings& settings, float rate,
                                    const std::vector<Vec3f>& points, const std::vector<std::pair<int, int>>& edges,
                                    const std::vector<Matrix4>& placements, float scale) {
    constexpr std::size_t kNearestPlacements = 16;
    std::vector<int> segments(edges.size(), 1);
    std::vector<const Matrix4*> nearest;
    for (const Matrix4& m : placements) nearest.push_back(&m);
    auto distance = [&](const Matrix4* m) { return length(Vec3f(m->transformPoint({0, 0, 0})) - camera.position()); };
    if (nearest.size() > kNearestPlacements) {
        std::partial_sort(nearest.begin(), nearest.begin() + kNearestPlacements, nearest.end(),
                          [&](const Matrix4* a, const Matrix4* b) { return distance(a) < distance(b); });
        nearest.resize(kNearestPlacements);
    }
    std::vector<std::pair<Vec3f, Vec3f>> world(edges.size());
    for (const Matrix4* m : nearest) {
        for (std::size_t e = 0; e < edges.size(); ++e)
            world[e] = {Vec3f(m->transformPoint(Vec3d(points[static_cast<std::size_t>(edges[e].first)]))),
                        Vec3f(m->transformPoint(Vec3d(points[static_cast<std::size_t>(edges[e].second)])))};
        std::vector<int> counts = edgeSegments(camera, settings, rate, world, scale);
        for (std::size_t e = 0; e < edges.size(); ++e) segments[e] = std::max(segments[e], counts[e]);
    }
    return segments;
}

}  // namespace fluence::delegate
