#include "media/exact_tracking.h"

#include <algorithm>
#include <cmath>

namespace fluence::media {
namespace {

// The cubic and its integral over [0, s] (OPTICAL DEPTH), before the channel's scale.
double polynomialAt(const ExtinctionPiece& piece, double s) {
    const double* k = piece.polynomial;
    return ((k[3] * s + k[2]) * s + k[1]) * s + k[0];
}
double integralAt(const ExtinctionPiece& piece, double s) {
    const double* k = piece.polynomial;
    return (((k[3] * 0.25 * s + k[2] * (1.0 / 3.0)) * s + k[1] * 0.5) * s + k[0]) * s;
}

// The s in [0, length] where the piece's integral reaches `remaining` (0 < remaining <= its
// integral `total` over the piece): Newton's method on the monotone integral, kept inside a
// shrinking bracket by bisection, to double precision.
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

RGB transmittanceOf(const Vec3d& tau) {
    return RGB(float(std::exp(-tau.x)), float(std::exp(-tau.y)), float(std::exp(-tau.z)));
}

}  // namespace

TransmittanceEstimate exactTransmittance(const Medium& medium, const MediumRay& ray) {
    Vec3d tau(0.0);
    int pieces = 0;
    medium.extinctionPieces(ray.origin, ray.direction, 0.0f, ray.tMax, [&](const ExtinctionPiece& piece) {
        ++pieces;
        tau += piece.scale * integralAt(piece, piece.tMax - piece.tMin);
        return true;
    });
    TransmittanceEstimate tr;
    tr.throughput = transmittanceOf(tau);
    tr.collisions = pieces;
    return tr;
}

FreeFlight sampleExactFlight(const Medium& medium, const MediumRay& ray, int hero, float u) {
    const double target = -std::log1p(-double(u));
    Vec3d tau(0.0), sigmaT(0.0);
    double tStop = -1.0;
    int pieces = 0;
    medium.extinctionPieces(ray.origin, ray.direction, 0.0f, ray.tMax, [&](const ExtinctionPiece& piece) {
        ++pieces;
        const double length = piece.tMax - piece.tMin, scale = piece.scale[hero];
        // An unbounded piece (an infinite homogeneous medium) is constant.
        const double total = std::isfinite(length) ? integralAt(piece, length) : INFINITY;
        if (!(scale > 0.0) || !(total > 0.0) || tau[hero] + scale * total < target) {
            for (int c = 0; c < 3; ++c)  // an unbounded piece absorbs all of the channels it has
                tau[c] += std::isfinite(length) ? piece.scale[c] * total : (piece.scale[c] > 0.0 ? INFINITY : 0.0);
            return true;
        }
        const double remaining = (target - tau[hero]) / scale;
        const double s =
            std::isfinite(length) ? invertIntegral(piece, length, total, remaining) : remaining / piece.polynomial[0];
        tau += piece.scale * integralAt(piece, s);
        sigmaT = piece.scale * std::max(polynomialAt(piece, s), 0.0);
        tStop = piece.tMin + s;
        return false;
    });
    FreeFlight flight;
    flight.collisions = pieces;
    const RGB transmittance = transmittanceOf(tau);
    if (tStop < 0.0) {  // escaped: P_c = T_c
        flight.t = ray.tMax;
        const float escape = transmittance[hero];
        flight.throughput = flight.pdfRatio = transmittance / escape;
        flight.lightPdfRatio = RGB(1.0f / escape);
        return flight;
    }
    flight.t = std::min(float(tStop), std::nextafter(ray.tMax, 0.0f));
    flight.p = ray.at(flight.t);
    flight.properties = medium.at(flight.p);
    const RGB pdf = RGB(float(sigmaT.x), float(sigmaT.y), float(sigmaT.z)) * transmittance;
    flight.ratioTrackedPdfRatio = RGB(0.0f);
    if (!(pdf[hero] > 0.0f)) {  // a stop where the density is 0: probability 0, ends the path unweighted
        flight.event = FlightEvent::Absorbed;
        flight.throughput = flight.pdfRatio = RGB(0.0f);
        return flight;
    }
    flight.pdfRatio = pdf / pdf[hero];
    flight.throughput = transmittance * flight.properties.sigmaS / pdf[hero];
    flight.absorbedThroughput = transmittance * flight.properties.sigmaA / pdf[hero];
    const bool scatters = !isBlack(flight.properties.sigmaS);
    flight.event = scatters ? FlightEvent::Scattered : FlightEvent::Absorbed;
    if (!scatters) flight.throughput = flight.absorbedThroughput;
    return flight;
}

}  // namespace fluence::media
