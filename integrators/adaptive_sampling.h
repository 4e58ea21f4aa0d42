// Adaptive sampling's decisions (RenderSettings::targetError, meanSamplesPerPixel): before each
// pass of the render loop (integrators/renderer.h), how many of the pass's samples each pixel takes.
//
// The error estimate. A pixel's relative variance per sample, a = mean over R G B of
// sigma_c^2 / (mean_c^2 + kRelativeFloor), where sigma_c^2 / n, the variance of the pixel's mean, is
// estimated from the difference of the means of the first and second halves of its samples (the
// film's half buffers, core/film.h): (first_c - second_c)^2 n_first n_second / n^2. Under the Sobol
// sampler each half of a power-of-two count is a net, so their difference measures the error
// Sobol's stratification leaves (the samples' own spread, or even- against odd-indexed halves,
// overstate it most where it is smallest: edges, direct light). One difference is a noisy
// estimate, so a is averaged over the pixel's 5x5 neighbourhood (kNeighbourhoodRadius 2; 3x3
// before: an allocation from 8 neighbours' one degree of freedom each came out up to 17% worse
// than from 24, bench/results/2026-12-06-adaptive-5.md), the pixel itself left out: a pixel
// whose own halves agree by luck amid noisy neighbours does not stop, the neighbours of a lone noisy
// pixel go on, and a pixel's decisions do not read its own samples, so a heavy-tailed pixel that
// has not yet drawn its rare bright samples (a low mean and a low spread together) is not stopped
// for it, which biased the image low (by 0.2-0.4% on the subsurface scene when the pixel counted).
// The neighbourhood is clipped to the pixel's kBlockSize x kBlockSize block of the image (blocks
// aligned to the image's origin), so a pixel's decisions depend on its block's pixels only: tiles
// whose edges fall on block edges (apps/frame_outputs.cpp) assemble into the one-piece render.
// The budget rule reads the larger of that and the mean of the same values over the pixel's whole
// block (63 pixels, the pixel itself left out again). Where the error is heavy-tailed (rare bright
// paths: the subsurface peer's back wall), 24 neighbours' halves have mostly not drawn a rare
// sample yet and read low; their pixels stopped at 16-50 samples against uniform's 128, and the
// rare sample one of them then drew stayed in the image as a firefly (six such pixels made the
// whole loss of that scene at seed 7). A block's 63 see rare samples more often. Selection seeds
// 11-13, relMSE at equal counted cost: 1.6%, 0.6% and 3.5% lower on the Cornell box, the smoke and
// the subsurface scene than the 5x5 mean alone; on the 8 evaluation seeds the smoke came out
// 0.1-0.9% worse instead (bench/results/2026-12-06-adaptive-7-s19.md). The target rule keeps the
// 5x5 mean (not measured with the block's).
// The floor (in the relMSE metric too, bench/) keeps near-black pixels from sampling forever.
//
// The rules. A pixel's relative standard error is e = sqrt(a / n) after n samples.
//  - Target (targetError E > 0): a pixel stops once e <= E. Every pixel ends near the same
//    relative noise: an even-looking image.
//  - Budget (meanSamplesPerPixel N > 0): the samples go where they lower the image's relative MSE
//    most for the CPU time. A pixel's samples do not all cost the same: where paths walk through
//    media or subsurface interiors they cost several times what a background pixel's do. Each
//    sample's cost is counted (rays traced, medium lookups and guided walk steps, integrators/sample_cost.h: counted,
//    not timed, so deterministic) and summed per pixel in the film; a pixel's cost per sample c is
//    the mean of its neighbours' (as a is, and for the same reason). For a sum of a_p / n_p over the
//    pixels with the total cost sum c_p n_p fixed, the best counts are n_p proportional to
//    sqrt(a_p / c_p) (Lagrange; not to a_p, which equalising e gives, and which spends exactly as
//    well as uniform sampling when every sample costs the same, and not to sqrt(a_p), which is
//    best only when they do). The budget is the cost of N uniform samples per pixel,
//    N sum_p c_p: `--mean-spp N` takes about the CPU time of `--spp N`. Before each pass the
//    factor is solved so that the pixels' costs add up to the budget, with stopped pixels at their
//    counts and the rest between what they have and samplesPerPixel; each pixel then takes the
//    pass's samples up to its count.
// Every pixel takes minSamples (at least kMinSamplesForHalves) before either rule applies. A pixel
// that takes fewer samples than the pass offers has stopped, for good. The decisions read the film
// between passes only, so they are the same at any thread count, and a render resumed from a pass
// boundary's film decides as the uninterrupted one did.
#pragma once

#include <cstdint>
#include <vector>

#include "core/film.h"

namespace fluence::integrators {

struct RenderSettings;

// The samples a pixel needs before its halves estimate anything (two in each).
inline constexpr int kMinSamplesForHalves = 4;

class AdaptiveSampling {
public:
    static constexpr int kBlockSize = 8;
    // The neighbourhood a pixel's a and c are averaged over: the (2 r + 1)^2 square (see the top).
    static constexpr int kNeighbourhoodRadius = 2;
    static constexpr double kRelativeFloor = 0.01;

    // Whether `settings` asks for adaptive sampling (either rule).
    static bool enabled(const RenderSettings& settings);

    // Per pixel of the film, row by row: the relative variance per sample a, averaged over the
    // neighbourhood (see the top of this file); 0 below kMinSamplesForHalves samples. The film is
    // the window at (windowX, windowY) of the image, and must keep the half buffers.
    static std::vector<double> neighbourhoodVariances(const Film& film, int windowX, int windowY);
    // What the budget rule reads: per pixel, the larger of neighbourhoodVariances and the mean of
    // the same relative variances over the pixel's block, itself left out (see the top).
    static std::vector<double> budgetVariances(const Film& film, int windowX, int windowY);
    // Per pixel of the film, row by row: the cost per sample c (Film::cost over the samples),
    // averaged over the same neighbourhood; 1 where no sample was counted.
    static std::vector<double> neighbourhoodCosts(const Film& film, int windowX, int windowY);

    // The samples per pixel of a uniform render that would cost what the film's samples cost, each
    // pixel's cost per sample its own mean: sum_p cost_p / sum_p (cost_p / n_p); the mean count
    // when no cost was counted.
    static double uniformSamplesOfTheSameCost(const Film& film);

    // A pass's plan (planPass).
    struct PassPlan {
        // Per pixel of the film, row by row: how many of the pass's samples [done, done + count) it
        // takes. Without adaptive sampling, count everywhere (a pixel that stopped before takes none).
        std::vector<std::uint32_t> samples;
        // The samples the film is expected to hold when the render ends, as the rules see it now (for
        // progress reports): a stopped pixel's count; an active pixel's goal: under the budget rule
        // the count it is to end with (before the rule applies, the mean the budget buys, N), else
        // samplesPerPixel.
        std::uint64_t expectedTotal = 0;
    };
    static PassPlan planPass(const Film& film, const RenderSettings& settings, int done, int count);
};

}  // namespace fluence::integrators
