// The path tracer through OpenVDB volumes (media/ tracking, volumes/ GridMedium): Beer-Lambert
// through a pure absorber against its closed form, and a white furnace of albedo-1 smoke that
// neither loses nor gains light, with next-event estimation and MIS at every scattering event.
#include <gtest/gtest.h>

#include <openvdb/openvdb.h>

#include <cmath>

#include "integrators/naive_path_tracer.h"
#include "integrators/path_tracer.h"
#include "render/camera.h"
#include "render/render_scene.h"
#include "tests/support/statistics.h"
#include "tests/support/temp_dir.h"

namespace fluence::integrators {
namespace {

constexpr double kVoxel = 0.05;
constexpr int kVoxels = 40;  // active voxels 0..39 per axis, each of density 1

// A cube of density 1 at voxel centres 0..39 (times kVoxel), background 0. Along a line through
// voxel centres the trilinear density is 1 over 39 voxels and ramps to 0 over one more at each end:
// its integral is 40 voxels = 2 units.
std::string writeCube(const test::TempDir& dir) {
    openvdb::initialize();
    openvdb::FloatGrid::Ptr grid = openvdb::FloatGrid::create(0.0f);
    grid->setName("density");
    grid->setTransform(openvdb::math::Transform::createLinearTransform(kVoxel));
    grid->fill(openvdb::CoordBBox(openvdb::Coord(0), openvdb::Coord(kVoxels - 1)), 1.0f, true);
    std::string path = dir.file("cube.vdb");
    openvdb::io::File file(path);
    file.write({grid});
    file.close();
    return path;
}

render::SceneDescription smokeUnderAWhiteSky(const std::string& file, float densityScale, const RGB& albedo) {
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

// The mean radiance (or, with `alpha`, coverage) of `n` paths along `ray` (`path` unless another
// integrator is given).
test::MeanEstimate radianceAlong(const render::RenderScene& scene, const render::Ray& ray, int n,
                                 const Integrator& tracer = PathTracer(IntegratorSettings{}), bool alpha = false) {
    render::Camera camera(render::CameraDesc{}, 8, 8);
    const std::unique_ptr<RenderState> state = tracer.prepare(scene, camera, 11, nullptr);
    RenderCounters counters;
    test::MeanEstimate e;
    for (int i = 0; i < n; ++i) {
        SampleStream rng(11, 0, std::uint64_t(i));
        FilmSample s = tracer.sample(*state, scene, camera, ray, rng, counters);
        e.add(alpha ? (s.hit ? 1.0f : 0.0f) : (s.radiance.x + s.radiance.y + s.radiance.z) / 3.0f);
    }
    return e;
}

TEST(VolumePath, PureAbsorberTransmitsBeerLambert) {
    test::TempDir dir{"fluence_volume_path"};
    // Optical depth along the centre line: densityScale * 2 units = 1.
    render::RenderScene scene(smokeUnderAWhiteSky(writeCube(dir), 0.5f, RGB(0.0f)));
    ASSERT_TRUE(scene.medium());
    const float centre = 20 * kVoxel;
    test::MeanEstimate e = radianceAlong(scene, render::Ray{{-5.0f, centre, centre}, {1.0f, 0.0f, 0.0f}}, 20000);
    EXPECT_NEAR(e.mean(), std::exp(-1.0), 4.0 * e.standardError() + 1e-4) << e.mean() << " +- " << e.standardError();
    // A camera sample counts as covered where its first event is in the volume: alpha estimates
    // the opacity 1 - T.
    test::MeanEstimate alpha = radianceAlong(scene, render::Ray{{-5.0f, centre, centre}, {1.0f, 0.0f, 0.0f}}, 20000,
                                             PathTracer(IntegratorSettings{}), true);
    EXPECT_NEAR(alpha.mean(), 1.0 - std::exp(-1.0), 4.0 * alpha.standardError());
}

TEST(VolumePath, AlbedoOneSmokeInAWhiteFurnaceVanishes) {
    test::TempDir dir{"fluence_volume_path"};
    render::RenderScene scene(smokeUnderAWhiteSky(writeCube(dir), 4.0f, RGB(1.0f)));  // optical depth 8 across
    const float centre = 20 * kVoxel;
    for (const Vec3f& d : {Vec3f(1, 0, 0), normalize(Vec3f(1, 0.4f, -0.3f))}) {
        test::MeanEstimate e = radianceAlong(scene, render::Ray{Vec3f(centre) - d * 5.0f, d}, 4000);
        EXPECT_NEAR(e.mean(), 1.0, 4.0 * e.standardError() + 1e-4) << e.mean() << " +- " << e.standardError();
    }
}

TEST(VolumePath, PathAgreesWithTheNaiveReferenceInChromaticSmoke) {
    // Coloured albedo (each channel scatters and absorbs differently; the extinction itself is
    // grey, so chromatic extinction is left to tests/media/), optical depth 4 across: next-event
    // estimation and MIS must give what phase sampling alone gives.
    test::TempDir dir{"fluence_volume_path"};
    render::RenderScene scene(smokeUnderAWhiteSky(writeCube(dir), 2.0f, RGB(0.9f, 0.6f, 0.3f)));
    const float centre = 20 * kVoxel;
    const Vec3f d = normalize(Vec3f(1, 0.3f, 0.2f));
    const render::Ray ray{Vec3f(centre) - d * 5.0f, d};
    test::MeanEstimate path = radianceAlong(scene, ray, 20000);
    test::MeanEstimate naive = radianceAlong(scene, ray, 20000, NaivePathTracer(IntegratorSettings{}));
    const double se =
        std::sqrt(path.standardError() * path.standardError() + naive.standardError() * naive.standardError());
    EXPECT_NEAR(path.mean(), naive.mean(), 4.0 * se) << path.mean() << " vs " << naive.mean();
}

}  // namespace
}  // namespace fluence::integrators
