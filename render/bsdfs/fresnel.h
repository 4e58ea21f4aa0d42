// Fresnel reflectance of a smooth interface: the exact equations for dielectrics, and Schlick's
// approximation for artist-specified conductors.
//
// The seeds name the Fresnel term F of Torrance-Sparrow and Cook-Torrance ("which portion of the
// incoming light gets reflected", 000); the equations are Fresnel's for unpolarised light, as in
// Cook & Torrance (1982) and every optics text (e.g. Born & Wolf, Principles of Optics, 1.5.2).
#pragma once

#include <algorithm>
#include <cmath>

#include "core/rgb.h"

namespace fluence::render {

// Reflectances |r_s|^2 and |r_p|^2 for light polarised perpendicular (s) and parallel (p) to
// the plane of incidence.
struct FresnelPolarized {
    float s = 1.0f;
    float p = 1.0f;
};

// Exact Fresnel reflectances of a dielectric interface. cosThetaI in [0, 1] is the cosine of
// the angle of incidence, on the incident side; eta = n(transmitted side) / n(incident side).
// Beyond the critical angle (eta < 1) there is total internal reflection: s = p = 1.
FresnelPolarized fresnelDielectricPolarized(float cosThetaI, float eta);

// Unpolarised reflectance: the mean of the s and p reflectances.
inline float fresnelDielectric(float cosThetaI, float eta) {
    FresnelPolarized r = fresnelDielectricPolarized(cosThetaI, eta);
    return 0.5f * (r.s + r.p);
}

// Per channel, for an interface whose index differs by channel (a coloured normal-incidence
// reflectance, see etaFromF0); evaluated once when the three indices are equal.
inline RGB fresnelDielectric(float cosThetaI, const RGB& eta) {
    if (eta.x == eta.y && eta.y == eta.z) return RGB(fresnelDielectric(cosThetaI, eta.x));
    return {fresnelDielectric(cosThetaI, eta.x), fresnelDielectric(cosThetaI, eta.y),
            fresnelDielectric(cosThetaI, eta.z)};
}

// The relative index eta > 1 whose reflectance at normal incidence, ((eta - 1) / (eta + 1))^2, is
// f0; f0 is clamped to [0, 0.99] (an index of 399), so the result is finite.
inline float etaFromF0(float f0) {
    float s = std::sqrt(std::clamp(f0, 0.0f, 0.99f));
    return (1.0f + s) / (1.0f - s);
}

// The reflectance at normal incidence of the relative index eta, ((eta - 1) / (eta + 1))^2 (the
// same for eta and 1 / eta): the inverse of etaFromF0.
inline float f0FromEta(float eta) {
    const float r = (eta - 1.0f) / (eta + 1.0f);
    return r * r;
}

// Schlick's approximation F0 + (1 - F0)(1 - cos)^5 (Schlick 1994), per channel: the reflectance
// at normal incidence F0 is the artist's "specular colour" of a metal. F0 = 1 gives F = 1.
inline RGB fresnelSchlick(const RGB& f0, float cosTheta) {
    float m = 1.0f - cosTheta;
    float m5 = (m * m) * (m * m) * m;
    return f0 + (RGB(1.0f) - f0) * m5;
}

}  // namespace fluence::render
