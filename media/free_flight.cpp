#include "media/free_flight.h"

#include <algorithm>

namespace fluence::media {
namespace {

// Per channel, sigmaMaj / max(sigmaMaj, sigmaT): the factor that turns a point's f = Tmaj sigma_k
// into its density Tmaj sigmaMaj sigma_k / max(sigmaMaj, sigmaT). Exactly 1 where the majorant
// bounds sigmaT, so that f / pdf is exactly 1 in a gray medium.
RGB densityScale(const TentativeCollision& c) {
    const RGB sigmaT = c.sigmaT();
    RGB scale(0.0f);
    for (int i = 0; i < 3; ++i) {
        const float normaliser = std::max(c.sigmaMaj[i], sigmaT[i]);
        if (normaliser > 0.0f) scale[i] = c.sigmaMaj[i] / normaliser;
    }
    return scale;
}

}  // namespace

FreeFlight sampleFreeFlight(const Medium& medium, const MediumRay& ray, int hero, SampleStream& stream) {
    FreeFlight flight;
    flight.t = ray.tMax;
    const MajorantTransmittance end =
        trackMajorants(medium, ray, TrackingRate::Majorant, hero, stream, [&](const TentativeCollision& c) {
            const MediumProperties& m = c.properties;
            ++flight.collisions;
            const float u = stream.next() * std::max(c.sigmaMaj[hero], c.sigmaT()[hero]);
            const bool absorbed = u < m.sigmaA[hero];
            const bool scattered = !absorbed && u < m.sigmaA[hero] + m.sigmaS[hero];
            const RGB f = c.tMaj * (absorbed ? m.sigmaA : scattered ? m.sigmaS : c.sigmaN());
            const RGB pdf = f * densityScale(c);
            flight.throughput *= f / pdf[hero];
            flight.pdfRatio *= pdf / pdf[hero];
            if (!absorbed && !scattered) {  // a null collision: the flight goes on
                flight.lightPdfRatio *= c.residualPdf() / pdf[hero];
                return true;
            }
            flight.ratioTrackedPdfRatio = flight.lightPdfRatio * c.tResidual / pdf[hero];
            flight.event = absorbed ? FlightEvent::Absorbed : FlightEvent::Scattered;
            flight.t = c.t;
            flight.p = c.p;
            flight.properties = m;
            return false;
        });
    if (flight.event == FlightEvent::Escaped) {
        flight.throughput *= end.tMaj / end.tMaj[hero];
        flight.pdfRatio *= end.tMaj / end.tMaj[hero];
        flight.lightPdfRatio *= end.tResidual / end.tMaj[hero];
    }
    return flight;
}

}  // namespace fluence::media
