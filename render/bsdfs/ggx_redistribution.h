// Where single-scattering GGX reflection sends the light, by elevation: for light arriving at
// mu_o, the share of what the lobe reflects that leaves at each elevation mu_i,
// tabulated as weights on the mu nodes of render/bsdfs/albedo_table.h. What a layer above a
// glossy base needs to know of the base (render/bsdfs/coat_return.h): how much of the base's
// reflection meets the layer where the layer reflects it back down.
//
//   spread_k(mu_o, alpha, f0) = integral hat_k(mu_i) f(wo, wi) cos theta_i dwi / E(mu_o, alpha, f0)
//   f: GGX reflection weighted by the Fresnel reflectance of f0 (render/bsdfs/ggx_albedo.h; 1 for
//      f0 = 1, the bare lobe of a metal), isotropic
//   hat_k: the piecewise-linear hat of the k-th of the 32 evenly spaced mu nodes, so that for
//          any g(mu) linear between the nodes, sum_k g(mu_k) spread_k = the mean of g(mu_i)
//          over the reflected light
//
// Each (mu_o, alpha) node's spread is integrated by the quadrature of albedo_table.h (the
// reflection off each of 32 x 32 visible normals of wo, binned by the hats): Fresnel's weight
// matters, since at grazing angles it favours the facets that send the light furthest from the
// mirror direction. A slice of one (alpha, f0) node of the axes of albedo_table.h is computed on
// first use and the spread is interpolated linearly in sqrt(alpha) and sqrt(f0).
#pragma once

#include <array>

#include "render/bsdfs/albedo_table.h"

namespace fluence::render {

using ElevationWeights = std::array<float, albedo_table::kCosines>;

// The light a lobe reflects from one direction, summed into the hats of the mu nodes as a
// quadrature visits it; normalised, the spread.
struct ElevationBins {
    std::array<double, albedo_table::kCosines> sum{};

    void add(float mu, double reflected) {
        const albedo_table::AxisPosition p = albedo_table::positionOf(mu, albedo_table::kCosines);
        sum[p.node] += reflected * (1.0f - p.fraction);
        sum[p.node + 1] += reflected * p.fraction;
    }
    // The shares of the total in each hat; all at `from` (the incident node) if nothing was
    // reflected.
    ElevationWeights spread(int from) const {
        double total = 0.0;
        for (double s : sum) total += s;
        ElevationWeights shares;
        for (int k = 0; k < albedo_table::kCosines; ++k)
            shares[k] = total > 0.0 ? float(sum[k] / total) : (k == from ? 1.0f : 0.0f);
        return shares;
    }
};

// The spread from the mu node i (wo at cosineAt(i)) at the width alpha and reflectance f0; sums
// to 1.
ElevationWeights ggxReflectionSpread(int i, float alpha, float f0);

}  // namespace fluence::render
