// The first-hit AOV pass: data RenderVars that the film does not keep (core/film.h) — the value of
// a primvar at the first surface a camera ray hits, and depth, normal or albedo filtered by min,
// max or closest — computed after the render over the very camera samples the film took.
//
// Sample n of image pixel (x, y) is re-drawn from the renderer's stream (seed, y*imageWidth+x, n)
// (integrators/renderer.h): its first value places the ray in the pixel, so the pass traces the
// same camera rays the integrator did, as many as the film holds for the pixel (adaptive sampling
// included), and finds the same first surface. The pass reads surfaces only: a pixel seen through
// a volume reports the surface behind it. It costs one camera ray per sample, and nothing when no
// such RenderVar is asked for. Results are per pixel, so they do not depend on the thread count.
//
// Values per sample: Depth is the camera-space depth of the hit (the far clip on a miss), Normal
// the world-space shading normal turned towards the camera, Albedo the diffuse reflectance, and
// Primvar the primvar interpolated over the hit triangle (render::RenderScene::primvarAt; zero on
// a miss, on a light shape and on meshes without it; components it lacks read zero), and
// MotionVector where the hit point moves on the image from the shutter's opening to its close, in
// pixels (x to the right, y up, as compositing packages read it; zero for what does not move and
// on a miss; render::RenderScene::pointAt).
// Filters: Box is the mean over every sample (misses included with their value); Min and Max are
// per component over the samples that hit; Closest is the value of the hit nearest the camera
// (the first of equals). A pixel without hits reads the miss value.
#pragma once

#include <string>
#include <vector>

#include "core/film.h"
#include "core/image.h"
#include "integrators/renderer.h"
#include "render/camera.h"
#include "render/render_scene.h"

namespace fluence::integrators {

// How a pixel combines its samples' values.
enum class PixelFilter { Box, Min, Max, Closest };

enum class FirstHitSource { Depth, Normal, Albedo, Primvar, MotionVector };

struct FirstHitAov {
    FirstHitSource source = FirstHitSource::Depth;
    std::string primvar;  // Primvar: its name without "primvars:"
    int components = 1;   // how many components are written (1 to 4)
    PixelFilter filter = PixelFilter::Box;
};

// The AOVs over `film`'s pixels (the window `settings` places in the camera's image), as an Image
// of film.width() x film.height() whose channels are each AOV's components in order, named
// "AOV.COMPONENT" by index ("0.0", "0.1", ..., "1.0", ...). Runs on settings.threads threads.
Image renderFirstHitAovs(const render::RenderScene& scene, const render::Camera& camera, const RenderSettings& settings,
                         const Film& film, const std::vector<FirstHitAov>& aovs);

}  // namespace fluence::integrators
