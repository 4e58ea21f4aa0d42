// `radiosity`: a finite-element solution of the radiance equation for diffuse scenes. Covers LD*E:
// every surface is treated as a Lambertian reflector of its diffuse albedo (glossy, specular,
// metallic and transmissive lobes are dropped; textures shade what the camera sees but the
// interreflection uses each material's constant diffuse colour), so mirrors, glass and caustics
// are missed and glossy surfaces look matte.
//
// prepare() solves, once per render:
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

class Radiosity final : public Integrator {
public:
    explicit Radiosity(const RadiositySettings& settings = {}) : settings_(settings) {}

    void prepare(const render::RenderScene& scene, const render::Camera& camera, std::uint64_t seed) const override;
    std::string summary() const override;
    FilmSample sample(const render::RenderScene& scene, const render::Camera& camera, const render::Ray& ray,
                      SampleStream& rng, RenderCounters& counters) const override;

    // The solution, after prepare(): the patches, and per element (2 * patch + side; side 0 is the
    // patch normal's) the mean incident radiance H and the outgoing radiance B = E + rho H.
    const std::vector<Patch>& patches() const { return patches_; }
    const std::vector<RGB>& irradiance() const { return irradiance_; }
    const std::vector<RGB>& radiance() const { return radiance_; }
    int sweeps() const { return sweeps_; }
    float residual() const { return residual_; }

private:
    RadiositySettings settings_;
    // Written by prepare() only.
    mutable std::vector<Patch> patches_;
    mutable PatchLocator locator_;
    mutable std::vector<RGB> irradiance_, radiance_;
    mutable std::vector<RGB> cornerIrradiance_;  // cornerAverages() of irradiance_, for display
    mutable int sweeps_ = 0;
    mutable float residual_ = 0.0f;
};

}  // namespace fluence::integrators
