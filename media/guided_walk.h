// Guided random walks in a homogeneous subsurface medium: Dwivedi sampling combined with classic
// sampling by multiple importance sampling (SubsurfaceMethod::RandomWalkGuided).
//
// THE IDEA (Krivanek & d'Eon 2014, "A zero-variance-based sampling scheme for Monte Carlo
// subsurface scattering"; Meng, Hanika & Dachsbacher 2016, "Improving the Dwivedi sampling
// scheme"). Deep in a half-space of single-scattering albedo alpha < 1, the light that will leave
// through its flat surface falls off with depth z as exp(-z sigmaT / nu), nu the Dwivedi
// eigenvalue of alpha (nu > 1; nu -> 1 as alpha -> 0, nu -> infinity as alpha -> 1). Sampling
// each step in proportion to that importance gives
//   directions: mu = dot(wi, axis) with density 1 / ((nu - mu) ln((nu + 1) / (nu - 1))) on [-1, 1]
//               (phi uniform), peaked towards `axis`, the entry's outward normal;
//   distances:  exponential at the stretched rate sigmaT (1 - mu / nu), longer towards the
//               surface;
// so walks head for the surface and leave where they would contribute. nu comes from d'Eon &
// Krivanek's fit (2020, "Zero-variance theory for efficient subsurface scattering", Eq. 67) of
//   nu(alpha) = 1 / sqrt(1 - alpha^(2.44294 - 0.0215813 alpha + 0.578637 / alpha)),
// clamped to [kMinNu, kMaxNu] (any nu > 1 gives a normalised density: the clamp only changes how
// strongly the walk is guided).
//
// BACKWARD GUIDING (a thin object). When the entry ray reached the far side at depth d below the
// entry plane, a walk at depth x in [0, d] may also be guided along -axis, towards that side,
// with probability b = 1 / (1 + exp((d - 2x) / L)), L = nu / sigmaT the diffusion length: rarely
// near the entry, half the time half-way, mostly near the far side (the same weighting Cycles'
// guided walk uses, from recorded path guiding). With no far side seen, b is 0.
//
// THE STEP AND ITS MIS. After a scattering a step is a direction and a length together; it is
// drawn by one of three strategies: classic (Henyey-Greenstein direction, exponential at sigmaT),
// guided towards the entry's surface, or guided away from it, chosen with probabilities 1 - f,
// f (1 - b) and f b, f = kGuidedFraction (1 - |g|) (the guided directions ignore anisotropy, so
// a forward-scattering medium relies on the classic ones). The step's density in channel c is the
// mixture of the three, each with channel c's sigmaT and nu (the one-sample balance heuristic over
// the strategies); stepPdf gives it per channel, and the path tracer's spectral MIS (media/
// tracking.h, with the hero channel drawn once per path) combines the channels as it does for
// classic flights. The step's value is p(wo, wi) sigmaS_c exp(-sigmaT_c t) at a collision, and
// p(wo, wi) exp(-sigmaT_c t) when the step reaches the boundary at t. The first step, from the
// entry along the direction the boundary refracted into, has no direction to choose: classic
// distance sampling. A collision scatters, always: the walk plays Russian roulette instead,
// surviving with probability max_c alpha_c and weighted by its inverse, which ends walks in a dark
// medium as the classic walk's absorptions do. Unbiased for any medium of albedo <= 1: every
// strategy has a positive density wherever the classic one has.
#pragma once

#include "core/random.h"
#include "core/rgb.h"
#include "core/vec.h"
#include "media/free_flight.h"
#include "media/medium.h"

namespace fluence::media {

inline constexpr float kGuidedFraction = 0.5f;  // of the steps guided, in an isotropic medium
inline constexpr double kMinNu = 1.0001, kMaxNu = 1e4;

// The Dwivedi eigenvalue nu of single-scattering albedo `albedo` (see THE IDEA), clamped.
double dwivediNu(double albedo);
// The density of mu = dot(wi, axis) on [-1, 1] under guided sampling with eigenvalue nu.
double dwivediCosinePdf(double nu, double mu);
// The mu drawn from u in [0, 1) (the inverse of that density's distribution function).
double sampleDwivediCosine(double nu, double u);

enum class WalkStrategy { Classic, TowardsEntry, AwayFromEntry };

// A step of the walk, as the scattering that started it drew it.
struct WalkStep {
    Vec3f origin, wo, wi;  // wo: towards where the walk came from (unused on the first step)
    bool first = false;    // from the entry, along the refracted direction: classic distances only
    WalkStrategy strategy = WalkStrategy::Classic;
};

class GuidedWalk {
public:
    // A walk that entered a medium of coefficients `m` at `entry`, through a surface of outward
    // geometric normal `outwardNormal`.
    GuidedWalk(const Vec3f& entry, const Vec3f& outwardNormal, const MediumProperties& m);

    // A step from the surface reached the boundary `distance` along `direction`: the far side,
    // for backward guiding (the first such step, the entry's, sets it; later ones change nothing).
    void sawFarSide(const Vec3f& direction, float distance);

    // The step after a scattering at p (the walk arrived from wo), drawn with channel `hero`'s
    // mixture of strategies, from three numbers in [0, 1).
    WalkStep sampleStep(const Vec3f& p, const Vec3f& wo, int hero, float uStrategy, Vec2f uDirection) const;

    // Per channel, the density of `step` having length t, ending at a collision or (not
    // `collided`) at the boundary: the mixture of the strategies (see THE STEP AND ITS MIS).
    RGB stepPdf(const WalkStep& step, float t, bool collided) const;

    // The step's flight up to the boundary at tBoundary, in FreeFlight's terms (its throughput
    // includes the direction's phase value and density; pdfRatio is channel c's density over
    // the hero's), with the Russian roulette at a collision.
    FreeFlight fly(const WalkStep& step, float tBoundary, int hero, SampleStream& stream) const;

private:
    // The probability of guiding a step from p away from the entry (see BACKWARD GUIDING).
    double backwardFraction(const Vec3f& p, int channel) const;

    Vec3f entry_, axis_;
    MediumProperties medium_;
    RGB sigmaT_;
    double nu_[3];
    float guidedFraction_, survival_;
    float farDepth_ = -1.0f;  // depth of the far side below the entry plane; < 0: not seen
};

}  // namespace fluence::media
