// `sppm`: progressive photon mapping in its probabilistic form (Knaus & Zwicker 2011), which
// converges as samples are added: the integrator for caustics, including those of point lights,
// which no path traced from the eye can find.
//
// Paths covered: L(S|D|V)*(D|V) S* E and L S* E (V: a scattering in a medium). Every sample index
// k has its own photon maps (Jensen 1996): before a pass, beginSamples() traces N photon paths from
// the lights for each of the pass's sample indices and stores a surface photon at every vertex with
// a diffuse or glossy lobe and a volume photon at every scattering in a medium, the first
// included, so direct light too comes from the photons (no next-event estimation: one estimator
// for all light that reaches a D or V vertex, and caustics get no special treatment). A camera
// sample follows the eye ray through delta (S) lobes only; at the first surface with a diffuse or
// glossy lobe it estimates the reflected radiance from the surface photons within r_k of the hit,
//     L(x, wo) ~ sum_p f(wo, wi_p) Phi_p / (pi r_k^2),
// and ends there (when the BSDF there also has a delta lobe, one lobe is drawn: a delta lobe
// continues the eye path, weighted as the path tracer weights it; any other ends it, as the
// estimate covers it). Emission is added where the eye path reaches it: lights seen directly
// and through specular chains (LS*E).
//
// Media (Jensen & Christensen 1998, "Efficient simulation of light transport in scenes with
// participating media using photon maps"; made progressive as Knaus & Zwicker 2011 do for volumes).
// Photon and eye paths cross the scene's volumes and the interiors of closed surfaces
// (integrators/medium_stack.h) by the same free-flight sampling as `path` (media/free_flight.h:
// delta tracking with hero-channel spectral MIS). Each path draws one hero channel and carries
// beta = f / p_h and rU = p_c / p_h (media/tracking.h); its estimate of any prefix is beta /
// channelAverage(rU), so a photon's flux Phi_p is that of its path up to where it is stored. A
// photon whose flight ends in a scattering is stored there as a volume photon (position, the
// direction it came from, Phi_p), then scatters by the medium's Henyey-Greenstein phase function
// (whose weight p / pdf is 1: the flux is unchanged, so it survives the roulette) and goes on; an
// absorbed one ends; one that escapes reaches the surface, attenuated. Derivation of the eye's
// estimate: delta tracking stores a photon in the volume dV about x, arriving within dw of -wi,
// with expected flux sigmaS(x) L(x, wi) dw dV (the flux crossing dV along wi, times the chance
// sigmaS dl of scattering over its length dl), so for the ball of radius R_k about x,
//     sum_p p(wo, wi_p) Phi_p / ((4/3) pi R_k^3) ~ sigmaS(x) L_s(x, wo),
//     L_s(x, wo) = integral p(wo, wi) L(x, wi) dwi,
// the in-scattered radiance per unit length, up to the O(R_k^2) bias of averaging over the ball
// (O(R_k) within R_k of a medium's boundary, where part of the ball holds no photons).
// The eye ray's radiance is integral_0^tHit T(t) sigmaS(t) L_s(t) dt + T(tHit) L(tHit); its free
// flight scatters at t with weight beta = T sigmaS / p (the sigmaS being the same one), so at a
// scattering the eye adds (beta / sigmaS(x)) times the sum above, divided by channelAverage(rU),
// and ends there as at a D vertex; an absorption adds beta Le / channelAverage(rU) (the emission
// of media is seen, and seen through specular chains, but lights nothing: photons leave lights
// only); an escape goes on to the surface. The photon's and the eye's estimates are independent
// and each unbiased, so their product is (up to the kernel's bias). Volume radii shrink with the
// 3D exponent, R_k^3 = r_1^3 prod_{j=1..k-1} (j + alpha)/(j + 1), so R_k^3 ~ k^(alpha - 1): bias
// and variance O(1/(N R_k^3)) both vanish in the pixel's average, as on surfaces, but slowly
// (R_k ~ k^(-1/9)), so a volume's r_1 matters more than a surface's.
//
// Interiors: a material's interior is a medium like any other, so a random-walk subsurface
// material is rendered by the photons' walks: photons that enter by its diffuse transmission walk
// through the interior and are stored where they come out, on the surface's inner side, which
// the surface estimate gathers through the transmission lobe (materials whose subsurface method
// is diffusion are rendered by this walk too). Scatterings inside an interior count against
// kMaxInteriorScatterings, not the depth, as in `path` (integrators/russian_roulette.h). Eye paths enter
// an interior only through a delta transmission (glass around a murky liquid), so volume photons
// are stored inside an interior only when the photon entered it through a BSDF with a delta
// lobe and transmission; elsewhere they would never be gathered, and a walk stores up to a
// thousand. (With surfaces that intersect, the flag of an interior a photon leaves from the
// middle of the stack can be misassigned: volume photons are then dropped where the eye could
// gather them, or kept where it cannot; the walks themselves are unaffected.)
//
// Convergence (Knaus & Zwicker 2011, after Hachisuka, Ogaki & Jensen 2008 and Hachisuka &
// Jensen 2009): sample k's radius shrinks as r_k^2 = r_1^2 prod_{j=1..k-1} (j + alpha)/(j + 1),
// alpha = kAlpha = 2/3, so r_k^2 ~ k^(alpha - 1); each sample is an independent estimate whose bias
// (O(r_k^2) where radiance is smooth) and variance (O(1/(N r_k^2))) both vanish in the pixel's
// average over k. Each pixel keeps no state: a sample's value depends only on (seed, pixel,
// sample index), as integrators/integrator.h requires, because map k depends only on (seed, k)
// and the sample reads map k, found from SampleStream::sampleIndex().
//
// Light path expression AOVs (integrators/light_path_expression.h): the eye path's events are
// followed forward as `path` follows them (C, its delta bounces, emission it reaches); each photon
// carries, per expression, the automaton states from which its own events read back to its light
// are accepted (integrators/photon_light_paths.h), so a gather knows exactly which expressions
// the joined path (eye events)(the gather vertex's kind: <R|T D|G> by the BSDF's split for the
// photon's direction, or <V D>)(photon events reversed) matches, and adds the photon's term to
// those layers. A layer's sample is its share of the beauty's sample, with the same radius r_k (the
// radius depends on the sample index only, never on which photons a layer counts), so the layers
// of a disjoint cover sum to the beauty and each converges as the beauty does. Expressions whose
// automaton has more than kMaxPhotonLpeStates (64) states are refused.
//
// r_1 is kInitialRadiusPixels pixels wide at the scene's bounding-sphere centre (the camera's
// footprint there), unless SppmSettings::initialRadius sets it in scene units; the volume
// radius starts from the same r_1.
//
// Conventions: photons carry flux, traced with the adjoint BSDF (render/bsdf.h, RADIANCE, NOT
// IMPORTANCE): a refracted photon's weight is f eta^2 |cos| / pdf, and shading normals get
// Veach's adjoint correction (1997, eq. 5.19). Photon paths play Russian roulette with survival
// min(1, the ratio of the new to the old flux's largest component), which keeps the photons'
// flux near the emitted flux. Photons leave the lights by their emission sampling
// (render::Light::sampleEmission, in each light of render/lights/), a light chosen in proportion to
// its power (RenderScene::lightSelection()); cylinder and line lights have no emission sampling,
// so their light reaches the eye only directly or through specular chains.
//
// Memory: the maps of one pass live together (a pass is at most 64 sample indices,
// integrators/renderer.h) and are freed when the next pass begins (the last pass's when the
// render ends): at most 64 pairs of maps of the
// photons N paths leave, 44 bytes per photon at most (integrators/photon_map.h); the Cornell box
// (about 1.7 photons per path) peaks at 230 MB with the default N. With light path expression
// AOVs a photon also keeps its index in its map (4 bytes) and its histories (24 bytes each, one or
// a few per expression: integrators/photon_light_paths.h). In a medium of albedo near 1 a
// photon path stores up to maxDepth volume photons, so thick bright media cost more. Photons are
// traced in chunks of paths on oneTBB's default arena, so on every core whatever the render's thread count
// (beginSamples() runs outside the renderer's arena); chunks are concatenated in order, so maps
// do not depend on the thread count.
//
// References: Jensen 1996, "Global Illumination using Photon Maps"; Jensen 2001, "Realistic
// Image Synthesis Using Photon Mapping"; Hachisuka & Jensen 2009, "Stochastic Progressive Photon
// Mapping"; Knaus & Zwicker 2011, "Progressive Photon Mapping: A Probabilistic Approach".
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "integrators/integrator.h"
#include "integrators/light_path_tracker.h"

namespace fluence::integrators {

struct SppmSettings {
    int photonPathsPerMap = 50000;  // N: photon paths traced for each sample index
    float initialRadius = 0.0f;     // r_1 in scene units; 0: kInitialRadiusPixels at the scene's centre
};

class Sppm final : public Integrator {
public:
    static constexpr float kInitialRadiusPixels = 1.5f;
    static constexpr double kAlpha = 2.0 / 3.0;  // the radius's shrink rate, in (0, 1)

    // Throws std::invalid_argument, naming the expression, for a light path expression AOV whose
    // automaton photons cannot carry (integrators/photon_light_paths.h).
    explicit Sppm(const IntegratorSettings& settings, const SppmSettings& sppm = {});

    // The per-render state: the initial radius; then, from beginSamples(), the photon maps of the
    // pass's sample indices, and the counts the summary reports.
    std::unique_ptr<RenderState> prepare(const render::RenderScene& scene, const render::Camera& camera,
                                         std::uint64_t seed, SplatFilm* splats) const override;
    void beginSamples(RenderState& state, const render::RenderScene& scene, const render::Camera& camera,
                      std::uint64_t seed, int firstSample, int count) const override;
    FilmSample sample(const RenderState& state, const render::RenderScene& scene, const render::Camera& camera,
                      const render::Ray& ray, SampleStream& rng, RenderCounters& counters) const override;

    // The radius of the sample of (0-based) index sampleIndex, r_k with k = sampleIndex + 1, for a
    // kernel of `dimensions` 2 (surfaces: r_k^2 shrinks) or 3 (media: r_k^3 shrinks).
    static float radius(float initialRadius, std::uint64_t sampleIndex, int dimensions);

private:
    std::span<const LightPathAov> aovs() const {
        return aovs_ ? std::span<const LightPathAov>(*aovs_) : std::span<const LightPathAov>();
    }

    int maxDepth_;
    SppmSettings settings_;
    std::shared_ptr<const std::vector<LightPathAov>> aovs_;  // null: none
};

}  // namespace fluence::integrators
