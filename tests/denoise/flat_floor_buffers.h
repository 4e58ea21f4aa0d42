// The denoiser's tests' buffers (denoise/denoiser.h) before their samples are drawn: a square image
// of a flat floor facing the camera (normal +Z, depth 2 everywhere), colours and albedo to be set.
#pragma once

#include <cstddef>

#include "denoise/denoiser.h"

namespace fluence::denoise {

inline DenoiseBuffers flatFloorBuffers(int size) {
    DenoiseBuffers b;
    b.width = b.height = size;
    const std::size_t n = std::size_t(size) * std::size_t(size);
    for (auto& half : b.halves) half.resize(3 * n);
    b.variance.resize(3 * n);
    b.albedo.resize(3 * n);
    b.normal.assign(3 * n, 0.0f);
    for (std::size_t p = 0; p < n; ++p) b.normal[3 * p + 2] = 1.0f;
    b.depth.assign(n, 2.0f);
    return b;
}

}  // namespace fluence::denoise
