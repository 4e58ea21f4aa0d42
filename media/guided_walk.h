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
// THE STEP AND ITS MIS. Each step is drawn with the coefficients of one channel, in one of two
// ways (WalkChannels). A HERO PER WALK (the default): the walk draws its hero h once, with
// probability P_h proportional to h's mean free path 1 / sigmaT_h, mixed with a uniform choice
// (kHeroFloor; 0.99 and 1.00 of the pure one's relMSE x CPU on the peer and the sample, within
// noise, bench/results/2026-12-06-hero-exponent-s21.md: a floor against channels left to a
// thousandth of the walks by a mean free path a thousand times shorter), and draws every step with h's
// coefficients; as in hero-wavelength spectral sampling (Wilkie et al. 2014; pbrt-v4 keeps such
// ratios along its volumetric paths) the walk's value f_c in channel c is weighted by the balance
// heuristic over whole walks, f_c / sum_k P_k prod_steps p_k(step), p_k the step's density under
// channel k (below). A red walk stays red, and its red estimate is not diluted by steps drawn
// with green or blue coefficients. The products are kept as ratios to the hero's, r_k = prod p_k /
// prod p_h (r_h = 1), and each step divides its value by p_h times the change of sum_k P_k r_k,
// so that the steps' divisors multiply to the sum and every exit sees the weight of the walk so
// far. The walks of an entry split N ways (integrators/path_tracer.h) take stratified heroes
// (u, u + 1/N, ... mod 1). Where a red mean free path five and ten times the green and blue ones
// made red 78% of the error, the hero walk took the Cycles peer's relMSE to 0.75x at 0.95x the CPU;
// P_h uniform or by albedo did worse than per step (bench/results/2026-12-06-walk-hero-s21.md).
// A CHANNEL PER STEP: c chosen anew at every step with probability P_c proportional to alpha_c T_c,
// T the walk's weight so far (uniform when that is zero everywhere), as Cycles' random walk
// chooses them, and each step weighted by the balance heuristic over its own densities, the
// mixture sum_c P_c p_c(step). After a scattering a step is a direction and a length
// together, drawn by one of three strategies: classic (Henyey-Greenstein direction, exponential
// at sigmaT_c), guided towards the entry's surface, or guided away from it, chosen with
// probabilities 1 - f, f (1 - b) and f b, f = kGuidedFraction (1 - |g|) (the guided directions
// ignore anisotropy, so a forward-scattering medium relies on the classic ones). The step's
// density under channel c, p_c, is the mixture of the three with c's sigmaT and nu (stepPdf);
// per step, the step's density as drawn is sum_c P_c p_c: the one-sample balance heuristic over
// the nine (channel, strategy) pairs, which fly divides by. The step's value is
// p(wo, wi) sigmaS_c exp(-sigmaT_c t) at a collision, and p(wo, wi) exp(-sigmaT_c t) when the
// step reaches the boundary at t. The first step, from the entry along the direction the
// boundary refracted into, has no direction to choose: classic distance sampling at the chosen
// channel's rate. Nothing a step draws depends on the path's hero channel (a walk's hero is its
// own), and the walk's density either way is the same in every channel, so to the path tracer's
// spectral MIS (media/tracking.h) the walk is one strategy shared by every hero: its pdfRatio is
// 1. A collision scatters, always: the walk plays Russian roulette instead, surviving with
// probability min(1, max_c T_c) and weighted by its inverse (the weight after the MIS, so a walk
// whose every channel has faded ends, and its survivors keep weights near 1; with a hero, that
// weight is a function of the walk alone, not of which hero drew it). Unbiased for any medium of
// albedo <= 1: every strategy has a positive density wherever the classic one has, and every
// chosen channel's classic strategy covers every length (with a hero, P_h > 0 for every channel
// with sigmaT_h > 0; one of sigmaT 0 scatters nothing, and the walks that bring its light, which
// leave without a collision, the other heroes draw too).
//
// THE COST OF A STEP. The length is drawn before the boundary is known (sampleLength), so the
// path tracer traces each step's ray only that far: no surface is shaded unless the walk leaves,
// and Embree culls what lies beyond. The entry's step is traced on to the far side, for backward
// guiding. The nine densities of a step take three exponentials per channel in float (density):
// the channel's transmittance T = exp(-sigmaT t), which the step's value shares, the factor
// q = exp(-sigmaT t |mu| / nu) between it and the two guided lengths' transmittances
// (exp(-sigmaT t (1 -+ mu / nu)) = T / q and T q, in the order of mu's sign), and the backward
// fraction's; where T is below float's normal range (sigmaT t > kFactoredExponentLimit), T / q
// would be 0 / 0, and the guided ones are taken directly. A walk's Dwivedi eigenvalues are a
// pure function of its albedos, remembered per thread (dwivediConstants).
#pragma once

#include "core/random.h"
#include "core/rgb.h"
#include "core/vec.h"
#include "media/free_flight.h"
#include "media/medium.h"

namespace fluence::media {

inline constexpr float kGuidedFraction = 0.5f;  // of the steps guided, in an isotropic medium
// The share of a hero walk's channel choice that is uniform over the channels with sigmaT > 0 (the
// rest by mean free path): a floor, so that a channel of a far shorter mean free path than another
// is still a hero often enough (THE STEP AND ITS MIS).
inline constexpr float kHeroFloor = 0.1f;
inline constexpr double kMinNu = 1.0001, kMaxNu = 1e4;
// Above this exponent exp(-x) (< 1.8e-35) is too near float's smallest normal number (1.2e-38)
// for the guided transmittances to be taken as quotients of it (see THE COST OF A STEP).
inline constexpr float kFactoredExponentLimit = 80.0f;

// The Dwivedi eigenvalue nu of single-scattering albedo `albedo` (see THE IDEA), clamped.
double dwivediNu(double albedo);
// The density of mu = dot(wi, axis) on [-1, 1] under guided sampling with eigenvalue nu.
double dwivediCosinePdf(double nu, double mu);
// The mu drawn from u in [0, 1) (the inverse of that density's distribution function).
double sampleDwivediCosine(double nu, double u);

enum class WalkStrategy { Classic, TowardsEntry, AwayFromEntry };

// How a walk chooses the channel whose coefficients draw its steps (THE STEP AND ITS MIS).
enum class WalkChannels {
    PerStep,  // anew at every step, P_c proportional to alpha_c T_c: MIS per step
    Hero,     // once per walk, its hero, P_h by the mean free path (and kHeroFloor): MIS over whole walks
};

// A step of the walk, as the scattering that started it drew it.
struct WalkStep {
    Vec3f origin, wo, wi;  // wo: towards where the walk came from (unused on the first step)
    bool first = false;    // from the entry, along the refracted direction: classic distances only
    WalkStrategy strategy = WalkStrategy::Classic;
    int channel = 0;  // whose coefficients drew it
};

class GuidedWalk {
public:
    // A walk that entered a medium of coefficients `m` at `entry`, through a surface of outward
    // geometric normal `outwardNormal`.
    // `channels`: how its steps choose their channel; with a hero, uHero in [0, 1) draws it.
    GuidedWalk(const Vec3f& entry, const Vec3f& outwardNormal, const MediumProperties& m,
               WalkChannels channels = WalkChannels::PerStep, float uHero = 0.0f);

    // A step from the surface reached the boundary `distance` along `direction`: the far side,
    // for backward guiding (the first such step, the entry's, sets it; later ones change nothing).
    void sawFarSide(const Vec3f& direction, float distance);

    // The probabilities P_c of drawing a step with channel c's coefficients (see THE STEP AND ITS
    // MIS; with a hero, those of drawing the hero).
    RGB channelProbabilities() const;
    // The channel of the next step: drawn from u in [0, 1) with channelProbabilities() (per step),
    // or the walk's hero (u unused).
    int stepChannel(float u) const;
    // A walk with a hero draws it again from u, before its first step (another walk of the same
    // entry); the u that drew the hero (0 per step).
    void chooseHero(float u);
    float heroSample() const { return heroSample_; }
    // Whether the walk draws its steps with a hero (stepChannel then reads no number).
    bool hasHero() const { return hero_ >= 0; }

    // The entry's step from `origin` along wi, the direction the boundary refracted into.
    WalkStep firstStep(const Vec3f& origin, const Vec3f& wi, int channel) const;
    // The step after a scattering at p (the walk arrived from wo), drawn with channel `channel`'s
    // mixture of strategies, from three numbers in [0, 1).
    WalkStep sampleStep(const Vec3f& p, const Vec3f& wo, int channel, float uStrategy, Vec2f uDirection) const;

    // The step's length, were there no boundary, from u in [0, 1).
    float sampleLength(const WalkStep& step, float u) const;

    // Per channel, the density of `step` having length t, ending at a collision or (not
    // `collided`) at the boundary: the mixture of the strategies (see THE STEP AND ITS MIS).
    RGB stepPdf(const WalkStep& step, float t, bool collided) const;

    // The step's flight of sampled `length` up to the boundary at tBoundary, in FreeFlight's terms
    // (its throughput includes the direction's phase value and the mixture density; pdfRatio 1),
    // with the Russian roulette at a collision; the walk's weight takes the flight's.
    FreeFlight fly(const WalkStep& step, float length, float tBoundary, SampleStream& stream);

private:
    // A step's densities (stepPdf) with what the step's value shares with them: per channel, the
    // transmittance exp(-sigmaT t), and the phase function's value (1 for the entry's step).
    struct Density {
        RGB pdf, transmittance;
        float phase = 1.0f;
    };
    Density density(const WalkStep& step, float t, bool collided) const;
    // What fly divides a step's value by, given its densities per channel (THE STEP AND ITS MIS);
    // with a hero it updates the walk's density ratios.
    float stepDivisor(const RGB& pdf);

    // The depth of p below the entry plane, clamped to the far side's (0 when it is not seen),
    // and the probability, at that depth, of guiding channel c's step away from the entry (see
    // BACKWARD GUIDING).
    float backwardDepth(const Vec3f& p) const;
    float backwardFraction(float depth, int channel) const;

    Vec3f entry_, axis_;
    MediumProperties medium_;
    RGB sigmaT_, albedo_;
    double nu_[3], lnRatio_[3];        // per channel: nu and ln((nu + 1) / (nu - 1)),
    float directionNorm_[3];           // 1 / (2 pi lnRatio), the guided directions' constant,
    float inverseDiffusionLength_[3];  // and sigmaT / nu
    float guidedFraction_;
    WalkChannels channels_;
    RGB heroProbabilities_{1.0f / 3.0f};  // P_h (with a hero)
    int hero_ = -1;                       // -1: a channel per step
    float heroSample_ = 0.0f;
    RGB densityRatio_{1.0f};  // with a hero, per channel the walk's density over the hero's
    RGB throughput_{1.0f};    // T, the walk's weight since the entry
    float farDepth_ = -1.0f;  // depth of the far side below the entry plane; < 0: not seen
};

}  // namespace fluence::media
