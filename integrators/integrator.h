// Integrators: the solution methods of the radiance equation.
//
// An integrator estimates the radiance arriving along one camera ray. Each declares the class of
// light paths it accounts for in Heckbert's notation (L light, D diffuse, S specular, E eye), so
// users and tests can tell which light a method will miss. Integrators are stateless once
// built: every random decision comes from the SampleStream, so a sample's value depends only on
// (seed, pixel, sample index).
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/film.h"
#include "core/random.h"
#include "render/camera.h"
#include "render/render_scene.h"

namespace fluence::integrators {

// What a render counted, for its summary: rays traced per kind, and samples discarded because
// their value was not finite (NaN or infinity; each one is a bug to find, so it is reported).
struct RenderCounters {
    std::uint64_t camera = 0;
    std::uint64_t bounce = 0;  // extension rays after the camera ray
    std::uint64_t shadow = 0;
    std::uint64_t nonFiniteSamples = 0;
    std::uint64_t rays() const { return camera + bounce + shadow; }
    RenderCounters& operator+=(const RenderCounters& o) {
        camera += o.camera;
        bounce += o.bounce;
        shadow += o.shadow;
        nonFiniteSamples += o.nonFiniteSamples;
        return *this;
    }
};

struct IntegratorSettings {
    int maxDepth = 64;  // maximum number of scattering events along a path
};

class Integrator {
public:
    virtual ~Integrator() = default;
    virtual FilmSample sample(const render::RenderScene& scene, const render::Camera& camera, const render::Ray& ray,
                              SampleStream& rng, RenderCounters& counters) const = 0;
};

struct IntegratorInfo {
    std::string name;
    std::string pathClasses;  // Heckbert notation
    std::string description;
    std::function<std::unique_ptr<Integrator>(const IntegratorSettings&)> create;
};

// Every integrator Fluence offers, in the order `fluence --help` lists them.
const std::vector<IntegratorInfo>& integratorRegistry();
// The entry named `name`, or nullptr.
const IntegratorInfo* findIntegrator(const std::string& name);

}  // namespace fluence::integrators
