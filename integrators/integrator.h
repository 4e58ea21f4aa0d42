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
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/film.h"
#include "core/random.h"
#include "integrators/path_classes.h"
#include "render/camera.h"
#include "render/render_scene.h"

namespace fluence::integrators {

// What a render counted, for its summary: rays traced per kind, the tentative collisions drawn in
// media (each a medium lookup; the path tracer counts them), and samples discarded because their
// value was not finite (NaN or infinity; each one is a bug to find, so it is reported). The rays
// and collisions are also each sample's cost for adaptive sampling (integrators/sample_cost.h).
struct RenderCounters {
    std::uint64_t camera = 0;
    std::uint64_t bounce = 0;  // extension rays after the camera ray
    std::uint64_t shadow = 0;
    std::uint64_t mediumCollisions = 0;
    std::uint64_t walkSteps = 0;     // steps of guided subsurface random walks (their free flights)
    std::uint64_t exactCells = 0;    // grid cells walked by exact flights and transmittances (--exact-flights)
    std::uint64_t exactFlights = 0;  // exact flights and transmittances started (each sets up its walk)
    std::uint64_t nonFiniteSamples = 0;
    std::uint64_t rays() const { return camera + bounce + shadow; }
    RenderCounters& operator+=(const RenderCounters& o) {
        camera += o.camera;
        bounce += o.bounce;
        shadow += o.shadow;
        mediumCollisions += o.mediumCollisions;
        walkSteps += o.walkSteps;
        exactCells += o.exactCells;
        exactFlights += o.exactFlights;
        nonFiniteSamples += o.nonFiniteSamples;
        return *this;
    }
    // The counts of `o` taken back out: what was counted between `o` and this reading.
    RenderCounters& operator-=(const RenderCounters& o) {
        camera -= o.camera;
        bounce -= o.bounce;
        shadow -= o.shadow;
        mediumCollisions -= o.mediumCollisions;
        walkSteps -= o.walkSteps;
        exactCells -= o.exactCells;
        exactFlights -= o.exactFlights;
        nonFiniteSamples -= o.nonFiniteSamples;
        return *this;
    }
};

struct LightPathAov;        // integrators/light_path_tracker.h
class LightPathExpression;  // integrators/light_path_expression.h

struct IntegratorSettings {
    int maxDepth = 64;  // maximum number of scattering events along a path
    // The method's parameters given (IntegratorInfo::parameters), by IntegratorParameter::option;
    // one not given takes the method's default.
    std::map<std::string, double> parameters;
    double parameter(const std::string& option, double fallback) const {
        const auto it = parameters.find(option);
        return it == parameters.end() ? fallback : it->second;
    }
    // Light path expression AOVs, for the integrators whose IntegratorInfo::lightPathExpressions
    // says they write them (at most kMaxLightPathLayers, core/film.h); null for none.
    std::shared_ptr<const std::vector<LightPathAov>> lightPathAovs;
};

// What an integrator computes for one render before its samples, shared by every pixel: a
// radiosity solution, the photon maps of photon mapping, the choice of light for light subpaths,
// the events of the scene's lights for light path expressions. Integrators that need some derive
// their own (RadiositySolution, SppmRenderState, ...); the others use this empty one. The render
// loop owns it for the length of the render; sample() only reads it.
class RenderState {
public:
    virtual ~RenderState() = default;
    // What the method has to say about its solution for the render summary (a radiosity
    // solution's residual, a photon count), one line, read after the render; "" for nothing.
    virtual std::string summary() const { return ""; }
};

// PER-RENDER STATE. An integrator is immutable once built: its settings only. The render loop
// (integrators/renderer.h) calls prepare() once, which returns the render's state; then, for each
// pass, beginSamples() with that state and sample() for every pixel sample of the pass, in
// parallel, each given the state as a const argument. beginSamples() is called one at a time
// (never during sample()) and may run parallel loops of its own: it is where a method builds what
// a pass's sample indices need (the photon maps of photon mapping, one per sample index, so that a
// sample's value still depends only on (seed, pixel, sample index), whatever the passes and
// threads). Methods that need neither leave both hooks as they are.
class Integrator {
public:
    virtual ~Integrator() = default;
    // Light tracing: a method that adds light to other pixels than its sample's (bdpt's t = 1)
    // returns true from usesSplats(). The render loop then hands prepare() the film's splat film
    // (core/splat_film.h), or nullptr where splats cannot be used (a film that is only a window of
    // the image: a tile, integrators/renderer.h); the state keeps it for the render, and sample()
    // may add to it from any thread. Without one the method leaves those strategies out.
    virtual bool usesSplats() const { return false; }
    virtual std::unique_ptr<RenderState> prepare(const render::RenderScene& /*scene*/, const render::Camera& /*camera*/,
                                                 std::uint64_t /*seed*/, SplatFilm* /*splats*/) const {
        return std::make_unique<RenderState>();
    }
    virtual void beginSamples(RenderState& /*state*/, const render::RenderScene& /*scene*/,
                              const render::Camera& /*camera*/, std::uint64_t /*seed*/, int /*firstSample*/,
                              int /*count*/) const {}
    virtual FilmSample sample(const RenderState& state, const render::RenderScene& scene, const render::Camera& camera,
                              const render::Ray& ray, SampleStream& rng, RenderCounters& counters) const = 0;
};

// A parameter of one method, set by `fluence render --OPTION VALUE` or by the RenderSettings
// attribute ATTRIBUTE (the option wins); a value must be positive, at most `maximum`, and whole
// for a count.
struct IntegratorParameter {
    std::string option;     // e.g. "radiosity-patch-size"
    std::string attribute;  // e.g. "fluence:radiosity:patchSize"
    std::string meaning;    // for --help: what it sets and its default
    bool count = false;     // a whole number
    double maximum = 1e30;  // a count's bounds its memory (photon maps)
    double minimum = 1.0;   // a count's lowest value (0 for a level that can be off)
};

struct IntegratorInfo {
    std::string name;
    std::string pathClasses;  // Heckbert notation
    unsigned covers = 0;      // the PathClass bits it accounts for (integrators/path_classes.h)
    std::string description;
    std::function<std::unique_ptr<Integrator>(const IntegratorSettings&)> create;
    bool lightPathExpressions = false;  // writes IntegratorSettings::lightPathAovs into FilmSample::lightPaths
    std::vector<IntegratorParameter> parameters;  // read by create() from IntegratorSettings::parameters
    // Why it cannot write an expression that parses ("" when it can); null: it writes every one.
    std::function<std::string(const LightPathExpression&)> lightPathProblem = {};
};

// Every integrator Fluence offers, in the order `fluence --help` lists them.
const std::vector<IntegratorInfo>& integratorRegistry();
// The entry named `name`, or nullptr.
const IntegratorInfo* findIntegrator(const std::string& name);

}  // namespace fluence::integrators
