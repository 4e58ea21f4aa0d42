#include "media/guided_walk.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

#include "core/frame.h"
#include "core/sampling.h"
#include "media/phase.h"

namespace fluence::media {
namespace {

constexpr double kTwoPi = 2.0 * 3.14159265358979323846;

// ln((nu + 1) / (nu - 1)), the guided cosine's normalisation.
double dwivediLnRatio(double nu) { return std::log1p(2.0 / (nu - 1.0)); }

// The guided cosine drawn from u, given lnRatio = dwivediLnRatio(nu): F(mu) = ln((nu + 1) / (nu -
// mu)) / lnRatio, so nu - mu = (nu + 1) e^(-u lnRatio); written with expm1 so that a large nu (mu
// nearly uniform) does not cancel.
double sampleCosine(double nu, double lnRatio, double u) {
    const double uL = u * lnRatio;
    return std::clamp(-nu * std::expm1(-uL) - std::exp(-uL), -1.0, 1.0);
}

// Per channel, nu and lnRatio of a walk of single-scattering albedos `albedo`: a pure function of
// them, remembered per thread (the last four), as the walks of one material share them and
// dwivediNu's power costs more than the rest of a walk's set-up.
struct DwivediConstants {
    RGB albedo;
    std::array<double, 3> nu, lnRatio;
};
const DwivediConstants& dwivediConstants(const RGB& albedo) {
    thread_local std::array<DwivediConstants, 4> entries;
    thread_local std::size_t used = 0, next = 0;
    for (std::size_t i = 0; i < used; ++i)
        if (entries[i].albedo == albedo) return entries[i];
    DwivediConstants& e = entries[next];
    e.albedo = albedo;
    for (int c = 0; c < 3; ++c) {
        e.nu[c] = dwivediNu(albedo[c]);
        e.lnRatio[c] = dwivediLnRatio(e.nu[c]);
    }
    next = (next + 1) % entries.size();
    used = std::max(used, next == 0 ? entries.size() : next);
    return e;
}

// weight / its sum, or uniform where that sum is 0 or not finite.
RGB normalisedOrUniform(const RGB& weight) {
    const float total = weight[0] + weight[1] + weight[2];
    return total > 0.0f && std::isfinite(total) ? weight / total : RGB(1.0f / 3.0f);
}

// The channel drawn from u in [0, 1) with probabilities p.
int channelFrom(const RGB& p, float u) { return u < p[0] ? 0 : u < p[0] + p[1] || !(p[2] > 0.0f) ? 1 : 2; }

}  // namespace

double dwivediNu(double albedo) {
    if (!(albedo > 0.0)) return kMinNu;
    const double a = std::min(albedo, 1.0);
    const double nu = 1.0 / std::sqrt(1.0 - std::pow(a, 2.44294 - 0.0215813 * a + 0.578637 / a));
    return std::isfinite(nu) ? std::clamp(nu, kMinNu, kMaxNu) : kMaxNu;
}

double dwivediCosinePdf(double nu, double mu) {
    if (mu < -1.0 || mu > 1.0) return 0.0;
    return 1.0 / ((nu - mu) * dwivediLnRatio(nu));
}

double sampleDwivediCosine(double nu, double u) { return sampleCosine(nu, dwivediLnRatio(nu), u); }

GuidedWalk::GuidedWalk(const Vec3f& entry, const Vec3f& outwardNormal, const MediumProperties& m, WalkChannels channels,
                       float uHero)
    : entry_(entry),
      axis_(outwardNormal),
      medium_(m),
      sigmaT_(m.sigmaA + m.sigmaS),
      albedo_(0.0f),
      channels_(channels) {
    for (int c = 0; c < 3; ++c) albedo_[c] = sigmaT_[c] > 0.0f ? std::min(m.sigmaS[c] / sigmaT_[c], 1.0f) : 0.0f;
    const DwivediConstants& constants = dwivediConstants(albedo_);
    for (int c = 0; c < 3; ++c) {
        nu_[c] = constants.nu[c];
        lnRatio_[c] = constants.lnRatio[c];
        directionNorm_[c] = static_cast<float>(1.0 / (kTwoPi * lnRatio_[c]));
        inverseDiffusionLength_[c] = static_cast<float>(sigmaT_[c] / nu_[c]);
    }
    guidedFraction_ = kGuidedFraction * (1.0f - std::abs(m.g));
    if (channels_ == WalkChannels::PerStep) return;
    RGB meanFreePath(0.0f), scatters(0.0f);
    for (int c = 0; c < 3; ++c) {
        meanFreePath[c] = sigmaT_[c] > 0.0f ? 1.0f / sigmaT_[c] : 0.0f;
        scatters[c] = sigmaT_[c] > 0.0f ? 1.0f : 0.0f;
    }
    heroProbabilities_ =
        (1.0f - kHeroFloor) * normalisedOrUniform(meanFreePath) + kHeroFloor * normalisedOrUniform(scatters);
    chooseHero(uHero);
}

RGB GuidedWalk::channelProbabilities() const {
    return hero_ < 0 ? normalisedOrUniform(albedo_ * throughput_) : heroProbabilities_;
}

int GuidedWalk::stepChannel(float u) const { return hero_ < 0 ? channelFrom(channelProbabilities(), u) : hero_; }

void GuidedWalk::chooseHero(float u) {
    if (channels_ == WalkChannels::PerStep) return;
    hero_ = channelFrom(heroProbabilities_, u);
    heroSample_ = u;
}

WalkStep GuidedWalk::firstStep(const Vec3f& origin, const Vec3f& wi, int channel) const {
    return WalkStep{origin, Vec3f(0.0f), wi, true, WalkStrategy::Classic, channel};
}

void GuidedWalk::sawFarSide(const Vec3f& direction, float distance) {
    const float depth = distance * dot(direction, -axis_);
    if (farDepth_ < 0.0f && depth > 0.0f) farDepth_ = depth;
}

float GuidedWalk::backwardDepth(const Vec3f& p) const {
    return farDepth_ < 0.0f ? 0.0f : std::clamp(dot(entry_ - p, axis_), 0.0f, farDepth_);
}

float GuidedWalk::backwardFraction(float depth, int channel) const {
    if (farDepth_ < 0.0f) return 0.0f;
    return 1.0f / (1.0f + std::exp((farDepth_ - 2.0f * depth) * inverseDiffusionLength_[channel]));
}

WalkStep GuidedWalk::sampleStep(const Vec3f& p, const Vec3f& wo, int channel, float uStrategy, Vec2f uDirection) const {
    WalkStep step{p, wo, Vec3f(0.0f), false, WalkStrategy::Classic, channel};
    if (uStrategy >= guidedFraction_) {
        step.wi = HenyeyGreenstein(medium_.g).sample(wo, uDirection).wi;
        return step;
    }
    const bool away = uStrategy < guidedFraction_ * backwardFraction(backwardDepth(p), channel);
    step.strategy = away ? WalkStrategy::AwayFromEntry : WalkStrategy::TowardsEntry;
    const double mu = sampleCosine(nu_[channel], lnRatio_[channel], uDirection.x);
    const float sinTheta = static_cast<float>(std::sqrt(std::max(0.0, 1.0 - mu * mu)));
    const float phi = 2.0f * kPi * uDirection.y;
    step.wi = Frame::fromNormal(away ? -axis_ : axis_)
                  .toWorld(Vec3f(sinTheta * std::cos(phi), sinTheta * std::sin(phi), static_cast<float>(mu)));
    return step;
}

GuidedWalk::Density GuidedWalk::density(const WalkStep& step, float t, bool collided) const {
    Density d;
    for (int c = 0; c < 3; ++c) {
        d.transmittance[c] = std::exp(-sigmaT_[c] * t);
        d.pdf[c] = collided ? sigmaT_[c] * d.transmittance[c] : d.transmittance[c];  // the classic length's
    }
    if (step.first) return d;
    d.phase = HenyeyGreenstein(medium_.g).p(step.wo, step.wi);
    const float mu = dot(step.wi, axis_), depth = backwardDepth(step.origin);
    for (int c = 0; c < 3; ++c) {
        // The guided lengths' rates are sigmaT (1 - r) towards the entry and sigmaT (1 + r) away,
        // r = mu / nu (in double, as sampleLength draws them); their transmittances T / q and T q,
        // q = exp(-sigmaT t |r|), in the order of r's sign (see THE COST OF A STEP).
        const double r = double(mu) / nu_[c];
        const float exponent = sigmaT_[c] * t, stretched = static_cast<float>(exponent * std::abs(r));
        float nearer, farther;  // exp(-exponent + stretched), exp(-exponent - stretched)
        if (exponent <= kFactoredExponentLimit) {
            const float q = std::exp(-stretched);
            nearer = d.transmittance[c] / q;
            farther = d.transmittance[c] * q;
        } else {
            nearer = std::exp(stretched - exponent);
            farther = std::exp(-exponent - stretched);
        }
        const float towardsTransmittance = r >= 0.0 ? nearer : farther;
        const float awayTransmittance = r >= 0.0 ? farther : nearer;
        const float b = backwardFraction(depth, c), norm = directionNorm_[c];
        float guided = (1.0f - b) * norm / static_cast<float>(nu_[c] - mu) * towardsTransmittance *
                       (collided ? static_cast<float>(sigmaT_[c] * (1.0 - r)) : 1.0f);
        if (b > 0.0f)
            guided += b * norm / static_cast<float>(nu_[c] + mu) * awayTransmittance *
                      (collided ? static_cast<float>(sigmaT_[c] * (1.0 + r)) : 1.0f);
        d.pdf[c] = (1.0f - guidedFraction_) * d.phase * d.pdf[c] + guidedFraction_ * guided;
    }
    return d;
}

float GuidedWalk::stepDivisor(const RGB& pdf) {
    const RGB probability = channelProbabilities();
    auto mixture = [&](const RGB& q) { return probability[0] * q[0] + probability[1] * q[1] + probability[2] * q[2]; };
    if (hero_ < 0) return mixture(pdf);
    // With a hero h: the step's density under h times the change of sum_k P_k r_k, r_k the walk's
    // density under k over h's, so that the divisors of a walk's steps multiply to the balance
    // heuristic's sum_k P_k prod_steps p_k (THE STEP AND ITS MIS).
    if (!(pdf[hero_] > 0.0f)) return 0.0f;
    const float before = mixture(densityRatio_);
    densityRatio_ *= pdf / pdf[hero_];
    return pdf[hero_] * (mixture(densityRatio_) / before);
}

RGB GuidedWalk::stepPdf(const WalkStep& step, float t, bool collided) const { return density(step, t, collided).pdf; }

float GuidedWalk::sampleLength(const WalkStep& step, float u) const {
    double rate = sigmaT_[step.channel];
    if (step.strategy != WalkStrategy::Classic) {
        const double r = double(dot(step.wi, axis_)) / nu_[step.channel];
        rate *= step.strategy == WalkStrategy::TowardsEntry ? 1.0 - r : 1.0 + r;
    }
    return static_cast<float>(-std::log1p(-double(u)) / rate);
}

FreeFlight GuidedWalk::fly(const WalkStep& step, float length, float tBoundary, SampleStream& stream) {
    FreeFlight flight;
    const bool collided = length < tBoundary;
    flight.t = collided ? length : tBoundary;
    const Density d = density(step, flight.t, collided);
    const float mixture = stepDivisor(d.pdf);
    if (!(mixture > 0.0f) || !std::isfinite(mixture)) {  // a length beyond float range: the walk is lost
        flight.event = FlightEvent::Absorbed;
        flight.throughput = RGB(0.0f);
        return flight;
    }
    flight.throughput = d.transmittance * (collided ? medium_.sigmaS : RGB(1.0f)) * (d.phase / mixture);
    throughput_ *= flight.throughput;
    if (!collided) return flight;  // Escaped: through the boundary
    flight.p = step.origin + step.wi * flight.t;
    flight.properties = medium_;
    const float survival = std::min(maxComponent(throughput_), 1.0f);
    // A number in [0, 1) never ends a walk that survives with probability 1: its dimension is taken,
    // its value not computed (SampleStream::skip).
    if (survival < 1.0f ? stream.next() >= survival : (stream.skip(), false)) {
        flight.event = FlightEvent::Absorbed;
        return flight;
    }
    flight.event = FlightEvent::Scattered;
    flight.throughput /= survival;
    throughput_ /= survival;
    return flight;
}

}  // namespace fluence::media
