// The Newton-bisection inversion of a piece's optical depth, and the crossing found with it
// (media/exact_depth.h).
#include "media/exact_depth.h"

namespace fluence::media {

double invertIntegral(const ExtinctionPiece& piece, double length, double total, double remaining) {
    double lo = 0.0, hi = length, s = length * (remaining / total);
    for (int iteration = 0; iteration < 64; ++iteration) {
        const double g = integralAt(piece, s) - remaining;
        if (g < 0.0)
            lo = s;
        else
            hi = s;
        const double sigma = polynomialAt(piece, s);
        double next = sigma > 0.0 ? s - g / sigma : 0.5 * (lo + hi);
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        if (std::abs(next - s) <= 1e-15 * length || hi - lo <= 1e-15 * length) return next;
        s = next;
    }
    return s;
}

Vec3d unboundedPieceDepth(const ExtinctionPiece& piece) {
    Vec3d tau;
    for (int c = 0; c < 3; ++c) tau[c] = piece.scale[c] * piece.polynomial[0] > 0.0 ? INFINITY : 0.0;
    return tau;
}

void DepthCrossingSearch::stop(const ExtinctionPiece& piece, double total) {
    const double length = piece.tMax - piece.tMin, scale = piece.scale[hero];
    Vec3d& tau = crossing.tau;
    const double remaining = (target - tau[hero]) / scale;
    const double s =
        std::isfinite(length) ? invertIntegral(piece, length, total, remaining) : remaining / piece.polynomial[0];
    tau += piece.scale * integralAt(piece, s);
    crossing.sigmaT = piece.scale * std::max(polynomialAt(piece, s), 0.0);
    crossing.tStop = piece.tMin + s;
}

}  // namespace fluence::media
