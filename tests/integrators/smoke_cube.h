// The smoke cube the volume path tests render: an OpenVDB grid of density 1 over 40^3 voxels of
// 0.05 units (a cube 2 units wide from the origin), the scene of it as a volume (under a white sky
// dome; tests replace the lights), and the mean radiance of many paths along one ray.
#pragma once

#include <openvdb/openvdb.h>

#include <memory>
#include <string>

#include "integrators/integrator.h"
#include "integrators/path_tracer.h"
#include "render/camera.h"
#include "render/render_scene.h"
#include "tests/support/statistics.h"
#include "tests/support/temp_dir.h"

namespace fluence::test {

constexpr double kSmokeVoxel = 0.05;
constexpr int kSmokeVoxels = 40;  // active voxels 0..39 per axis, each of density 1

// A cube of density 1 at voxel centres 0..39 (times kSmokeVoxel), background 0, written into
// `dir`. Along a line through voxel centres the trilinear density is 1 over 39 voxels and ramps
// to 0 over one more at each end: its integral is 40 voxels = 2 units.
inline std::string writeSmokeCube(const TempDir& dir) {
    openvdb::initialize();
    openvdb::FloatGrid::Ptr grid = openvdb::FloatGrid::create(0.0f);
    grid->setName("density");
    grid->setTransform(openvdb::math::Transform::createLinearTransform(kSmokeVoxel));
    grid->fill(openvdb::CoordBBox(openvdb::Coord(0), openvdb::Coord(kSmokeVoxels - 1)), 1.0f, true);
    std::string path = dir.file("cube.vdb");
    openvdb::io::File file(path);
    file.write({grid});
    file.close();
    return path;
}

// The cube `file` as a volume of extinction densityScale per unit and scattering albedo `albedo`,
// under a dome of radiance 1.
inline render::SceneDescription smokeUnderAWhiteSky(const std::string& file, float densityScale, const RGB& albedo) {
    render::SceneDescription desc;
    render::LightDesc sky;
    sky.name = "/Sky";
    sky.type = render::LightType::Dome;
    sky.radiance = RGB(1.0f);
    desc.lights.push_back(sky);
    render::VolumeDesc v;
    v.name = "/Smoke";
    v.density = render::VolumeFieldDesc{file, "density", -1};
    v.params.densityScale = densityScale;
    v.params.albedo = albedo;
    desc.volumes.push_back(v);
    desc.camera = render::CameraDesc{};
    return desc;
}

// The mean radiance, per channel or (channel < 0) averaged over the three, or with `alpha` the
// coverage, of `n` paths along `ray` (`path` unless another integrator is given); seed 11.
inline MeanEstimate radianceAlong(
    const render::RenderScene& scene, const render::Ray& ray, int n,
    const integrators::Integrator& tracer = integrators::PathTracer(integrators::IntegratorSettings{}),
    bool alpha = false, int channel = -1) {
    render::Camera camera(render::CameraDesc{}, 8, 8);
    const std::unique_ptr<integrators::RenderState> state = tracer.prepare(scene, camera, 11, nullptr);
    integrators::RenderCounters counters;
    MeanEstimate e;
    for (int i = 0; i < n; ++i) {
        SampleStream rng(11, 0, std::uint64_t(i));
        FilmSample s = tracer.sample(*state, scene, camera, ray, rng, counters);
        e.add(alpha          ? (s.hit ? 1.0f : 0.0f)
              : channel >= 0 ? s.radiance[channel]
                             : (s.radiance.x + s.radiance.y + s.radiance.z) / 3.0f);
    }
    return e;
}

}  // namespace fluence::test
