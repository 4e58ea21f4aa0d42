#include "media/exact_tracking.h"

#include <algorithm>
#include <cmath>

#include "media/exact_depth.h"

namespace fluence::media {
namespace {

RGB transmittanceOf(const Vec3d& tau) {
    return RGB(float(std::exp(-tau.x)), float(std::exp(-tau.y)), float(std::exp(-tau.z)));
}

}  // namespace

TransmittanceEstimate exactTransmittance(const Medium& medium, const MediumRay& ray) {
    const OpticalDepth depth = medium.exactOpticalDepth(ray.origin, ray.direction, 0.0f, ray.tMax);
    TransmittanceEstimate tr;
    tr.throughput = transmittanceOf(depth.tau);
    tr.collisions = depth.pieces;
    return tr;
}

FreeFlight sampleExactFlight(const Medium& medium, const MediumRay& ray, int hero, float u) {
    const double target = -std::log1p(-double(u));
    const DepthCrossing crossing = medium.exactDepthCrossing(ray.origin, ray.direction, 0.0f, ray.tMax, hero, target);
    const Vec3d& sigmaT = crossing.sigmaT;
    const double tStop = crossing.tStop;
    FreeFlight flight;
    flight.collisions = crossing.pieces;
    const RGB transmittance = transmittanceOf(crossing.tau);
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
