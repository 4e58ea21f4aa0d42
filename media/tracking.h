// Majorant tracking: the one routine that walks a medium's majorant segments and draws tentative
// collisions along a ray (after pbrt-v4's SampleT_maj; Pharr, Jakob & Humphreys, "Physically
// Based Rendering", 4th ed., section 14.2). Every volumetric estimator is built on it: ratio
// tracking (media/ratio_tracking.h) for transmittance, delta tracking (media/free_flight.h) for
// free-flight sampling; a random walk, BDPT or photon tracing would be too. None of them looks
// inside a medium: they see its coefficients at the points drawn here, and its majorants.
// Conventions (units, majorants, minorants) are those of media/medium.h.
//
// THE NULL-COLLISION FORMULATION (Miller, Georgiev & Jarosz 2019, "A null-scattering path
// integral formulation of light transport", sections 3 and 4). A fictitious null coefficient
// sigmaN = sigmaMaj - sigmaT >= 0 fills the medium up to its majorant, and the radiance arriving
// at the start of a ray, per channel, becomes
//     L(0) = integral_0^tMax Tmaj(t) [sigmaA Le + sigmaS Ls + sigmaN L](t) dt + Tmaj(tMax) L(tMax),
//     Tmaj(t) = exp(-integral_0^t sigmaMaj),
// with Ls the radiance scattered in (the phase function against L). Expanding the sigmaN L term
// again and again, a flight through a medium is a sequence of points t1 < t2 < ... < tn, each
// null, absorbing or scattering, and its contribution f is the product, over the stretches
// between consecutive points, of Tmaj over the stretch times the coefficient of the point that
// ends it: sigmaN, sigmaA Le, or sigmaS times the phase function; Tmaj(tMax - tn) ends a flight
// that leaves. Transmittance is the sum over the flights of null points only:
//     T(t) = sum_n integral Tmaj(t1) sigmaN(t1) Tmaj(t2 - t1) sigmaN(t2) ... Tmaj(t - tn) dt1..dtn.
//
// SAMPLING. trackMajorants() draws the points as a Poisson process along the ray whose rate is
// the hero channel h's sigmaMaj (TrackingRate::Majorant: delta tracking) or sigmaMaj - sigmaMin
// (TrackingRate::Residual: ratio tracking), piecewise constant over the segments: exponential
// steps, drawn again at each segment boundary (the process is memoryless). Had channel c been the
// hero, a point at distance s after the previous point (or the ray's start) would have had density
//     Majorant rate:  Tmaj_c(s) sigmaMaj_c
//     Residual rate:  Tres_c(s) (sigmaMaj_c - sigmaMin_c)   (TentativeCollision::residualPdf)
// with Tres = exp(-integral (sigmaMaj - sigmaMin)), and reaching the end of the ray with no further
// point, probability Tmaj_c or Tres_c over the last stretch (the routine's return value). The
// callback sees both transmittances since the previous point, so either pdf is known in every
// channel whichever rate drew the points.
//
// SPECTRAL MIS (the hero estimator of Miller et al. 2019, section 5.2; hero wavelengths: Wilkie
// et al. 2014, "Hero wavelength spectral sampling"). Media are chromatic, and one distance serves
// all three channels; it is drawn from the rates of one channel, the hero, chosen uniformly at
// random once per path: h = sampleHeroChannel(u). Let f_c(x) be the contribution of a flight (or a
// whole path) x in channel c and p_c(x) its density had c been the hero. One-sample multiple
// importance sampling over the three equally likely heroes with the balance heuristic weights
// the sample drawn with hero h by p_h / (p_0 + p_1 + p_2), which gives
//     F_c(x) = f_c(x) / ((p_0(x) + p_1(x) + p_2(x)) / 3),
// an unbiased estimate of the integral of f_c for every c as long as p_c(x) > 0 wherever
// f_c(x) != 0: so it is here (below, f_c <= p_c point by point). Products of densities under-
// and overflow along a path, so every routine returns them divided by the hero's density:
//     throughput = f / p_h,   pdfRatio = p / p_h  (1 in the hero channel),
//     F = throughput / channelAverage(pdfRatio),
// and the ratios of consecutive pieces of a path multiply. F_c <= 3 f_c / p_c: with f_c <= p_c,
// as for both estimators below, a flight's estimate is at most 3, whatever the hero and however
// the channels differ. (A fixed hero, F_c = f_c / p_h, would miss every point where the hero's
// rate is 0 but f_c is not, and its weights grow as exp((sigma_h - sigma_c) t).)
//
// THE ESTIMATORS.
//   Ratio tracking (ratioTrackingTransmittance; Novak, Selle & Jarosz 2014, "Residual ratio
//     tracking for estimating attenuation in participating media", with the minorant as its
//     control): residual rate, every point null. f_c = Tmaj_c sigmaN_c per point and Tmaj_c at
//     the end, p_c = Tres_c (sigmaMaj_c - sigmaMin_c) and Tres_c; f_c <= p_c since
//     sigmaMin <= sigmaT. With sigmaMin = 0 it is plain ratio tracking (Cramer 1978); where
//     sigmaMin = sigmaMaj (a homogeneous medium) no point is drawn and the estimate is exact.
//   Delta tracking (sampleFreeFlight; Woodcock et al. 1965): majorant rate; at each point the
//     hero chooses absorption, scattering or a null collision with probabilities sigmaA_h,
//     sigmaS_h, sigmaN_h over sigmaMaj_h; a null collision goes on. A point of kind k has
//     f_c = Tmaj_c sigma_k,c (times Le or the phase function, which the caller applies) and
//     p_c = Tmaj_c sigmaMaj_c sigma_k,c / sigmaMaj_c = f_c; escaping, f_c = p_c = Tmaj_c.
//   Unbiased ray marching (rayMarchingTransmittance, media/ray_marching_transmittance.h; Kettunen
//     et al. 2021) is the one transmittance estimator not built on trackMajorants(): it walks the
//     same majorant segments with evenly spaced combs of points and samples no channel and no null
//     point (pdfRatio 1), so it serves only where no strategy is weighted against it by null-point
//     densities (below). media/transmittance.h chooses between it and ratio tracking.
//   Emission is scored where a flight is absorbed (an absorption estimator: F = throughput Le
//   / channelAverage(pdfRatio)); pbrt-v4's collision estimator, which scores sigmaA Le / sigmaMaj
//   at every tentative collision, has less variance in thin emitting media and would be built on
//   trackMajorants() the same way.
//
// HOW A PATH TRACER USES THEM, with next-event estimation and MIS (as pbrt-v4's VolPathIntegrator
// does, in this file's terms). A path carries its hero h (drawn once, at the camera), beta =
// f / p_h, rU = p_c / p_h of the path as sampled (phase/BSDF sampling and delta tracking), and
// rL = the same path's density had its last segment been drawn by light sampling, over p_h:
//   Through a medium up to the next surface at distance tHit:
//     FreeFlight flight = sampleFreeFlight(medium, {x, w, tHit}, h, stream);
//     beta *= flight.throughput;  rU *= flight.pdfRatio;  rL *= flight.lightPdfRatio;
//     Absorbed:  L += beta * flight.properties.emission / channelAverage(rU); the path ends.
//     Scattered: at flight.p, with wo = -w, phase function HG(flight.properties.g):
//       next-event estimation: a light sample (wi, Le, lightPdf at distance d), then
//         TransmittanceEstimate tr = ratioTrackingTransmittance(medium, {flight.p, wi, d}, h, stream);
//         L += beta * HG.p(wo, wi) * tr.throughput * Le
//              / channelAverage(rU * (lightPdf * tr.pdfRatio + HG.pdf(wo, wi) * tr.throughput));
//         (tr.throughput is also delta tracking's density ratio for the same null points; drop
//         the second term for a delta light, which phase sampling cannot hit: then any unbiased
//         estimate with pdfRatio 1 serves as tr, and `path` ray-marches those shadow rays);
//       phase sampling: s = HG.sample(wo, u); beta *= s.p / s.pdf (= 1); rL = rU / s.pdf;
//       the path goes on along s.wi.
//     Escaped: the path reaches the surface at tHit. If it is an emitter reached after a
//       scattering: rL *= lightPdf (the light's solid-angle density for this direction) and
//       L += beta * Le / channelAverage(rU + rL); seen from the camera or after a delta
//       (specular) event, which light sampling cannot produce: L += beta * Le / channelAverage(rU).
//   A shadow ray or a flight that crosses several media (or several stretches of one) makes one
//   call per stretch, and multiplies the ratios. Everything is drawn from the path's SampleStream, so the estimate is a
//   pure function of (seed, pixel, sample).
#pragma once

#include <algorithm>
#include <limits>

#include "core/function_ref.h"
#include "core/random.h"
#include "core/rgb.h"
#include "core/vec.h"
#include "media/medium.h"

namespace fluence::media {

// origin + t direction for t in [0, tMax); direction is a unit vector; tMax may be infinite.
struct MediumRay {
    Vec3f origin, direction;
    float tMax = std::numeric_limits<float>::infinity();
    Vec3f at(float t) const { return origin + direction * t; }
};

inline float channelAverage(const RGB& c) { return (c.x + c.y + c.z) / 3.0f; }

// The path's hero channel, uniform over the three from u in [0, 1) (see SPECTRAL MIS).
inline int sampleHeroChannel(float u) { return std::min(2, static_cast<int>(u * 3.0f)); }

enum class TrackingRate {
    Majorant,  // sigmaMaj: wherever the medium may collide (delta tracking)
    Residual,  // sigmaMaj - sigmaMin: only where sigmaT may differ from its minorant (ratio tracking)
};

// A point drawn by trackMajorants(), with what every estimator needs there.
struct TentativeCollision {
    float t = 0.0f;
    Vec3f p;                      // ray.at(t)
    MediumProperties properties;  // medium.at(p)
    RGB sigmaMaj, sigmaMin;       // the bounds of the segment holding p
    RGB tMaj, tResidual;          // exp(-integral sigmaMaj), exp(-integral (sigmaMaj - sigmaMin)), from
                                  // the previous point (or the ray's start) to t

    RGB sigmaT() const { return properties.sigmaA + properties.sigmaS; }
    RGB sigmaN() const { return vmax(sigmaMaj - sigmaT(), RGB(0.0f)); }  // the null coefficient
    RGB residualRate() const { return vmax(sigmaMaj - sigmaMin, RGB(0.0f)); }
    // Per channel c: the density of this point had c been the hero and the rate been residual
    // (see SAMPLING; at the majorant rate it is tMaj * sigmaMaj).
    RGB residualPdf() const { return tResidual * residualRate(); }
};

// tMaj and tResidual over a stretch of a ray (the last point's to the ray's end).
struct MajorantTransmittance {
    RGB tMaj{1.0f}, tResidual{1.0f};
};

// Draws tentative collisions along `ray` through `medium` at `rate` in channel `hero` (0, 1 or 2),
// calling `atCollision` at each in increasing t until it returns false or the ray ends. Returns the
// transmittances from the last point (or the start) to ray.tMax if the ray ended, (1, 1) if
// `atCollision` stopped the walk. Randomness: one number from `stream` per exponential step.
// Queries the medium's majorants over [0, ray.tMax) once.
MajorantTransmittance trackMajorants(const Medium& medium, const MediumRay& ray, TrackingRate rate, int hero,
                                     SampleStream& stream, FunctionRef<bool(const TentativeCollision&)> atCollision);

}  // namespace fluence::media
