// The radiance a volume emits by its temperature, for GridMedium's blackbody emission.
//
// MODEL. L(T) = sigma_SB T^4 / pi * 1e-6 * colour(T): the Stefan-Boltzmann law gives a blackbody's
// radiance, sigma_SB T^4 / pi in W m^-2 sr^-1 (sigma_SB = 5.670374419e-8 W m^-2 K^-4, CODATA 2018),
// scaled by 1e-6 as Cycles' Principled Volume scales its blackbody term (so that flames of
// 1000-3000 K have radiances of about 0.02-1.5 and blackbodyIntensity 1 means the same brightness
// in both renderers), and coloured by core/blackbody.h's colour of luminance 1 (linear Rec.709).
// Below 100 K the radiance is taken as 0 (it is below 2e-6 there).
//
// TABLE. Computing the colour integrates Planck's law over the CIE observer (95 exponentials), too
// slow per medium sample: it is tabulated every 5 K from 100 K to 20000 K and interpolated linearly
// (error below 1e-3 of the luminance); hotter media, rare, compute it directly. T^4 is always
// exact. The table is built once, on first use, thread-safely.
#pragma once

#include "core/rgb.h"

namespace fluence::volumes {

RGB blackbodyRadiance(float kelvin);

}  // namespace fluence::volumes
