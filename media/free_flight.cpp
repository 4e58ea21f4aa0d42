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

// The numbers that choose the events at a flight's tentative collisions. Default: a fresh number
// from the stream at each. Given one number u (a stratified dimension of the sample), it chooses
// the first collision's event, and after a null collision, which has probability 1 - pStop, it is
// remapped to (u - pStop) / (1 - pStop): uniform on [0, 1) again and independent of the choices
// made so far, so every choice keeps its probability (the flight is delta tracking's, unbiased),
// while the collision the flight stops at, among the tentative ones, is a monotone function of u
// (an inverse CDF), which carries u's stratification over a pixel's samples into the distance
// (as Cycles' volume_integrate_step_scattering remaps its one scatter number across steps). Each
// remap divides u's spacing (2^-24, a float's) by the null probability; once the product of those
// falls below kMinReach (12 of the 24 bits left), fresh numbers from the stream take over.
class EventNumbers {
public:
    EventNumbers() = default;
    explicit EventNumbers(float u) : u_(u), reused_(true) {}

    float next(SampleStream& stream) {
        if (!reused_) return stream.next();
        return static_cast<float>(u_);
    }
    void passedNull(double pStop) {
        if (!reused_) return;
        reach_ *= 1.0 - pStop;
        if (!(reach_ >= kMinReach)) {  // a NaN pStop, too, hands over to fresh numbers
            reused_ = false;
            return;
        }
        u_ = std::clamp((u_ - pStop) / (1.0 - pStop), 0.0, kBelowOne);
    }

private:
    static constexpr double kMinReach = 0x1p-12;
    static constexpr double kBelowOne = 1.0 - 0x1p-24;
    double u_ = 0.0, reach_ = 1.0;
    bool reused_ = false;
};

// Delta tracking with the events at the tentative collisions chosen by `events` (see
// sampleFreeFlight's two forms in free_flight.h).
FreeFlight deltaTracking(const Medium& medium, const MediumRay& ray, int hero, EventNumbers events,
                         SampleStream& stream) {
    FreeFlight flight;
    flight.t = ray.tMax;
    const MajorantTransmittance end =
        trackMajorants(medium, ray, TrackingRate::Majorant, hero, stream, [&](const TentativeCollision& c) {
            const MediumProperties& m = c.properties;
            ++flight.collisions;
            const float normaliser = std::max(c.sigmaMaj[hero], c.sigmaT()[hero]);
            const float u = events.next(stream) * normaliser;
            const bool absorbed = u < m.sigmaA[hero];
            const bool scattered = !absorbed && u < m.sigmaA[hero] + m.sigmaS[hero];
            const RGB f = c.tMaj * (absorbed ? m.sigmaA : scattered ? m.sigmaS : c.sigmaN());
            const RGB pdf = f * densityScale(c);
            flight.throughput *= f / pdf[hero];
            flight.pdfRatio *= pdf / pdf[hero];
            if (!absorbed && !scattered) {  // a null collision: the flight goes on
                events.passedNull((double(m.sigmaA[hero]) + m.sigmaS[hero]) / normaliser);
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

}  // namespace

FreeFlight sampleFreeFlight(const Medium& medium, const MediumRay& ray, int hero, SampleStream& stream) {
    return deltaTracking(medium, ray, hero, EventNumbers(), stream);
}

FreeFlight sampleFreeFlight(const Medium& medium, const MediumRay& ray, int hero, float uEvent, SampleStream& steps) {
    return deltaTracking(medium, ray, hero, EventNumbers(uEvent), steps);
}

}  // namespace fluence::media
