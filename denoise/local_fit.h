// One weighted first-order regression of the denoiser (denoise/denoiser.h): the colour of the
// neighbours j of a centre pixel i as a linear function of their features centred on i's, fitted
// for both halves at once (half 0 with the weights of half 1's guide and the other way round).
#pragma once

#include <cstddef>

#include "denoise/denoise_planes.h"

namespace fluence::denoise {

inline constexpr int kFeatures = 8;         // the constant, albedo R G B, normal X Y Z, relative depth
inline constexpr int kMaxOutputs = 3 * 17;  // the beauty and up to 16 layers, R G B each
inline constexpr int kMaxRadius = 8;

// The NL-means weight of pixel j for pixel i on the guide `guide` (0 or 1; see denoiser.h).
float colourWeight(const DenoisePlanes& planes, int guide, std::size_t i, std::size_t j, float k2);

// The weight of neighbour j in the fit of centre i, beyond its colour weight: 1 unless j's
// variance exceeds `ratio` times the variance level of i's window, and then the square of their
// ratio. A firefly is a pixel whose variance is far above its neighbours': its value F, weighted
// by a power of 1 / F², is not spread over them, while its own fit (j = i) keeps it.
float fireflyWeight(const DenoisePlanes& planes, std::size_t i, std::size_t j, float ratio);

// The features of pixel j centred on pixel i's.
void centredFeatures(const DenoisePlanes& planes, std::size_t i, std::size_t j, float x[kFeatures]);

// Fits centre (x, y): writes, for each half h, outputs() x kFeatures coefficients (output-major) at
// coefficients[h], so that the fitted value of output o at pixel j is the dot product of
// coefficients[h][o * kFeatures ...] with centredFeatures(i, j).
void fitCentre(const DenoisePlanes& planes, const DenoiseSettings& settings, int x, int y, float* coefficients[2]);

}  // namespace fluence::denoise
