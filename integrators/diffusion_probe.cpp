#include "integrators/diffusion_probe.h"

#include <array>
#include <cmath>

#include "core/frame.h"
#include "media/normalized_diffusion.h"

namespace fluence::integrators {

namespace {

constexpr std::array<float, 3> kAxisProbability{0.5f, 0.25f, 0.25f};  // normal, tangent, bitangent

std::array<Vec3f, 3> probeAxes(const render::SurfaceHit& entry) {
    const Frame frame = Frame::fromNormalAndTangent(entry.shadingNormal, entry.tangent);
    return {frame.n, frame.s, frame.t};
}

struct DiffusionExit {
    render::SurfaceHit hit;  // where the light leaves, seen from the outside
    RGB weight;              // R(|po - pi|) / pdf(po)
};

// Whether a path that arrived along -wo at `hit` and leaves along wi enters a diffusion material.
bool entersDiffusion(const render::SurfaceHit& hit, const Vec3f& wo, const Vec3f& wi) {
    const render::MaterialParams& m = hit.material;
    return m.subsurface > 0.0f && m.subsurfaceMethod == render::SubsurfaceMethod::Diffusion && !m.thinWalled &&
           hit.interior >= 0 && dot(wo, hit.geometricNormal) > 0.0f && dot(wi, hit.geometricNormal) < 0.0f;
}

// The exit point of light entering at `entry`, or nullopt when the probe finds none.
std::optional<DiffusionExit> sampleDiffusionExit(const render::RenderScene& scene, const render::SurfaceHit& entry,
                                                 SampleStream& rng, RenderCounters& counters) {
    const render::MaterialParams& m = entry.material;
    const media::NormalizedDiffusion profile(m.subsurfaceColor, m.subsurfaceRadius * m.subsurfaceScale);
    const float uAxis = rng.next(), uChannel = rng.next();
    const Vec2f uDisk = rng.next2D();  // the probe's radius and angle
    const float uRadius = uDisk.x, uAngle = uDisk.y, uHit = rng.next();

    const std::array<Vec3f, 3> axes = probeAxes(entry);
    const int axis = uAxis < kAxisProbability[0] ? 0 : uAxis < kAxisProbability[0] + kAxisProbability[1] ? 1 : 2;
    const int channel = std::min(2, static_cast<int>(uChannel * 3.0f));
    const float r = profile.sampleRadius(channel, uRadius), rMax = profile.maxRadius(channel);
    if (!(r < rMax)) return std::nullopt;
    const float phi = 2.0f * kPi * uAngle, halfChord = std::sqrt(rMax * rMax - r * r);
    const Vec3f& along = axes[axis];
    const Vec3f& u = axes[(axis + 1) % 3];
    const Vec3f& v = axes[(axis + 2) % 3];
    const Vec3f start = entry.point + (u * std::cos(phi) + v * std::sin(phi)) * r - along * halfChord;

    // The surfaces of the entry's material along the probe.
    std::array<render::SurfaceHit, kMaxProbeHits> hits;
    int found = 0;
    float t = 0.0f;
    const float length = 2.0f * halfChord;
    while (found < kMaxProbeHits) {
        ++counters.bounce;
        std::optional<render::SurfaceHit> hit = scene.intersect(render::Ray{start, along, t, length, entry.time});
        if (!hit) break;
        if (hit->interior == entry.interior) hits[found++] = *hit;
        t = std::nextafter(hit->t, length) + 1e-5f * length;
    }
    if (found == 0) return std::nullopt;
    const render::SurfaceHit& exit = hits[std::min(found - 1, static_cast<int>(uHit * found))];

    const Vec3f d = exit.point - entry.point;
    float pdf = 0.0f;
    for (int a = 0; a < 3; ++a) {
        const float height = dot(d, axes[a]);
        const float rProjected = std::sqrt(std::max(0.0f, dot(d, d) - height * height));
        const float cosine = std::abs(dot(exit.geometricNormal, axes[a]));
        for (int c = 0; c < 3; ++c)
            if (rProjected < profile.maxRadius(c))
                pdf += kAxisProbability[a] * cosine * profile.pdfArea(c, rProjected) / 3.0f;
    }
    pdf /= static_cast<float>(found);
    if (!(pdf > 0.0f)) return std::nullopt;
    return DiffusionExit{exit, profile.profile(fluence::length(d)) / pdf};
}

}  // namespace

DiffusionStep stepThroughDiffusion(const render::RenderScene& scene, const render::SurfaceHit& hit, const Vec3f& wo,
                                   const Vec3f& wi, RGB& throughput, std::optional<render::SurfaceHit>& exit,
                                   SampleStream& rng, RenderCounters& counters) {
    if (!entersDiffusion(hit, wo, wi)) return DiffusionStep::NotEntered;
    std::optional<DiffusionExit> sampled = sampleDiffusionExit(scene, hit, rng, counters);
    if (!sampled) return DiffusionStep::Lost;
    throughput *= sampled->weight;
    exit = sampled->hit;
    return DiffusionStep::Exited;
}

}  // namespace fluence::integrators
