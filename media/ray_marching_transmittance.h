// Transmittance by unbiased ray marching (after Kettunen, d'Eon, Pantaleoni & Novák 2021, "An
// unbiased ray-marching transmittance estimator"): a ray-marched optical depth as the control of a
// power series in the residual, whose randomly truncated higher orders remove ray marching's bias.
//
// THE ESTIMATOR, per channel c, along a ray through `medium` from 0 to tMax. The optical depth
// splits into the minorants' part, known exactly segment by segment, and the residual:
//     tau_c = tauMin_c + tauRes_c,   tauMin_c = integral sigmaMin_c,   tauRes_c = integral (sigmaT_c - sigmaMin_c).
//   A comb estimates tauRes. Let w = max_c (sigmaMaj_c - sigmaMin_c), constant over a segment,
//   U(t) = integral_0^t w (the residual majorant's optical depth, one for all channels), and
//   tauR = U(tMax). A comb of offset xi in [0, 1) places M = ceil(tauR / stepDepth) points at
//   u_j = (j + xi) tauR / M, j = 0..M-1, i.e. at t_j = U^-1(u_j), and sums
//       R_c(xi) = (tauR / M) sum_j (sigmaT_c(t_j) - sigmaMin_c(t_j)) / w(t_j).
//   Each u_j is uniform over its stratum of [0, tauR) when xi is uniform, and the summand is the
//   residual's density in u, so E[R_c] = tauRes_c (systematic sampling: unbiased, and exact where
//   the residual is constant in u).
//   The series: draw the control C_c = R_c(xi_0) and keep it fixed. Then
//       T_c = exp(-tauMin_c - C_c) exp(C_c - tauRes_c) = exp(-tauMin_c - C_c) sum_k (C_c - tauRes_c)^k / k!.
//   Draw an order K >= 1 with P(K >= k) = q^(k-1) (Russian roulette with continuation q) and K more
//   combs, X_i,c = C_c - R_c(xi_i), i = 1..K: independent, each of mean C_c - tauRes_c given C.
//   The U-statistic e_k(X_1..X_K) / binomial(K, k), with e_k the elementary symmetric polynomial
//   (the mean of the products over every k of the K samples), is an unbiased estimate of
//   (C_c - tauRes_c)^k for k <= K, so
//       T^_c = exp(-tauMin_c - C_c) sum_{k=0..K} e_k(X) / (binomial(K, k) k! P(K >= k))
//   has E[T^_c | C] = T_c for every control, hence E[T^_c] = T_c. Ray marching alone would be the
//   k = 0 term, exp(-tauMin - C), biased high (E[exp(-C)] >= exp(-tauRes), Jensen's inequality);
//   the first-order term cancels the control's own error to first order at every sample, and the
//   rarer higher orders the rest. Where every comb gives the same R (a constant residual along u,
//   e.g. a homogeneous medium, or no residual at all) every X is 0 and T^ = exp(-tau) exactly.
//   To first order in the combs' errors T^ = T (1 - (R(xi_1) - tauRes)): its variance is about
//   T^2 Var(R), the control's error cancelling. Plain ratio tracking's relative variance is
//   exp(integral (sigmaMaj - sigmaT)^2 / sigmaMaj) - 1: set by the distance between majorant and
//   density, however smooth the density is.
//
// T^ is unbiased but not bounded: it can be negative or above 1 (rarely, where a comb misses a
// sharp feature). Every number is drawn from `stream` whatever the hero (one per comb's offset,
// one per roulette decision): no channel is sampled, so pdfRatio is 1 and throughput is T^, and
// an integrator multiplies a light sample by it without weighting it against a strategy that
// samples null points (media/tracking.h). Work: (K + 1) M lookups, E[K] = 1 / (1 - q).
//
// A stretch of residual majorant reaching to infinity cannot be marched: such a ray is ratio-
// tracked instead (media/ratio_tracking.h, with `hero`), as it would have been.
#pragma once

#include "core/random.h"
#include "media/medium.h"
#include "media/tracking.h"
#include "media/transmittance_estimate.h"

namespace fluence::media {

// The defaults were chosen on the Cycles peer's smoke (bench/results/2026-12-05-ray-marching-
// transmittance.md): per-sample error and CPU against ratio tracking at steps 1, 1.5, 2 and 4 and
// continuations 0.5 and 0.25; a step of 4 multiplied the error by 3, steps 1 to 2 at q = 0.25 all
// gained about 10% in efficiency, and 1 keeps the most margin.
struct RayMarchingSettings {
    float stepDepth = 1.0f;      // residual majorant optical depth between a comb's points
    float continuation = 0.25f;  // q: the probability of each order beyond the first
};

// The transmittance of ray.origin -> ray.at(ray.tMax) through `medium` (hero: only for the
// ratio-tracking fallback above).
TransmittanceEstimate rayMarchingTransmittance(const Medium& medium, const MediumRay& ray, int hero,
                                               SampleStream& stream, const RayMarchingSettings& settings = {});

}  // namespace fluence::media
