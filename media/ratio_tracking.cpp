#include "media/ratio_tracking.h"

namespace fluence::media {

TransmittanceEstimate ratioTrackingTransmittance(const Medium& medium, const MediumRay& ray, int hero,
                                                 SampleStream& stream) {
    TransmittanceEstimate e;
    const MajorantTransmittance end =
        trackMajorants(medium, ray, TrackingRate::Residual, hero, stream, [&](const TentativeCollision& c) {
            ++e.collisions;
            const RGB f = c.tMaj * c.sigmaN(), pdf = c.residualPdf();
            e.throughput *= f / pdf[hero];
            e.pdfRatio *= pdf / pdf[hero];
            return !isBlack(e.throughput);
        });
    e.throughput *= end.tMaj / end.tResidual[hero];
    e.pdfRatio *= end.tResidual / end.tResidual[hero];
    return e;
}

}  // namespace fluence::media
