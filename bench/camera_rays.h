// Camera rays for the volume benchmarks: a pinhole camera at `eye` looking at `target` with `up`,
// the tangents of its half fields of view, and one ray through every `stride`-th pixel centre of
// a width x height image.
#pragma once

#include <vector>

#include "core/vec.h"

namespace fluence::bench {

struct CameraRay {
    Vec3f origin, direction;
};

inline std::vector<CameraRay> cameraRays(const Vec3f& eye, const Vec3f& target, const Vec3f& up, float tanHalfWidth,
                                         float tanHalfHeight, int width, int height, int stride) {
    Vec3f forward = normalize(target - eye), right = normalize(cross(forward, up)), upward = cross(right, forward);
    std::vector<CameraRay> rays;
    for (int y = stride / 2; y < height; y += stride)
        for (int x = stride / 2; x < width; x += stride) {
            float u = (2.0f * (x + 0.5f) / width - 1.0f) * tanHalfWidth;
            float v = (1.0f - 2.0f * (y + 0.5f) / height) * tanHalfHeight;
            rays.push_back({eye, normalize(forward + right * u + upward * v)});
        }
    return rays;
}

}  // namespace fluence::bench
