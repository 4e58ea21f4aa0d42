// Where the Charlie sheen lobe (render/bsdfs/sheen.h) sends the light, by elevation: for light
// arriving at mu_o, the share of what the lobe reflects that leaves at each elevation mu_i, as
// weights on the mu nodes of render/bsdfs/albedo_table.h; the sheen's counterpart of
// render/bsdfs/ggx_redistribution.h, for a coat over sheen (render/bsdfs/coat_return.h).
//
//   spread_k(mu_o, r) = integral hat_k(mu_i) f(wo, wi) cos theta_i dwi / E(mu_o, r)
//   hat_k: the piecewise-linear hat of the k-th of the 32 evenly spaced mu nodes
//
// Each (mu_o, r) node's spread is integrated by the sheen tables' quadrature (1024 points over
// the hemisphere, crowded towards the horizon, binned by the hats). A slice of one roughness node
// of the sheen tables' axis (24 values over [0.1, 1]) is computed on first use (about a
// millisecond: 32 x 1024 evaluations of the lobe) and the spread is interpolated linearly in r.
#pragma once

#include "render/bsdfs/ggx_redistribution.h"

namespace fluence::render {

// The spread from the mu node i (wo at cosineAt(i)) of the sheen of roughness r; sums to 1.
ElevationWeights sheenReflectionSpread(int i, float roughness);

}  // namespace fluence::render
