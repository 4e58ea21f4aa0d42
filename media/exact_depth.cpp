// The Newton-bisection inversion of a piece's optical depth (media/exact_depth.h).
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

}  // namespace fluence::media
