#include "bench/minimal_path_tracer.h"

#include <embree3/rtcore.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/frame.h"
#include "core/sampling.h"
#include "integrators/russian_roulette.h"
#include "render/bsdf_arena.h"
#include "render/bsdfs/lambertian.h"
#include "render/embree_ray.h"
#include "render/lights/rect_light.h"
#include "render/lights/rect_light.h"
#include "render/material_bsdf.h"

namespace fluence::bench {

namespace {

[[noreturn]] void refuse(const std::string& why) { throw std::invalid_argument("the minimal path tracer " + why); }

}  // namespace

MinimalPathTracer::MinimalPathTracer(const render::RenderScene& scene, int maxDepth)
    : surfaces_(scene.embreeSurfaces()), maxDepth_(maxDepth) {
    if (scene.stats().instances > 0) refuse("takes no instances");
    if (scene.hasMedia()) refuse("takes no volumes or material interiors");
    if (scene.stats().emissiveTriangles > 0) refuse("takes no emissive meshes");
    const auto* rect = scene.lightCount() == 1 ? dynamic_cast<const render::RectLight*>(&scene.light(0)) : nullptr;
    if (!rect) refuse("needs one light, a RectLight");

    // The light: corners (-X, -Y), (+X, -Y), (+X, +Y), (-X, +Y), emitting away from (c1 - c0) x (c3 - c0).
    const std::array<Vec3f, 4> corners = rect->corners();
    corner_ = corners[0];
    edgeU_ = corners[1] - corners[0];
    edgeV_ = corners[3] - corners[0];
    area_ = rect->area();
    const float uu = dot(edgeU_, edgeU_), uv = dot(edgeU_, edgeV_), vv = dot(edgeV_, edgeV_), det = uu * vv - uv * uv;
    if (!(area_ > 0.0f) || !(det > 0.0f)) refuse("needs a light of non-zero area");
    normal_ = -normalize(cross(edgeU_, edgeV_));
    inverseUU_ = vv / det;
    inverseUV_ = -uv / det;
    inverseVV_ = uu / det;
    radiance_ = rect->emitted({corner_ + (edgeU_ + edgeV_) * 0.5f, normal_}, normal_);
    // The same radiance at every point and in every direction (no texture, no shaping): checked on a
    // grid of points, along the normal and 60 degrees off it towards each edge.
    const Vec3f tilts[] = {normal_, normalize(normal_ * 0.5f + normalize(edgeU_) * 0.866f),
                           normalize(normal_ * 0.5f - normalize(edgeV_) * 0.866f)};
    for (int i = 0; i < 5; ++i)
        for (int j = 0; j < 5; ++j)
            for (const Vec3f& wo : tilts)
                if (rect->emitted({corner_ + edgeU_ * ((i + 0.5f) / 5.0f) + edgeV_ * ((j + 0.5f) / 5.0f), normal_},
                                  wo) != radiance_)
                    refuse("needs a light of uniform radiance (no texture, no shaping)");

    // The table of triangles: each surface triangle, hit inside from just above it, through bare
    // Embree (its ids and barycentrics) and through the renderer (its material's BSDF).
    struct Entry {
        unsigned geomID, primID;
        Triangle triangle;
    };
    std::vector<Entry> entries;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    render::BsdfArena arena;
    const Vec3f up(0.0f, 0.0f, 1.0f);
    for (const render::RenderScene::SurfaceTriangle& t : scene.surfaceTriangles()) {
        const Vec3f c = cross(t.p1 - t.p0, t.p2 - t.p0);
        if (!(lengthSquared(c) > 0.0f)) continue;  // degenerate: no ray hits it
        const Vec3f n = normalize(c), inside = t.p0 * 0.6f + t.p1 * 0.3f + t.p2 * 0.1f;
        const render::Ray ray{render::offsetRayOrigin(inside, n), -n};
        RTCRayHit h;
        render::storeRayHit(h, ray.origin, ray.direction, ray.tMin, ray.tMax);
        rtcIntersect1(surfaces_, &context, &h);
        const std::optional<render::SurfaceHit> hit = scene.intersect(ray);
        if (h.hit.geomID == RTC_INVALID_GEOMETRY_ID || !hit || hit->lightShape)
            refuse("found no triangle inside a triangle");
        if (std::abs(h.hit.u - 0.3f) > 1e-3f || std::abs(h.hit.v - 0.1f) > 1e-3f)
            refuse("found Embree's triangle corners in another order than RenderScene::surfaceTriangles'");
        if (std::abs(dot(hit->shadingNormal, hit->geometricNormal)) < 1.0f - 1e-5f)
            refuse("takes only flat-shaded meshes");
        arena.reset();
        const render::Bsdf& bsdf = render::materialBsdf(hit->material, arena);
        if (!dynamic_cast<const render::LambertianBsdf*>(&bsdf)) refuse("takes only Lambertian materials");
        entries.push_back({h.hit.geomID, h.hit.primID, {t.p0, t.p1, t.p2, bsdf.f(up, up) * kPi}});
    }
    std::vector<unsigned> triangles;  // per geomID: one more than its largest primID
    for (const Entry& e : entries) {
        if (e.geomID >= triangles.size()) triangles.resize(e.geomID + 1, 0);
        triangles[e.geomID] = std::max(triangles[e.geomID], e.primID + 1);
    }
    firstTriangle_.assign(triangles.size(), 0);
    for (std::size_t g = 1; g < triangles.size(); ++g) firstTriangle_[g] = firstTriangle_[g - 1] + triangles[g - 1];
    const std::size_t total = triangles.empty() ? 0 : firstTriangle_.back() + triangles.back();
    triangles_.assign(total, Triangle{});
    std::vector<bool> filled(total, false);
    for (const Entry& e : entries) {
        const std::size_t i = firstTriangle_[e.geomID] + e.primID;
        if (filled[i]) refuse("found one Embree triangle inside two triangles");
        filled[i] = true;
        triangles_[i] = e.triangle;
    }
}

float MinimalPathTracer::hitLight(const Vec3f& o, const Vec3f& d, float tMin, float tMax) const {
    const float facing = dot(d, normal_);
    if (facing == 0.0f) return 0.0f;
    const float t = dot(corner_ - o, normal_) / facing;
    if (!(t > tMin && t < tMax)) return 0.0f;
    const Vec3f q = o + d * t - corner_;
    const float qu = dot(q, edgeU_), qv = dot(q, edgeV_);
    const float a = qu * inverseUU_ + qv * inverseUV_, b = qu * inverseUV_ + qv * inverseVV_;
    return a >= 0.0f && a <= 1.0f && b >= 0.0f && b <= 1.0f ? t : 0.0f;
}

RGB MinimalPathTracer::radiance(render::Ray ray, SampleStream& rng, Counters& counters) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RGB L(0.0f), throughput(1.0f);
    float scatterPdf = 0.0f;  // the density `ray`'s direction was drawn with (unused for the camera ray)
    for (int depth = 0;; ++depth) {
        RTCRayHit h;
        render::storeRayHit(h, ray.origin, ray.direction, ray.tMin, ray.tMax);
        rtcIntersect1(surfaces_, &context, &h);
        ++(depth == 0 ? counters.camera : counters.bounce);

        // The light, in front of the surface hit: its emission, then the path ends (as on a light shape in `path`).
        if (const float t = hitLight(ray.origin, ray.direction, ray.tMin, h.ray.tfar); t > 0.0f) {
            const float cosLight = -dot(normal_, ray.direction);
            if (cosLight > 0.0f)
                L += throughput * radiance_ *
                     (depth == 0 ? 1.0f : powerHeuristic(scatterPdf, t * t / (area_ * cosLight)));
            break;
        }
        if (h.hit.geomID == RTC_INVALID_GEOMETRY_ID || depth >= maxDepth_) break;

        // The unit normal facing the ray (one reciprocal: normalize's three divisions showed in profiles).
        const Vec3f ng(h.hit.Ng_x, h.hit.Ng_y, h.hit.Ng_z);
        const Vec3f n = ng * ((dot(ng, ray.direction) > 0.0f ? -1.0f : 1.0f) / std::sqrt(lengthSquared(ng)));
        const Triangle& hit = triangle(h.hit.geomID, h.hit.primID);
        const Vec3f from =
            render::offsetRayOrigin(hit.p0 * (1.0f - h.hit.u - h.hit.v) + hit.p1 * h.hit.u + hit.p2 * h.hit.v, n);
        const RGB& a = hit.albedo;

        // Next-event estimation: a point uniform on the light, its shadow ray, the power heuristic
        // against the cosine density (f cos = a cos / pi = a times that density).
        const Vec2f uLight = rng.next2D();
        const Vec3f toLight = corner_ + edgeU_ * uLight.x + edgeV_ * uLight.y - from;
        const float distanceSquared = lengthSquared(toLight), distance = std::sqrt(distanceSquared);
        const Vec3f wi = toLight * (1.0f / distance);
        const float cosLight = -dot(normal_, wi), cosSurface = dot(n, wi);
        if (cosLight > 0.0f && cosSurface > 0.0f) {
            RTCRay shadow;
            render::storeRay(shadow, from, wi, 0.0f, distance * (1.0f - kShadowRayShortening));
            rtcOccluded1(surfaces_, &context, &shadow);
            ++counters.shadow;
            if (shadow.tfar >= 0.0f) {
                const float lightPdf = distanceSquared / (area_ * cosLight), cosinePdf = cosSurface * kInvPi;
                L += throughput * a * radiance_ * (cosinePdf * powerHeuristic(lightPdf, cosinePdf) / lightPdf);
            }
        }

        // The bounce: cosine-weighted (weight f cos / pdf = a), then Russian roulette.
        const Vec3f local = sampleCosineHemisphere(rng.next2D());
        if (!(local.z > 0.0f)) break;
        throughput *= a;
        if (!integrators::continuePath(throughput, 1.0f, depth, rng)) break;
        scatterPdf = local.z * kInvPi;
        ray = {from, Frame::fromNormal(n).toWorld(local), 0.0f, std::numeric_limits<float>::infinity()};
    }
    return L;
}

MinimalRender MinimalPathTracer::render(tbb::task_arena& arena, const render::Camera& camera, int width, int height,
                                        int spp, std::uint64_t seed) const {
    struct Row {
        Counters counters;
        std::uint64_t nonFinite = 0;
        ImageMeanSum image;
    };
    std::vector<Row> rows(static_cast<std::size_t>(height));
    arena.execute([&] {
        tbb::parallel_for(0, height, [&](int y) {
            Row row;
            for (int x = 0; x < width; ++x) {
                RGB sum(0.0f);
                double lum = 0.0, lumSquared = 0.0;
                for (int s = 0; s < spp; ++s) {
                    SampleStream rng(seed, std::uint64_t(y) * std::uint64_t(width) + std::uint64_t(x),
                                     std::uint64_t(s));
                    const Vec2f jitter = rng.next2D();
                    RGB L = radiance(camera.generateRay(float(x) + jitter.x, float(y) + jitter.y), rng, row.counters);
                    if (!isFinite(L)) {
                        L = RGB(0.0f);
                        ++row.nonFinite;
                    }
                    sum += L;
                    const double l = luminance(L);
                    lum += l;
                    lumSquared += l * l;
                }
                const double n = spp, mean = lum / n;
                const double variance = spp > 1 ? std::max(0.0, (lumSquared - n * mean * mean) / (n - 1.0)) / n
                                                : std::numeric_limits<double>::infinity();
                row.image.addPixel(sum / float(spp), mean, variance);
            }
            rows[std::size_t(y)] = row;
        });
    });
    MinimalRender result;
    ImageMeanSum image;
    for (const Row& row : rows) {
        result.camera += row.counters.camera;
        result.bounce += row.counters.bounce;
        result.shadow += row.counters.shadow;
        result.nonFiniteSamples += row.nonFinite;
        image.add(row.image);
    }
    result.mean = image.mean();
    return result;
}

}  // namespace fluence::bench
