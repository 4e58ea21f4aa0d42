#include "integrators/bdpt.h"
#include "integrators/direct_lighting.h"
#include "integrators/integrator.h"
#include "integrators/naive_path_tracer.h"
#include "integrators/path_tracer.h"
#include "integrators/photon_light_paths.h"
#include "integrators/radiosity.h"
#include "integrators/sppm.h"
#include "integrators/whitted.h"

namespace fluence::integrators {

// In the order `fluence --help` lists them: the default first, then by the light paths they cover,
// the reference estimator last.
const std::vector<IntegratorInfo>& integratorRegistry() {
    static const std::vector<IntegratorInfo> registry = {
        {"path",
         "L(S|D)*E",
         kAllPathClasses & ~kDeltaLightCaustics,
         "unidirectional path tracing with next-event estimation, MIS and Russian roulette",
         [](const IntegratorSettings& s) { return std::make_unique<PathTracer>(s); },
         true,
         {{"subsurface-walks", "fluence:path:subsurfaceWalks",
           "random walks from each entry of a camera ray into a guided subsurface interior, each lighting its exit "
           "with weight 1/N (default 1)",
           true, PathTracer::kMaxSubsurfaceWalks},
          {"walk-hero", "fluence:path:walkHero",
           "guided walks' channels: 1 a hero per walk, drawn mostly by mean free path, the walk weighted by MIS over "
           "whole "
           "walks; 0 a channel drawn at every step, MIS per step (default 1)",
           true, 1, 0.0},
          {"walks-after-diffuse", "fluence:path:walksAfterDiffuse",
           "1: a random walk at every entry into a subsurface interior (default, unbiased); 0: on a path that has "
           "bounced diffusely, a subsurface material reflects its subsurface share diffusely in its subsurface colour "
           "instead of walking, as Cycles' Principled BSDF does (biased: far less noise in the light it sends to other "
           "surfaces, a few percent darker)",
           true, 1, 0.0},
          {"exact-flights", "fluence:path:exactFlights",
           "regular tracking of the scene volume's free flights where its extinction is exact: 1 the camera ray's, 2 "
           "every flight with exact shadow transmittance where phase sampling competes, 3 also to delta lights "
           "(default 3; 0: delta tracking)",
           true, PathTracer::kMaxExactFlights, 0.0}}},
        {"direct",
         "L(D|S)?E",
         kEmitterSeen | kDirect | kDeltaLights,
         "local illumination with shadows: emitters seen, direct lighting of the first hit (NEE + MIS); no indirect "
         "light",
         [](const IntegratorSettings& s) { return std::make_unique<DirectLighting>(s); },
         false,
         {}},
        {"whitted",
         "LD?S*E",
         kEmitterSeen | kDirect | kSpecularSeen | kDeltaLights,
         "Whitted ray tracing: direct lighting (as `direct`) seen through mirrors and smooth glass; no caustics",
         [](const IntegratorSettings& s) { return std::make_unique<Whitted>(s); },
         false,
         {}},
        {"bdpt",
         "L(S|D|V)*E; from delta lights LD(S|D|V)*E, L(S|D|V)*DD(S|D|V)*E and L(S|D|V)*DE (no LS+DS+E)",
         kEmitterSeen | kDirect | kSpecularSeen | kIndirect | kCaustics | kDeltaLightCaustics | kDeltaLights |
             kVolumes | kSubsurface,
         "bidirectional path tracing, MIS (power heuristic, spectral in media) over every light/camera prefix pair, "
         "light tracing to the camera (t = 1) included, through volumes and interiors (subsurface walks join nowhere); "
         "point-light caustics seen directly (LS+DE) or lit onward, not through glass or mirrors (LS+DS+E); tiles and "
         "orthographic cameras and depth of field leave t = 1 out",
         [](const IntegratorSettings& s) { return std::make_unique<Bdpt>(s); },
         true,
         {}},
        {"sppm",
         "L(S|D|V)*(D|V)S*E, LS*E",
         kEmitterSeen | kDirect | kSpecularSeen | kIndirect | kCaustics | kDeltaLightCaustics | kDeltaLights |
             kVolumes | kSubsurface,
         "probabilistic progressive photon mapping: caustics, also from point lights, and volumetric caustics; "
         "subsurface by random walk; emissive media light nothing; light path expressions of at most 64 automaton "
         "states (each photon carries its own events' summary)",
         [](const IntegratorSettings& s) {
             SppmSettings sppm;
             sppm.photonPathsPerMap = static_cast<int>(s.parameter("sppm-photons", sppm.photonPathsPerMap));
             sppm.initialRadius = static_cast<float>(s.parameter("sppm-radius", sppm.initialRadius));
             return std::make_unique<Sppm>(s, sppm);
         },
         true,
         {{"sppm-photons", "fluence:sppm:photons", "photon paths traced per sample index (default 50000)", true, 1e7},
          {"sppm-radius", "fluence:sppm:radius",
           "the first sample's gather radius in scene units (default: 1.5 pixels' footprint at the scene's centre)"}},
         photonLightPathProblem},
        {"radiosity",
         "LD*E",
         kEmitterSeen | kDirect | kIndirect | kDeltaLights,
         "finite-element radiosity: patches, ray-cast form factors, Gauss-Seidel; every surface diffuse",
         [](const IntegratorSettings& s) {
             RadiositySettings radiosity;
             radiosity.patchEdge = static_cast<float>(s.parameter("radiosity-patch-size", radiosity.patchEdge));
             return std::make_unique<Radiosity>(radiosity);
         },
         false,
         {{"radiosity-patch-size", "fluence:radiosity:patchSize",
           "the longest patch edge in scene units (default: the scene's diameter / 16)"}}},
        {"naive",
         "L(S|D)*E without delta lights",
         kAllPathClasses & ~(kDeltaLights | kDeltaLightCaustics),
         "reference path tracing by BSDF sampling only (no NEE, no MIS): slow; for validating `path`",
         [](const IntegratorSettings& s) { return std::make_unique<NaivePathTracer>(s); },
         false,
         {}},
    };
    return registry;
}

const IntegratorInfo* findIntegrator(const std::string& name) {
    for (const IntegratorInfo& info : integratorRegistry())
        if (info.name == name) return &info;
    return nullptr;
}

}  // namespace fluence::integrators
