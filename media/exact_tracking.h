// Regular tracking: free flights and transmittances from a medium's exact extinction (the cubic
// pieces of media/medium.h, EXACT EXTINCTION), with no tentative collision and no null point.
//
// OPTICAL DEPTH. Over a piece, tau_c(s) = sum_k coefficients[k][c] s^(k+1) / (k + 1): a quartic in
// closed form. Summed piece by piece (in double precision), it gives tau_c(t) anywhere on the ray,
// and the transmittance T_c(t) = exp(-tau_c(t)) exactly: zero variance.
//
// FREE FLIGHT (inversion of the hero's optical depth). With u uniform in [0, 1), the flight stops at
// the t where tau_h(t) = -log(1 - u) (found in the piece where the running depth crosses it, by
// Newton's method safeguarded by bisection on the monotone tau_h: sigmaT >= 0), or escapes if
// tau_h(tMax) falls short. Had channel c been the hero, its densities would have been
//     stopping at t:  p_c(t) = sigmaT_c(t) T_c(t),     escaping:  P_c = T_c(tMax),
// exactly: the classical path space, with no null points, and the outcome a monotone function of u
// alone (an inverse CDF, so a stratified u stratifies escape and distance over a pixel's samples).
// A point of the flight is both a scattering and an absorption (no choice between them is drawn):
// with f_c = T_c sigmaS_c (scattering, the caller multiplies by the phase function) and T_c sigmaA_c
// (absorption, times Le), the weights are f_c / p_h: throughput = T sigmaS / p_h and
// absorbedThroughput = T sigmaA / p_h (media/free_flight.h); E[either] over the flight is the
// integral of its f, so scoring the emission at the point and going on scattering adds both terms
// of the transport equation's source without bias. In a grey medium the scattering weight is the
// albedo, not a random 0 or 1. pdfRatio = p_c / p_h as media/tracking.h defines it.
//   lightPdfRatio on escape = 1 / P_h: the light strategy's density of the same escaped path, in the
// same classical space, is the prefix's density times the light's (no flight drawn: its shadow ray's
// transmittance is a weight, exactTransmittance() below), so over p_h it gets 1 / P_h beside the
// prefix's ratio (integrators/path_tracer.cpp, EXACT FLIGHTS, for the weights that sum to one).
// ratioTrackedPdfRatio stays 0: no ratio-tracked strategy is weighted against these flights (the
// path tracer does not use them where the equiangular strategy applies).
//
// RANDOMNESS. One number, u, and nothing else: no stream.
#pragma once

#include "media/free_flight.h"
#include "media/medium.h"
#include "media/tracking.h"
#include "media/transmittance_estimate.h"

namespace fluence::media {

// T_c = exp(-tau_c(ray.tMax)) exactly (throughput T, pdfRatio 1; collisions: the pieces walked).
// The medium must have exact extinction.
TransmittanceEstimate exactTransmittance(const Medium& medium, const MediumRay& ray);

// The free flight of the hero channel by inversion of its optical depth with u in [0, 1) (FREE
// FLIGHT above): Escaped, or Scattered (Absorbed where sigmaS is 0 in every channel), with the weights
// of media/free_flight.h (collisions: the pieces walked). The medium must have exact extinction.
FreeFlight sampleExactFlight(const Medium& medium, const MediumRay& ray, int hero, float u);

}  // namespace fluence::media
