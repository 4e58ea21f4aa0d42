// Forced collisions: points along a ray drawn at the majorant rate, conditioned to fall within the
// ray, and stratified. The path tracer estimates the light of its delta lights scattered along a
// whole stretch of medium at them (integrators/path_tracer.cpp), where a delta-tracked free flight
// (media/free_flight.h) would estimate it only at the one real collision it may or may not reach:
// a ray through thin smoke then scores its in-scattered sunlight on every sample instead of a few.
//
// DENSITY. With s(t) = maxComponent(sigmaMaj(t)) over the medium's majorant segments (the
// largest channel's, so that the density is the same whichever channel is the hero: p_c / p_h = 1
// in the spectral MIS of media/tracking.h) and S(t) the integral of s from 0 to t, the points
// have the density over [0, ray.tMax)
//     p(t) = s(t) exp(-S(t)) / (1 - exp(-S(tMax))):
// the distance to the first tentative collision of delta tracking at rate s, given that there is
// one within the ray. `count` points are drawn by inverting its distribution at the stratified
// quantiles (k + u_k) / count, k = 0 .. count - 1, so for any f that is 0 wherever s is 0,
//     sum_k f(t_k) weight_k,   weight_k = 1 / (count p(t_k)),
// estimates the integral of f over the ray without bias. For in-scattering, f = T sigmaS (phase
// function, light, shadow transmittance): sigmaS <= sigmaMaj <= s, so the weights never exceed
// what the transmittance estimate and the density's exponential allow.
//
// COST. Two walks over the medium's majorant segments (the total S(tMax), then the points), and no
// density lookup: the caller looks the medium up at the points and estimates the transmittance to
// them (ratio tracking over the stretches between consecutive points, media/ratio_tracking.h).
// A point that float rounding would push past the last segment's end is placed at that end.
#pragma once

#include <span>

#include "media/medium.h"
#include "media/tracking.h"

namespace fluence::media {

struct ForcedCollision {
    float t = 0.0f;       // along the ray, in increasing order over the points
    float weight = 0.0f;  // 1 / (count p(t))
};

// Draws u.size() points (u: numbers in [0, 1), one per stratum) into `points` (at least as long),
// in increasing t. Returns how many were drawn: u.size(), or 0 when the ray meets no majorant.
int sampleForcedCollisions(const Medium& medium, const MediumRay& ray, std::span<const float> u,
                           std::span<ForcedCollision> points);

}  // namespace fluence::media
