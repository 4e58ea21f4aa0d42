// `radiosity`: a finite-element solution of the radiance equation for diffuse scenes. Covers LD*E:
// every surface is treated as a Lambertian reflector of its diffuse albedo (glossy, specular,
// metallic and transmissive lobes are dropped; textures shade what the camera sees but the
// interreflection uses each material's constant diffuse colour), so mirrors, glass and caustics
// are missed and glossy surfaces look matte.
//
// prepare() solves, once per render (solve(); the solution is the render's state):
//  - Meshing (integrators/radiosity_mesh.h): every surface triangle cut into patches no longer
//    than RadiositySettings::patchEdge (default: defaultPatchEdge(), the scene's diameter / 16).
//    Each patch has two elements, one per side (Fluence's surfaces are two-sided), with constant
//    radiance B (radiance units: radiosity / pi) and constant albedo rho.
//  - Form factors by hemisphere ray casting: from each element, formFactorRays cosine-distributed
//    rays leave uniformly distributed points of its patch; F_ij is the fraction that first hits
//    element j (the element of the patch hit, on the side facing the ray). Rays that escape or hit
//    a light's own shape carry nothing. Rows are exact in sum for closed scenes (sum_j F_ij = 1),
//    so a closed box's solution is exact whatever the rays' noise.
//  - Direct light (the first gather): for every light that is not an emissive mesh triangle
//    (rect, disk, sphere, cylinder, distant and dome lights, delta lights included: a point or
//    angle-0 distant light's sample is exact irradiance), directSamples light samples
//    (render::Light::sample from uniform points of the patch, the light chosen by power) with
//    shadow rays give D_i, the element's mean incident radiance cosine-weighted and over pi.
//    Emissive triangles are patches: their light enters through E_i and the form factors.
//  - Gauss-Seidel sweeps on B_i = E_i + rho_i H_i, H_i = D_i + sum_j F_ij B_j, until the relative
//    residual ||B - E - rho (D + F B)|| / ||E + rho D|| (area-weighted L1, largest colour channel)
//    falls below `tolerance` or `maxSweeps` is reached. summary() reports patches, sweeps and
//    the residual.
// Everything is deterministic from the seed: element e draws from SampleStream(seed, e, k) with
// k = 0 for form factors and 1 for direct light, whatever the thread count. The solve's rays are
// not in the render's RenderCounters (prepare() has none); they number 2 x patches x
// (formFactorRays + directSamples) at most. Cost grows with the triangle count (every triangle is
// at least one patch): about 2 x 10^4 patches take seconds.
//
// sample(): the camera ray's hit shows its emission plus its albedo (at the hit, textured) times
// the irradiance H interpolated over the element it lies on from its corners' values, each the
// area-weighted mean of H over the elements meeting there and facing the same way
// (cornerAverages, Gouraud shading; creases stay sharp). Light shapes and lights at infinity seen
// directly show their emission.
//
// References: Goral, Torrance, Greenberg & Battaile, "Modeling the Interaction of Light Between
// Diffuse Surfaces" (SIGGRAPH 1984); Cohen & Wallace, "Radiosity and Realistic Image Synthesis"
// (1993), ch. 4 (form factors by ray casting) and ch. 5 (Gauss-Seidel).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "integrators/integrator.h"
#include "integrators/radiosity_mesh.h"

namespace fluence::integrators {

struct RadiositySettings {
    float patchEdge = 0.0f;    // longest patch edge in scene units; 0: defaultPatchEdge(scene bounds)
    int formFactorRays = 256;  // hemisphere rays per element
    int directSamples = 64;    // light samples per element
    float tolerance = 1e-4f;   // relative residual that ends the solve
    int maxSweeps = 500;       // Gauss-Seidel sweeps at most
};

// The solution: the patches, and per element (2 * patch + side; side 0 is the patch normal's) the
// mean incident radiance H and the outgoing radiance B = E + rho H. It is the per-render state
// (integrators/integrator.h) that sample() reads.
struct RadiositySolution final : RenderState {
    std::vector<Patch> patches;
    PatchLocator locator;
    std::vector<RGB> irradiance, radiance;
    std::vector<RGB> cornerIrradiance;  // cornerAverages() of irradiance, for display
    int sweeps = 0;
    float residual = 0.0f;
    float tolerance = 0.0f;  // RadiositySettings::tolerance, for the summary
    // Patches, sweeps and the residual.
    std::string summary() const override;
};

class Radiosity final : public Integrator {
public:
    explicit Radiosity(const RadiositySettings& settings = {}) : settings_(settings) {}

    // The solution for `scene`, its random numbers drawn from `seed`.
    std::unique_ptr<RadiositySolution> solve(const render::RenderScene& scene, std::uint64_t seed) const;
    std::unique_ptr<RenderState> prepare(const render::RenderScene& scene, const render::Camera& camera,
                                         std::uint64_t seed, SplatFilm* splats) const override;
    FilmSample sample(const RenderState& state, const render::RenderScene& scene, const render::Camera& camera,
                      const render::Ray& ray, SampleStream& rng, RenderCounters& counters) const override;

private:
    RadiositySettings settings_;
};

}  // namespace fluence::integrators
