// The Henyey-Greenstein phase function (Henyey & Greenstein 1941, "Diffuse radiation in the
// galaxy"; sampling by inverting its CDF in cos theta, derived below).
//
// DIRECTIONS. As for BSDFs (render/bsdf.h), wo and wi are unit vectors pointing AWAY from the
// scattering point: wo towards the previous path vertex (the viewer), wi towards the next (the
// light). Light travels along -wi, scatters, and leaves along wo, so the scattering angle theta is
// the angle between -wo and wi:
//     p(wo, wi) = (1 - g^2) / (4 pi (1 + g^2 - 2 g cos theta)^(3/2)),  cos theta = dot(-wo, wi).
// g > 0 scatters forward (wi near -wo: the path goes on roughly straight), g < 0 backward, g = 0
// is isotropic; the mean of cos theta is g. p is reciprocal, p(wo, wi) = p(wi, wo), and
// integrates to 1 over the sphere of wi; it is a density in solid angle, with no cosine factor.
//
// THE TRIPLE. p(wo, wi) is both the phase function's value and the density sample() draws wi
// with, so a sample's weight p / pdf is exactly 1; the record still carries both, as BsdfSample
// does, because multiple importance sampling needs the pdf. g is clamped to [-kMaxG, kMaxG]: at
// |g| = 1 the lobe is a Dirac delta, whose density no finite float can hold.
//
// SAMPLING. With mu = cos theta, the CDF of mu on [-1, 1] is
//     F(mu) = (1 - g^2) / (2 g) * ((1 + g^2 - 2 g mu)^(-1/2) - 1 / (1 + g)),
// whose inverse at xi, written with a = 2 xi - 1 so that it has no 0/0 at g = 0, is
//     mu = (a + g) / (1 + g a) + g (1 - g^2) (1 - a^2) / (2 (1 + g a)^2)
// (mu = a, uniform, at g = 0; mu = +-1 exactly at a = +-1); phi is uniform.
#pragma once

#include "core/vec.h"

namespace fluence::media {

struct PhaseSample {
    Vec3f wi;          // unit, pointing away from the scattering point
    float p = 0.0f;    // p(wo, wi)
    float pdf = 0.0f;  // solid-angle density of wi: equal to p
};

class HenyeyGreenstein {
public:
    static constexpr float kMaxG = 0.999f;

    explicit HenyeyGreenstein(float g);

    float g() const { return g_; }
    float p(const Vec3f& wo, const Vec3f& wi) const;
    float pdf(const Vec3f& wo, const Vec3f& wi) const { return p(wo, wi); }
    // Draws wi from u in [0,1)^2 (u.x picks the scattering angle, u.y the azimuth).
    PhaseSample sample(const Vec3f& wo, Vec2f u) const;

private:
    float g_;
};

// The phase function's value at cos theta = dot(-wo, wi) (see DIRECTIONS), for |g| <= kMaxG.
float henyeyGreenstein(float cosTheta, float g);

}  // namespace fluence::media
