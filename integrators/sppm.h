// `sppm`: progressive photon mapping in its probabilistic form (Knaus & Zwicker 2011), which
// converges as samples are added: the integrator for caustics, including those of point lights,
// which no path traced from the eye can find.
//
// Paths covered: L(S|D)*D S* E and L S* E. Every sample index k has its own photon map (Jensen
// 1996): before a pass, beginSamples() traces N photon paths from the lights for each of the
// pass's sample indices and stores a photon at every vertex with a diffuse or glossy lobe, the
// first included, so direct light too comes from the photons (no next-event estimation: one
// estimator for all light that reaches a D vertex, and caustics get no special treatment). A
// camera sample follows the eye ray through delta (S) lobes only; at the first surface with a
// diffuse or glossy lobe it estimates the reflected radiance from the photons within r_k of the hit,
//     L(x, wo) ~ sum_p f(wo, wi_p) Phi_p / (pi r_k^2),
// and ends there (when the BSDF there also has a delta lobe, one lobe is drawn: a delta lobe
// continues the eye path, weighted as the path tracer weights it; any other ends it, as the
// estimate covers it). Emission is added where the eye path reaches it: lights seen directly
// and through specular chains (LS*E).
//
// Convergence (Knaus & Zwicker 2011, after Hachisuka, Ogaki & Jensen 2008 and Hachisuka &
// Jensen 2009): sample k's radius shrinks as r_k^2 = r_1^2 prod_{j=1..k-1} (j + alpha)/(j + 1),
// alpha = kAlpha = 2/3, so r_k^2 ~ k^(alpha - 1); each sample is an independent estimate whose bias
// (O(r_k^2) where radiance is smooth) and variance (O(1/(N r_k^2))) both vanish in the pixel's
// average over k. Each pixel keeps no state: a sample's value depends only on (seed, pixel,
// sample index), as integrators/integrator.h requires, because map k depends only on (seed, k)
// and the sample reads map k, found from SampleStream::sampleIndex().
//
// r_1 is kInitialRadiusPixels pixels wide at the scene's bounding-sphere centre (the camera's
// footprint there), unless SppmSettings::initialRadius sets it in scene units.
//
// Conventions: photons carry flux, traced with the adjoint BSDF (render/bsdf.h, RADIANCE, NOT
// IMPORTANCE): a refracted photon's weight is f eta^2 |cos| / pdf, and shading normals get
// Veach's adjoint correction (1997, eq. 5.19). Photon paths play Russian roulette with survival
// min(1, the ratio of the new to the old flux's largest component), which keeps the photons'
// flux near the emitted flux. Photons leave the lights by their emission sampling
// (render::Light::sampleEmission, render/light_emission.cpp), a light chosen in proportion to
// its power (RenderScene::lightSelection()); cylinder and line lights have no emission sampling,
// so their light reaches the eye only directly or through specular chains. Participating media and subsurface scattering are not supported (the
// registry's `covers` says so): photons and eye rays cross volumes and material interiors as if
// they were empty, so a subsurface material is its surface BSDF alone, whose subsurface lobe
// transmits diffusely into an interior that neither absorbs nor scatters.
//
// Memory: the maps of one pass live together (a pass is at most 64 sample indices,
// integrators/renderer.h) and are freed when the next pass begins (the last pass's when the
// integrator is destroyed or prepares the next render): at most 64 maps of the
// photons N paths leave, 44 bytes per photon at most (integrators/photon_map.h); the Cornell box
// (about 1.7 photons per path) peaks at 230 MB with the default N. Photons are traced in chunks
// of paths on oneTBB's default arena, so on every core whatever the render's thread count
// (beginSamples() runs outside the renderer's arena); chunks are concatenated in order, so maps
// do not depend on the thread count.
//
// References: Jensen 1996, "Global Illumination using Photon Maps"; Jensen 2001, "Realistic
// Image Synthesis Using Photon Mapping"; Hachisuka & Jensen 2009, "Stochastic Progressive Photon
// Mapping"; Knaus & Zwicker 2011, "Progressive Photon Mapping: A Probabilistic Approach".
#pragma once

#include <cstdint>
#include <vector>

#include "integrators/integrator.h"
#include "integrators/photon_map.h"

namespace fluence::integrators {

struct SppmSettings {
    int photonPathsPerMap = 50000;  // N: photon paths traced for each sample index
    float initialRadius = 0.0f;     // r_1 in scene units; 0: kInitialRadiusPixels at the scene's centre
};

class Sppm final : public Integrator {
public:
    static constexpr float kInitialRadiusPixels = 1.5f;
    static constexpr double kAlpha = 2.0 / 3.0;  // the radius's shrink rate, in (0, 1)

    explicit Sppm(const IntegratorSettings& settings, const SppmSettings& sppm = {})
        : maxDepth_(settings.maxDepth), settings_(sppm) {}

    void prepare(const render::RenderScene& scene, const render::Camera& camera, std::uint64_t seed) const override;
    void beginSamples(const render::RenderScene& scene, const render::Camera& camera, std::uint64_t seed,
                      int firstSample, int count) const override;
    std::string summary() const override;
    FilmSample sample(const render::RenderScene& scene, const render::Camera& camera, const render::Ray& ray,
                      SampleStream& rng, RenderCounters& counters) const override;

    // The radius of the sample of (0-based) index sampleIndex, r_k with k = sampleIndex + 1.
    static float radius(float initialRadius, std::uint64_t sampleIndex);

private:
    int maxDepth_;
    SppmSettings settings_;
    // Written by the hooks only (integrators/integrator.h).
    mutable float initialRadius_ = 0.0f;
    mutable int firstSample_ = 0;
    mutable std::vector<PhotonMap> maps_;  // sample indices [firstSample_, firstSample_ + size)
    mutable std::uint64_t mapsBuilt_ = 0, photonsStored_ = 0, photonRays_ = 0, mostBytes_ = 0;
    mutable std::size_t silentLights_ = 0;  // lights without emission sampling
};

}  // namespace fluence::integrators
