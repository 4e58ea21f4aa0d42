// The throughput ceiling's reference (issue #10 item 4, embree_throughput_bench --minimal): the
// leanest honest unidirectional path tracer for what the Cornell box is, Lambertian triangle
// meshes lit by one rect light, run straight on RenderScene::embreeSurfaces(). The per-hit work
// left next to Embree's is what any path tracer with next-event estimation must do here.
//
// It estimates what the `path` integrator estimates on such a scene, with the same strategies:
//   - camera rays from render::Camera::generateRay, jittered uniformly over the pixel (as the render
//     loop does); sample s of pixel (x, y) draws from SampleStream(seed, y * width + x, s);
//   - at each surface hit: the point from Embree's barycentrics and the triangle's corners, as the
//     renderer computes it (o + t d is not precise enough for render::offsetRayOrigin: rays leaving
//     such points re-hit their own surface, which lost 4% of the Cornell box's light); Embree's
//     geometric normal, normalised and turned towards the incoming ray; the albedo of the hit
//     triangle, from the table of triangles made once (below); next-event estimation to the
//     rect light by uniform area sampling, one rtcOccluded1 shadow ray from
//     render::offsetRayOrigin(p, n) stopped short as RenderScene::occluded stops it, weighted by
//     Veach's power heuristic against the cosine BSDF density; a cosine-weighted bounce; Russian
//     roulette as `path` plays it (integrators/russian_roulette.h continuePath); at most maxDepth bounces;
//   - BSDF-sampled rays are tested against the light's rectangle analytically (a plane and two edge
//     coordinates) up to the surface hit; emission reached from its front is weighted against the
//     light strategy (in full for camera rays), and a path ends on the light, as in `path`.
// Rays are counted as RenderCounters counts them: camera, bounce (each rtcIntersect1), shadow (each
// rtcOccluded1).
//
// Setup (not part of any timing): the light is the scene's only light, a render::RectLight whose
// corners, area and radiance (RectLight::emitted, so UsdLux normalize is applied) are read once;
// it must have the same radiance everywhere and in every direction (no texture or shaping). The
// table of triangles holds, per Embree (geomID, primID), the triangle's world-space corners and
// the albedo of the renderer's own BSDF there: each triangle of RenderScene::surfaceTriangles() is
// hit at a point inside it (barycentrics 0.6, 0.3, 0.1) by a ray through bare Embree (for its ids,
// and to check that Embree's barycentrics name the same corners) and through
// RenderScene::intersect (for its material, whose BSDF from render::materialBsdf must be a
// render::LambertianBsdf; albedo = f(n, n) pi). The albedo is constant over each triangle
// (textures and per-corner colours are not followed). A scene outside this (instances, media,
// emissive meshes, other lights, other materials, smooth shading normals) raises
// std::invalid_argument saying what.
#pragma once

#include <tbb/task_arena.h>

#include <cstdint>
#include <vector>

#include "bench/image_mean.h"
#include "core/random.h"
#include "core/rgb.h"
#include "core/vec.h"
#include "render/camera.h"
#include "render/ray.h"
#include "render/render_scene.h"

namespace fluence::bench {

// Shadow rays stop this fraction of their length short of the light, as RenderScene::occluded's do.
inline constexpr float kShadowRayShortening = 1e-4f;

struct MinimalRender {
    std::uint64_t camera = 0, bounce = 0, shadow = 0;
    std::uint64_t nonFiniteSamples = 0;  // dropped (counted as zero), as the render loop does
    ImageMean mean;                      // of the image's luminance
    std::uint64_t rays() const { return camera + bounce + shadow; }
};

class MinimalPathTracer {
public:
    MinimalPathTracer(const render::RenderScene& scene, int maxDepth);

    // Renders width x height pixels (the camera's image) at `spp` samples each, rows in parallel
    // over the arena's threads; the result does not depend on the thread count.
    MinimalRender render(tbb::task_arena& arena, const render::Camera& camera, int width, int height, int spp,
                         std::uint64_t seed) const;

private:
    struct Counters {
        std::uint64_t camera = 0, bounce = 0, shadow = 0;
    };
    // The radiance along one camera sample's path.
    RGB radiance(render::Ray ray, SampleStream& rng, Counters& counters) const;
    // The distance along o + t d, t in (tMin, tMax), to the light's rectangle (either side); 0: none.
    float hitLight(const Vec3f& o, const Vec3f& d, float tMin, float tMax) const;
    struct Triangle {
        Vec3f p0, p1, p2;  // Embree's corners: the hit at barycentrics (u, v) is p0 (1 - u - v) + p1 u + p2 v
        RGB albedo;
    };
    const Triangle& triangle(unsigned geomID, unsigned primID) const {
        return triangles_[firstTriangle_[geomID] + primID];
    }

    RTCSceneTy* surfaces_;
    int maxDepth_;
    // The light: corner, edges (its points are corner + a edgeU + b edgeV, a and b in [0, 1]), the
    // entries of the inverse of the edges' Gram matrix (which give a and b of a point in its plane),
    // the emitting side's unit normal, area and radiance.
    Vec3f corner_, edgeU_, edgeV_, normal_;
    float inverseUU_ = 0, inverseUV_ = 0, inverseVV_ = 0;
    float area_ = 0;
    RGB radiance_;
    std::vector<std::size_t> firstTriangle_;  // per geomID: its first entry in triangles_
    std::vector<Triangle> triangles_;         // by geomID, then primID
};

}  // namespace fluence::bench
