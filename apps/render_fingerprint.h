// What must be the same for a render to resume another's checkpoint (apps/render_checkpoint.h):
// every input that changes the value of a pixel sample or the shape of the film.
//
// Named entries: the Fluence version; the scene (absolute path) and the content of every layer
// file it composed (a 64-bit FNV-1a over them, so an edited layer is noticed); the asset files
// it refers to (textures, VDBs) by path, size and modification time (their contents are not read;
// a UDIM set's tiles are not listed); the camera, image resolution, window (tile) and frame; seed, integrator,
// samples per pixel, adaptive sampling's target error and minimum, maximum depth, the light path
// expression layers; and the options that change the scene: variants, --set, --purpose, render
// settings prim, subsurface method, dome light sampling, dicing. Whoever adds an option that changes what a sample
// sees must add it here. Not in it, because they do not change the samples: threads, time limit,
// output and preview paths, summary, checkpoint and snapshot intervals.
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "apps/cli_options.h"
#include "apps/render_checkpoint.h"
#include "integrators/light_path_tracker.h"
#include "scene/stage.h"

namespace fluence::app {

// What the render command resolved for one frame (the options alone do not say).
struct ResolvedRender {
    std::string cameraPath;
    int imageWidth = 0, imageHeight = 0;
    int windowX = 0, windowY = 0, windowWidth = 0, windowHeight = 0;
    double time = 0.0;  // NaN: default values
    std::string integrator;
    std::map<std::string, double> integratorParameters;  // by option
    int samplesPerPixel = 0;
    std::vector<integrators::LightPathAov> lightPathLayers;
    std::string sampler;
};

CheckpointFingerprint renderFingerprint(const RenderOptions& options, const usd::Stage& stage,
                                        const ResolvedRender& render);

// The fingerprint as 16 hex digits (FNV-1a over its entries), for an output's header
// ("fluence/fingerprint"): with --resume, an output that carries the render's own digest and has
// no checkpoint beside it is already rendered, and its frame is skipped.
std::string fingerprintDigest(const CheckpointFingerprint& fingerprint);

}  // namespace fluence::app
