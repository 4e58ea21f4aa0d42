#include "media/guided_walk.h"

#include <algorithm>
#include <cmath>

#include "core/frame.h"
#include "core/sampling.h"
#include "media/phase.h"

namespace fluence::media {
namespace {

constexpr double kTwoPi = 2.0 * 3.14159265358979323846;

// The density of a length t at rate sigma: a collision there, or (not collided) none before it.
double lengthPdf(double sigma, double t, bool collided) {
    const double transmittance = std::exp(-sigma * t);
    return collided ? sigma * transmittance : transmittance;
}

// The density of the guided cosine mu in [-1, 1], given lnRatio = ln((nu + 1) / (nu - 1)) (which a
// walk keeps per channel), and the guided direction's solid-angle density.
double cosinePdf(double nu, double lnRatio, double mu) { return 1.0 / ((nu - mu) * lnRatio); }
double guidedDirectionPdf(double nu, double lnRatio, double mu) { return cosinePdf(nu, lnRatio, mu) / kTwoPi; }
// The stretch of the guided length's rate, for mu = dot(wi, axis).
double stretch(double nu, double mu) { return 1.0 - mu / nu; }

}  // namespace

double dwivediNu(double albedo) {
    if (!(albedo > 0.0)) return kMinNu;
    const double a = std::min(albedo, 1.0);
    const double nu = 1.0 / std::sqrt(1.0 - std::pow(a, 2.44294 - 0.0215813 * a + 0.578637 / a));
    return std::isfinite(nu) ? std::clamp(nu, kMinNu, kMaxNu) : kMaxNu;
}

double dwivediCosinePdf(double nu, double mu) {
    if (mu < -1.0 || mu > 1.0) return 0.0;
    return cosinePdf(nu, std::log1p(2.0 / (nu - 1.0)), mu);
}

double sampleDwivediCosine(double nu, double u) {
    // F(mu) = ln((nu + 1) / (nu - mu)) / ln((nu + 1) / (nu - 1)), so nu - mu = (nu + 1) e^(-u L);
    // written with expm1 so that a large nu (mu nearly uniform) does not cancel.
    const double uL = u * std::log1p(2.0 / (nu - 1.0));
    return std::clamp(-nu * std::expm1(-uL) - std::exp(-uL), -1.0, 1.0);
}

GuidedWalk::GuidedWalk(const Vec3f& entry, const Vec3f& outwardNormal, const MediumProperties& m)
    : entry_(entry), axis_(outwardNormal), medium_(m), sigmaT_(m.sigmaA + m.sigmaS), albedo_(0.0f) {
    for (int c = 0; c < 3; ++c) {
        albedo_[c] = sigmaT_[c] > 0.0f ? std::min(m.sigmaS[c] / sigmaT_[c], 1.0f) : 0.0f;
        nu_[c] = dwivediNu(albedo_[c]);
        lnRatio_[c] = std::log1p(2.0 / (nu_[c] - 1.0));
    }
    guidedFraction_ = kGuidedFraction * (1.0f - std::abs(m.g));
}

RGB GuidedWalk::channelProbabilities() const {
    const RGB weight = albedo_ * throughput_;
    const float total = weight[0] + weight[1] + weight[2];
    return total > 0.0f && std::isfinite(total) ? weight / total : RGB(1.0f / 3.0f);
}

int GuidedWalk::sampleChannel(float u) const {
    const RGB p = channelProbabilities();
    return u < p[0] ? 0 : u < p[0] + p[1] || !(p[2] > 0.0f) ? 1 : 2;
}

WalkStep GuidedWalk::firstStep(const Vec3f& origin, const Vec3f& wi, int channel) const {
    return WalkStep{origin, Vec3f(0.0f), wi, true, WalkStrategy::Classic, channel};
}

void GuidedWalk::sawFarSide(const Vec3f& direction, float distance) {
    const float depth = distance * dot(direction, -axis_);
    if (farDepth_ < 0.0f && depth > 0.0f) farDepth_ = depth;
}

double GuidedWalk::backwardFraction(const Vec3f& p, int channel) const {
    if (farDepth_ < 0.0f) return 0.0;
    const double x = std::clamp(double(dot(entry_ - p, axis_)), 0.0, double(farDepth_));
    const double diffusionLength = nu_[channel] / sigmaT_[channel];
    return 1.0 / (1.0 + std::exp((farDepth_ - 2.0 * x) / diffusionLength));
}

WalkStep GuidedWalk::sampleStep(const Vec3f& p, const Vec3f& wo, int channel, float uStrategy, Vec2f uDirection) const {
    WalkStep step{p, wo, Vec3f(0.0f), false, WalkStrategy::Classic, channel};
    if (uStrategy >= guidedFraction_) {
        step.wi = HenyeyGreenstein(medium_.g).sample(wo, uDirection).wi;
        return step;
    }
    const bool away = uStrategy < guidedFraction_ * backwardFraction(p, channel);
    step.strategy = away ? WalkStrategy::AwayFromEntry : WalkStrategy::TowardsEntry;
    const double mu = sampleDwivediCosine(nu_[channel], uDirection.x);
    const float sinTheta = static_cast<float>(std::sqrt(std::max(0.0, 1.0 - mu * mu)));
    const float phi = 2.0f * kPi * uDirection.y;
    step.wi = Frame::fromNormal(away ? -axis_ : axis_)
                  .toWorld(Vec3f(sinTheta * std::cos(phi), sinTheta * std::sin(phi), static_cast<float>(mu)));
    return step;
}

RGB GuidedWalk::stepPdf(const WalkStep& step, float t, bool collided) const {
    RGB pdf(0.0f);
    const double mu = dot(step.wi, axis_);
    const double phase = step.first ? 0.0 : HenyeyGreenstein(medium_.g).pdf(step.wo, step.wi);
    for (int c = 0; c < 3; ++c) {
        const double sigma = sigmaT_[c], nu = nu_[c], lnRatio = lnRatio_[c];
        const double classic = lengthPdf(sigma, t, collided);
        if (step.first) {
            pdf[c] = static_cast<float>(classic);
            continue;
        }
        const double b = backwardFraction(step.origin, c);
        const double towards = guidedDirectionPdf(nu, lnRatio, mu) * lengthPdf(sigma * stretch(nu, mu), t, collided);
        const double away = guidedDirectionPdf(nu, lnRatio, -mu) * lengthPdf(sigma * stretch(nu, -mu), t, collided);
        pdf[c] = static_cast<float>((1.0 - guidedFraction_) * phase * classic +
                                    guidedFraction_ * ((1.0 - b) * towards + b * away));
    }
    return pdf;
}

float GuidedWalk::sampleLength(const WalkStep& step, float u) const {
    double rate = sigmaT_[step.channel];
    if (step.strategy != WalkStrategy::Classic) {
        const double mu = dot(step.wi, axis_);
        rate *= stretch(nu_[step.channel], step.strategy == WalkStrategy::TowardsEntry ? mu : -mu);
    }
    return static_cast<float>(-std::log1p(-double(u)) / rate);
}

FreeFlight GuidedWalk::fly(const WalkStep& step, float length, float tBoundary, SampleStream& stream) {
    FreeFlight flight;
    const bool collided = length < tBoundary;
    flight.t = collided ? length : tBoundary;
    const RGB pdf = stepPdf(step, flight.t, collided);
    const RGB probability = channelProbabilities();
    const float mixture = probability[0] * pdf[0] + probability[1] * pdf[1] + probability[2] * pdf[2];
    if (!(mixture > 0.0f) || !std::isfinite(mixture)) {  // a length beyond float range: the walk is lost
        flight.event = FlightEvent::Absorbed;
        flight.throughput = RGB(0.0f);
        return flight;
    }
    const float phase = step.first ? 1.0f : HenyeyGreenstein(medium_.g).p(step.wo, step.wi);
    for (int c = 0; c < 3; ++c)
        flight.throughput[c] = phase * (collided ? medium_.sigmaS[c] : 1.0f) * std::exp(-sigmaT_[c] * flight.t);
    flight.throughput /= mixture;
    throughput_ *= flight.throughput;
    if (!collided) return flight;  // Escaped: through the boundary
    flight.p = step.origin + step.wi * flight.t;
    flight.properties = medium_;
    const float survival = std::min(maxComponent(throughput_), 1.0f);
    if (stream.next() >= survival) {
        flight.event = FlightEvent::Absorbed;
        return flight;
    }
    flight.event = FlightEvent::Scattered;
    flight.throughput /= survival;
    throughput_ /= survival;
    return flight;
}

}  // namespace fluence::media
