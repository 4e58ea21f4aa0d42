#include "integrators/radiosity.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "core/frame.h"
#include "core/sampling.h"
#include "integrators/emission.h"
#include "integrators/first_hit.h"

namespace fluence::integrators {

namespace {

// The streams of an element's random numbers (SampleStream's sample index).
enum Stream : std::uint64_t { kFormFactorStream = 0, kDirectStream = 1 };

Vec3f pointOn(const Patch& patch, Vec2f u) {
    const Vec2f b = sampleUniformTriangle(u);
    return patch.p0 * b.x + patch.p1 * b.y + patch.p2 * (1.0f - b.x - b.y);
}

// One entry of a form-factor row: the element a share of the rays reached.
struct FormFactor {
    int element;
    float value;
};
using FormFactorRows = std::vector<std::vector<FormFactor>>;

// Row e: the fraction of `rays` cosine-distributed rays from element e's patch that first hit
// each element.
std::vector<FormFactor> formFactorRow(const render::RenderScene& scene, const std::vector<Patch>& patches,
                                      const PatchLocator& locator, int element, int rays, std::uint64_t seed) {
    const Patch& patch = patches[element / kSides];
    const Vec3f n = sideNormal(patch, element % kSides);
    const Frame frame = Frame::fromNormal(n);
    SampleStream rng(seed, static_cast<std::uint64_t>(element), kFormFactorStream);
    std::vector<int> reached;
    for (int r = 0; r < rays; ++r) {
        const Vec3f origin = render::offsetRayOrigin(pointOn(patch, rng.next2D()), n);
        const Vec3f direction = frame.toWorld(sampleCosineHemisphere(rng.next2D()));
        std::optional<render::SurfaceHit> hit = scene.intersect({origin, direction});
        if (!hit || hit->lightShape) continue;
        std::optional<PatchPoint> target = locator.locate(patches, hit->point, hit->geometricNormal);
        if (!target) continue;
        reached.push_back(elementOf(target->patch, dot(direction, patches[target->patch].normal) < 0.0f ? 0 : 1));
    }
    std::sort(reached.begin(), reached.end());
    std::vector<FormFactor> row;
    for (std::size_t i = 0; i < reached.size();) {
        std::size_t j = i;
        while (j < reached.size() && reached[j] == reached[i]) ++j;
        row.push_back({reached[i], float(j - i) / float(rays)});
        i = j;
    }
    return row;
}

// The lights that are not patches (every light but emissive mesh triangles), chosen by power.
struct ExternalLights {
    std::vector<int> lights;
    DiscreteDistribution choice;
};
ExternalLights externalLights(const render::RenderScene& scene) {
    ExternalLights out;
    std::vector<double> powers;
    for (std::size_t i = 0; i < scene.lightCount(); ++i) {
        const render::Light& light = scene.light(i);
        if (light.isSurfaceEmitter()) continue;
        out.lights.push_back(static_cast<int>(i));
        powers.push_back(std::max(0.0f, light.power(scene.bounds())));
    }
    if (!out.lights.empty()) out.choice = DiscreteDistribution(powers);
    return out;
}

// D_e: the element's mean incident radiance from the external lights, cosine-weighted, over pi.
RGB directLight(const render::RenderScene& scene, const ExternalLights& external, const Patch& patch, int element,
                int samples, std::uint64_t seed) {
    if (external.lights.empty()) return RGB(0.0f);
    const Vec3f n = sideNormal(patch, element % kSides);
    SampleStream rng(seed, static_cast<std::uint64_t>(element), kDirectStream);
    RGB sum(0.0f);
    for (int s = 0; s < samples; ++s) {
        const Vec3f from = render::offsetRayOrigin(pointOn(patch, rng.next2D()), n);
        const std::size_t chosen = external.choice.sample(rng.next());
        const float choicePdf = external.choice.pmf(chosen);
        const Vec2f u = rng.next2D();
        if (choicePdf <= 0.0f) continue;
        std::optional<render::LightSample> ls = scene.light(external.lights[chosen]).sample(from, u);
        if (!ls || ls->pdf <= 0.0f || isBlack(ls->Li)) continue;
        const float cosine = dot(ls->wi, n);
        if (cosine <= 0.0f) continue;
        // Light sampling alone: light that passes surfaces (render/shadow_rays.cpp) counts in full.
        const int light = external.lights[chosen];
        if (scene.shadowTest(light, from, ls->wi, ls->distance) == render::ShadowTest::Blocked) continue;
        sum += ls->Li * (cosine / (ls->pdf * choicePdf));
    }
    return sum * (kInvPi / float(samples));
}

// H_e = D_e + sum_j F_ej B_j.
RGB gathered(const std::vector<FormFactor>& row, const RGB& direct, const std::vector<RGB>& radiance) {
    RGB h = direct;
    for (const FormFactor& f : row) h += radiance[f.element] * f.value;
    return h;
}

}  // namespace

std::unique_ptr<RadiositySolution> Radiosity::solve(const render::RenderScene& scene, std::uint64_t seed) const {
    auto solution = std::make_unique<RadiositySolution>();
    std::vector<Patch>& patches = solution->patches;
    std::vector<RGB>& radiance = solution->radiance;
    const float edge = settings_.patchEdge > 0.0f ? settings_.patchEdge : defaultPatchEdge(scene.bounds());
    patches = meshPatches(scene.surfaceTriangles(), edge);
    solution->locator = PatchLocator(patches);
    const int elements = kSides * static_cast<int>(patches.size());

    FormFactorRows rows(elements);
    std::vector<RGB> direct(elements);
    const ExternalLights external = externalLights(scene);
    tbb::parallel_for(0, elements, [&](int e) {
        rows[e] = formFactorRow(scene, patches, solution->locator, e, settings_.formFactorRays, seed);
        direct[e] = directLight(scene, external, patches[e / kSides], e, settings_.directSamples, seed);
    });

    // Gauss-Seidel on B = E + rho (D + F B), from B = E + rho D. The norms weigh each element by
    // its area and take the largest colour channel.
    auto updated = [&](int e) {  // the right-hand side for element e, from the current B
        const Patch& p = patches[e / kSides];
        return p.emission + p.albedo * gathered(rows[e], direct[e], radiance);
    };
    radiance.resize(elements);
    double sourceNorm = 0.0;
    for (int e = 0; e < elements; ++e) {
        const Patch& p = patches[e / kSides];
        radiance[e] = p.emission + p.albedo * direct[e];
        sourceNorm += p.area * maxComponent(radiance[e]);
    }
    auto relativeResidual = [&] {
        if (sourceNorm <= 0.0) return 0.0f;
        double r = 0.0;
        for (int e = 0; e < elements; ++e) {
            const RGB difference = updated(e) - radiance[e];
            r += patches[e / kSides].area *
                 maxComponent(RGB(std::abs(difference.x), std::abs(difference.y), std::abs(difference.z)));
        }
        return float(r / sourceNorm);
    };
    solution->tolerance = settings_.tolerance;
    solution->residual = relativeResidual();
    while (solution->residual > settings_.tolerance && solution->sweeps < settings_.maxSweeps) {
        for (int e = 0; e < elements; ++e) radiance[e] = updated(e);
        ++solution->sweeps;
        solution->residual = relativeResidual();
    }
    solution->irradiance.resize(elements);
    for (int e = 0; e < elements; ++e) solution->irradiance[e] = gathered(rows[e], direct[e], radiance);
    solution->cornerIrradiance = cornerAverages(patches, solution->irradiance);
    return solution;
}

std::unique_ptr<RenderState> Radiosity::prepare(const render::RenderScene& scene, const render::Camera&,
                                                std::uint64_t seed, SplatFilm*) const {
    // Patches are not geometry: they do not know which lights reach them (shadow links they honour).
    if (scene.lightLinks().excludesAnything())
        throw std::invalid_argument(
            "integrator 'radiosity' cannot render light links that exclude geometry (collection:lightLink); "
            "render with 'path', 'bdpt', 'sppm', 'direct' or 'whitted'");
    return solve(scene, seed);
}

std::string RadiositySolution::summary() const {
    char line[160];
    std::snprintf(line, sizeof line, "radiosity: %zu patches, %d Gauss-Seidel sweeps, residual %.3g (tolerance %.3g)",
                  patches.size(), sweeps, double(residual), double(tolerance));
    return line;
}

FilmSample Radiosity::sample(const RenderState& state, const render::RenderScene& scene, const render::Camera& camera,
                             const render::Ray& ray, SampleStream&, RenderCounters& counters) const {
    const RadiositySolution& solution = static_cast<const RadiositySolution&>(state);
    FilmSample out;
    ++counters.camera;
    std::optional<render::SurfaceHit> hit = scene.intersect(ray);
    if (!hit) {
        forEachLightAtInfinity(scene, ray.direction, ray.time, true, [&](int, const RGB& le) { out.radiance += le; });
        return out;
    }
    const Vec3f wo = -ray.direction;
    recordFirstHit(out, *hit, wo, camera);
    out.radiance = emittedAtHit(scene, *hit, wo);
    if (hit->lightShape) return out;
    if (std::optional<PatchPoint> at = solution.locator.locate(solution.patches, hit->point, hit->geometricNormal)) {
        const int e = elementOf(at->patch, dot(wo, solution.patches[at->patch].normal) > 0.0f ? 0 : 1);
        const RGB* corner = &solution.cornerIrradiance[3 * std::size_t(e)];
        out.radiance +=
            hit->material.diffuse * (corner[0] * (1.0f - at->b1 - at->b2) + corner[1] * at->b1 + corner[2] * at->b2);
    }
    return out;
}

}  // namespace fluence::integrators
