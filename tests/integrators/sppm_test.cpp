// `sppm` (integrators/sppm.h) and its photon map (integrators/photon_map.h).
//
// Tolerances: every mean compared here is measured over independent renders (different seeds),
// its standard error taken from their spread: sppm's pixels share their photon maps, so they are
// not independent, and the pixels of a region with contrast (a caustic, a shadow edge) spread with
// the contrast as well as the noise, so neither method's pixel-to-pixel spread is a standard error.
// Two means agree within Welch's t band at a Sidak-corrected 1% over the suite's comparisons.
// Photon mapping is biased at a finite radius, by blurring the irradiance over the gather disk;
// the blur moves flux but does not create or destroy it, so a mean over a region that holds the
// blurred features (the caustic, the shadow edge) whole differs from the unblurred one only through
// the O(r^2) curvature of smooth irradiance at the region's edge, well under the standard errors
// here. In media the gather ball also reaches out of the fog near its faces, where there are no
// photons: a bias of order r there, which SppmMedia.FogUnderAnAreaLightConvergesToPathAsTheBiasFalls
// measures at a large radius and shows falling into the noise as the radius shrinks.
#include "integrators/sppm.h"

#include <gtest/gtest.h>

#include <openvdb/openvdb.h>

#include <cmath>
#include <cstring>
#include <set>

#include "integrators/bdpt.h"
#include "integrators/path_tracer.h"
#include "integrators/photon_map.h"
#include "media/subsurface_medium.h"
#include "tests/integrators/render_support.h"
#include "tests/support/chi2.h"
#include "tests/support/scenes.h"
#include "tests/support/temp_dir.h"

namespace fluence::integrators {
namespace {

using test_support::Rendered;

TEST(PhotonMap, RangeQueryFindsExactlyThePhotonsWithinTheRadius) {
    // Photons in a box, half of them crowded into a corner so that slots hold many cells' photons;
    // queries in and around the box, half of them around the crowd, some right on cell faces.
    SampleStream rng(7, 0, 0);
    std::vector<Photon> photons;
    for (int i = 0; i < 20000; ++i) {
        const float spread = i % 2 ? 4.0f : 0.5f;
        photons.push_back({Vec3f(rng.next() * spread - 2.0f, rng.next() * spread - 2.0f, rng.next() * spread - 2.0f),
                           Vec3f(0.0f, 0.0f, 1.0f), RGB(float(i))});
    }
    const float radius = 0.125f;
    const PhotonMap map(photons, radius);
    ASSERT_EQ(map.size(), photons.size());
    std::size_t found = 0;
    for (int q = 0; q < 400; ++q) {
        const float spread = q % 2 ? 5.0f : 0.5f, low = q % 2 ? -2.5f : -2.0f;
        Vec3f p(rng.next() * spread + low, rng.next() * spread + low, rng.next() * spread + low);
        if (q % 4 == 0) p = Vec3f(std::round(p.x * 4.0f) / 4.0f, std::round(p.y * 4.0f) / 4.0f, p.z);  // on cell faces
        std::multiset<float> expected, got;
        for (const Photon& photon : photons)
            if (lengthSquared(photon.position - p) <= radius * radius) expected.insert(photon.power.x);
        map.forEachWithin(p, [&](const Photon& photon) { got.insert(photon.power.x); });
        EXPECT_EQ(got, expected) << "query " << q;
        found += got.size();
    }
    EXPECT_GT(found, 1000u);  // the queries did meet photons
}

TEST(Sppm, RadiusShrinksAsKnausAndZwicker) {
    EXPECT_FLOAT_EQ(Sppm::radius(2.0f, 0, 2), 2.0f);
    EXPECT_FLOAT_EQ(Sppm::radius(2.0f, 0, 3), 2.0f);
    // r_3^2 = r_1^2 (1 + a)/2 (2 + a)/3 on surfaces, r_3^3 = r_1^3 (1 + a)/2 (2 + a)/3 in media; a = 2/3.
    const double a = 2.0 / 3.0;
    EXPECT_NEAR(Sppm::radius(2.0f, 2, 2), 2.0 * std::sqrt((1 + a) / 2 * (2 + a) / 3), 1e-6);
    EXPECT_NEAR(Sppm::radius(2.0f, 2, 3), 2.0 * std::cbrt((1 + a) / 2 * (2 + a) / 3), 1e-6);
}

// A point light on a pole (a sphere light treated as a point, of intensity 10) above a diffuse
// floor; on the floor either a diffuse sphere or a smooth glass one whose caustic falls in front
// of it, towards the camera, which looks down at 45 degrees.
constexpr float kSphereRadius = 0.5f, kSphereHeight = 0.75f;
const Vec3f kLightPosition(0.0f, 2.0f, 4.0f);

render::SceneDescription floorScene(bool glass, float lightRadius) {
    render::SceneDescription s;
    s.materials.push_back(test::diffuseMaterial("/floor", RGB(0.5f)));
    render::MaterialDesc sphere = test::diffuseMaterial("/ball", RGB(0.7f));
    if (glass) {
        sphere.transmission = 1.0f;
        sphere.specular = 1.0f;
        sphere.roughness = 0.0f;
    }
    s.materials.push_back(sphere);
    s.meshes.push_back(test::quadMesh("/floor", {{{-6, -6, 0}, {6, -6, 0}, {6, 6, 0}, {-6, 6, 0}}}, 0));
    render::MeshDesc ball = test::sphereMesh(kSphereRadius, 64, 32, 1);
    for (Vec3f& p : ball.positions) p.z += kSphereHeight;
    s.meshes.push_back(ball);
    render::LightDesc light;
    light.name = "/light";
    light.type = render::LightType::Sphere;
    light.treatAsPoint = lightRadius == 0.0f;
    light.normalize = true;
    light.radius = light.treatAsPoint ? 0.5f : lightRadius;
    light.radiance = RGB(40.0f);  // normalized: intensity 10 as a point, power 40 pi as a sphere
    light.transform = Matrix4::translate({kLightPosition.x, kLightPosition.y, kLightPosition.z});
    s.lights.push_back(light);
    s.camera = test::lookAtOriginCamera(1.0f);
    s.camera->transform = Matrix4::translate({0, -3, 3}) * Matrix4::rotateX(45);
    return s;
}

// Pixels of a size x size render whose camera ray (through the pixel's centre) meets the floor
// within `reach` of `centre` without passing the sphere's bounding sphere.
std::vector<bool> floorRegion(const render::SceneDescription& desc, int size, const Vec3f& centre, float reach) {
    render::Camera camera(*desc.camera, size, size);
    std::vector<bool> region(std::size_t(size) * size, false);
    const Vec3f ball(0.0f, 0.0f, kSphereHeight);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            render::Ray ray = camera.generateRay(float(x) + 0.5f, float(y) + 0.5f);
            if (ray.direction.z >= 0.0f) continue;
            const Vec3f onFloor = ray.origin + ray.direction * (-ray.origin.z / ray.direction.z);
            const Vec3f toBall = ball - ray.origin;
            const float along = dot(toBall, ray.direction);
            const bool pastBall = lengthSquared(toBall - ray.direction * along) < 1.05f * kSphereRadius * kSphereRadius;
            region[std::size_t(y) * size + x] = !pastBall && lengthSquared(onFloor - centre) < reach * reach;
        }
    return region;
}

// Channel `channel` (red by default) over `region`: its mean, with the standard error of
// independent pixels.
test::MeanEstimate regionEstimate(const Image& image, const std::vector<bool>& region, int channel = 0) {
    test::MeanEstimate e;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            if (region[std::size_t(y) * image.width + x]) e.add(image.pixel(x, y)[channel]);
    return e;
}

// `renders` renders with seeds 1, 2, ..., `spp` samples each: independent estimates, whatever the
// integrator shares between pixels.
std::vector<Image> rendersOverSeeds(const Integrator& integrator, const render::SceneDescription& desc, int size,
                                    int spp, int renders) {
    std::vector<Image> images;
    for (int seed = 1; seed <= renders; ++seed)
        images.push_back(test_support::renderWith(integrator, desc, size, spp, 0, seed).image);
    return images;
}

// The region's mean of `channel` over independent renders, its standard error from their spread.
test::MeanEstimate regionMeanOver(const std::vector<Image>& images, const std::vector<bool>& region, int channel = 0) {
    test::MeanEstimate e;
    for (const Image& image : images) e.add(regionEstimate(image, region, channel).mean());
    return e;
}

test::MeanEstimate regionMeanOverSeeds(const Integrator& integrator, const render::SceneDescription& desc, int size,
                                       int spp, int renders, const std::vector<bool>& region) {
    return regionMeanOver(rendersOverSeeds(integrator, desc, size, spp, renders), region);
}

// The significance of each comparison of two methods below (about ten in the suite).
const double kAlpha = test::sidakAlpha(10);

void print(const char* what, const char* aName, const test::MeanEstimate& a, const char* bName,
           const test::MeanEstimate& b) {
    std::printf("%s: %s %.5f +- %.5f, %s %.5f +- %.5f (Welch band %.5f)\n", what, aName, a.mean(),
                a.unbiasedStandardError(), bName, b.mean(), b.unbiasedStandardError(), test::welchBand(a, b, kAlpha));
}

// `a` and `b` estimate the same value: a two-sided Welch test at kAlpha.
void expectAgreement(const char* what, const char* aName, const test::MeanEstimate& a, const char* bName,
                     const test::MeanEstimate& b) {
    print(what, aName, a, bName, b);
    EXPECT_NEAR(a.mean(), b.mean(), test::welchBand(a, b, kAlpha)) << what;
}

// `a` exceeds `b` by more than their noise can explain: a one-sided Welch test at kAlpha.
void expectSignificantlyGreater(const char* what, const char* aName, const test::MeanEstimate& a, const char* bName,
                                const test::MeanEstimate& b) {
    print(what, aName, a, bName, b);
    EXPECT_GT(a.mean() - b.mean(), test::welchBand(a, b, 2.0 * kAlpha)) << what;
}

// Where the glass sphere focuses the point light on the floor (paraxial focus f = n R / (2 (n - 1))
// from the centre, along the light's direction; the floor is a little further).
Vec3f causticCentre() {
    const Vec3f ball(0.0f, 0.0f, kSphereHeight);
    const Vec3f d = normalize(ball - kLightPosition);
    return ball + d * (-kSphereHeight / d.z);
}

TEST(Sppm, DiffuseSceneAgreesWithPathAndItsErrorFalls) {
    const render::SceneDescription desc = floorScene(false, 0.0f);
    constexpr int kSize = 32;
    const std::vector<bool> region = floorRegion(desc, kSize, Vec3f(0.0f), 2.0f);
    const SppmSettings settings{20000, 0.05f};
    const PathTracer pathTracer(IntegratorSettings{});
    test::MeanEstimate path = regionMeanOverSeeds(pathTracer, desc, kSize, 32, 8, region);
    test::MeanEstimate sppm = regionMeanOverSeeds(Sppm(IntegratorSettings{}, settings), desc, kSize, 16, 6, region);
    expectAgreement("diffuse region", "sppm", sppm, "path", path);

    // Per pixel (where blur bias and photon noise both show), sppm's distance from a converged
    // path image falls as samples are added.
    Rendered reference = test_support::renderWith(PathTracer(IntegratorSettings{}), desc, kSize, 1024);
    auto rmsError = [&](int spp) {
        Image image = test_support::renderWith(Sppm(IntegratorSettings{}, settings), desc, kSize, spp, 0, 3).image;
        double sum = 0.0;
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) sum += std::pow(image.pixel(x, y)[0] - reference.image.pixel(x, y)[0], 2);
        return std::sqrt(sum / (kSize * kSize));
    };
    const double early = rmsError(2), late = rmsError(32);
    std::printf("diffuse per-pixel rms error against path: 2 spp %.5f, 32 spp %.5f\n", early, late);
    EXPECT_LT(late, early);
}

TEST(Sppm, FindsThePointLightCausticThatPathCannot) {
    const render::SceneDescription desc = floorScene(true, 0.0f);
    constexpr int kSize = 48;
    const std::vector<bool> caustic = floorRegion(desc, kSize, causticCentre(), 0.15f);
    test::MeanEstimate path = regionMeanOverSeeds(PathTracer(IntegratorSettings{}), desc, kSize, 4, 4, caustic);
    test::MeanEstimate sppm =
        regionMeanOverSeeds(Sppm(IntegratorSettings{}, SppmSettings{20000, 0.03f}), desc, kSize, 8, 8, caustic);
    // path sees only the indirect light in the glass sphere's shadow: sppm, over five times brighter.
    expectSignificantlyGreater("point-light caustic", "sppm", sppm, "5 x path", path.scaled(5.0));
}

TEST(Sppm, AreaLightCausticConvergesToPathsAndBdpts) {
    // A sphere light of radius 0.8 in place of the point: path finds the caustic only by BSDF
    // sampling through the glass, which hits a light this large often enough for its error to be
    // small within the test's time; so does bdpt, whose other strategies cannot join through the
    // glass. The region lies in the ball's shadow: with a diffuse ball in place of the glass it
    // reads 0.0024 (against 0.08), so its light is the caustic's. The three methods converge to
    // the same brightness there.
    render::SceneDescription desc = floorScene(true, 0.8f);
    desc.camera->focalLength = 150.0f;  // zoomed in on the caustic, so that most pixels see it
    desc.camera->transform = Matrix4::translate({0.0, causticCentre().y - 3.0, 3.0}) * Matrix4::rotateX(45);
    constexpr int kSize = 32;
    const std::vector<bool> region = floorRegion(desc, kSize, causticCentre(), 0.5f);
    test::MeanEstimate path = regionMeanOverSeeds(PathTracer(IntegratorSettings{}), desc, kSize, 256, 8, region);
    test::MeanEstimate sppm =
        regionMeanOverSeeds(Sppm(IntegratorSettings{}, SppmSettings{20000, 0.03f}), desc, kSize, 16, 6, region);
    expectAgreement("area-light caustic region", "sppm", sppm, "path", path);
    test::MeanEstimate bdpt = regionMeanOverSeeds(Bdpt(IntegratorSettings{}), desc, kSize, 128, 8, region);
    expectAgreement("area-light caustic region", "sppm", sppm, "bdpt", bdpt);
}

TEST(Sppm, ImagesAreBitIdenticalAcrossThreadCounts) {
    const render::SceneDescription desc = floorScene(true, 0.0f);
    const Sppm sppm(IntegratorSettings{}, SppmSettings{5000, 0.05f});
    Rendered one = test_support::renderWith(sppm, desc, 24, 5, 1, 42);
    Rendered two = test_support::renderWith(sppm, desc, 24, 5, 2, 42);
    ASSERT_EQ(one.image.pixels.size(), two.image.pixels.size());
    EXPECT_EQ(0,
              std::memcmp(one.image.pixels.data(), two.image.pixels.data(), one.image.pixels.size() * sizeof(float)));
    Rendered otherSeed = test_support::renderWith(sppm, desc, 24, 5, 2, 43);
    EXPECT_NE(0, std::memcmp(one.image.pixels.data(), otherSeed.image.pixels.data(),
                             one.image.pixels.size() * sizeof(float)));
}

// ---- Media. Fog is a box of constant density in an OpenVDB grid (the scene's volumes, where `path`
// samples lights at every scattering): `voxels` voxels of `voxel` units per axis, density 1, its
// corner at `corner`. Its trilinear density ramps to 0 over the last voxel at each face.
render::VolumeDesc fogBox(const test::TempDir& dir, int voxels, double voxel, const Vec3d& corner, float sigmaT,
                          const RGB& albedo, float g) {
    openvdb::initialize();
    openvdb::FloatGrid::Ptr grid = openvdb::FloatGrid::create(0.0f);
    grid->setName("density");
    grid->setTransform(openvdb::math::Transform::createLinearTransform(voxel));
    grid->fill(openvdb::CoordBBox(openvdb::Coord(0), openvdb::Coord(voxels - 1)), 1.0f, true);
    const std::string path = dir.file("fog.vdb");
    openvdb::io::File file(path);
    file.write({grid});
    file.close();
    render::VolumeDesc v;
    v.name = "/Fog";
    v.transform = Matrix4::translate(corner);
    v.density = render::VolumeFieldDesc{path, "density", -1};
    v.params.densityScale = sigmaT;
    v.params.albedo = albedo;
    v.params.anisotropy = g;
    return v;
}

// Every pixel's red channel, as a region estimate.
test::MeanEstimate imageMean(const Image& image) {
    return regionEstimate(image, std::vector<bool>(std::size_t(image.width) * image.height, true));
}

// A cube of fog 2 units wide (extinction 1.5, albedo 0.8, g 0.3) under a square area light, seen
// from the side so closely that every pixel looks into it: single and multiple scattering (LV+E),
// nothing else.
render::SceneDescription litFogCube(const test::TempDir& dir) {
    render::SceneDescription s;
    s.volumes.push_back(fogBox(dir, 40, 0.05, Vec3d(-0.975), 1.5f, RGB(0.8f), 0.3f));
    s.lights.push_back(test::rectLight("/light", 1.0f, 1.0f, RGB(20.0f), Matrix4::translate({0.0, 0.0, 2.5})));
    s.camera = test::lookAtOriginCamera(4.0f);
    s.camera->focalLength = 120.0f;
    return s;
}

// The mean over the pixels (their centres' rays) of sppm's sample of index `sampleIndex` alone, with
// its photon map of that index and `seed`: an estimate whose radius is r_k, k = sampleIndex + 1.
double sppmSampleMean(const render::SceneDescription& desc, const SppmSettings& settings, int size,
                      std::uint64_t sampleIndex, std::uint64_t seed) {
    const Sppm sppm(IntegratorSettings{}, settings);
    const render::RenderScene scene(desc);
    const render::Camera camera(*desc.camera, size, size);
    const std::unique_ptr<RenderState> state = sppm.prepare(scene, camera, seed, nullptr);
    sppm.beginSamples(*state, scene, camera, seed, int(sampleIndex), 1);
    RenderCounters counters;
    double sum = 0.0;
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            SampleStream rng(seed, std::uint64_t(y) * size + x, sampleIndex);
            sum +=
                sppm.sample(*state, scene, camera, camera.generateRay(float(x) + 0.5f, float(y) + 0.5f), rng, counters)
                    .radiance.x;
        }
    return sum / (size * size);
}

TEST(SppmMedia, FogUnderAnAreaLightConvergesToPathAsTheBiasFalls) {
    // Each estimate is the image's mean over independent renders (seeds 1, 2, ...), its standard
    // error from their spread. sppm's samples are taken one sample index at a time, at k = 1 and
    // at k = 1e6 + 1, where the volume radius r_k ~ k^((alpha - 1)/3) has shrunk to 0.22 of r_1: the
    // kernel's bias (mostly the ball's part outside the fog near its faces, where no photons are)
    // is clear at r_1 = 0.7 and falls into the noise at 0.16.
    test::TempDir dir{"fluence_sppm_fog"};
    const render::SceneDescription desc = litFogCube(dir);
    constexpr int kSize = 16;
    test::MeanEstimate path;
    for (int seed = 1; seed <= 4; ++seed)
        path.add(imageMean(test_support::renderWith(PathTracer(IntegratorSettings{}), desc, kSize, 256, 0, seed).image)
                     .mean());
    const SppmSettings settings{40000, 0.7f};
    double bias[2];
    int i = 0;
    for (std::uint64_t sampleIndex : {std::uint64_t(0), std::uint64_t(1000000)}) {
        test::MeanEstimate sppm;
        for (int seed = 1; seed <= 16; ++seed) sppm.add(sppmSampleMean(desc, settings, kSize, sampleIndex, seed));
        const double band = test::welchBand(sppm, path, kAlpha);
        bias[i] = sppm.mean() - path.mean();
        std::printf("fog, sample index %llu (radius %.3f): bias %+.5f, band %.5f\n",
                    static_cast<unsigned long long>(sampleIndex), Sppm::radius(settings.initialRadius, sampleIndex, 3),
                    bias[i], band);
        print("fog", "sppm", sppm, "path", path);
        if (i++ == 0)
            EXPECT_GT(std::abs(bias[0]), band) << "the large radius's bias should show";
        else
            EXPECT_LT(std::abs(bias[1]), band);
    }
    EXPECT_LT(std::abs(bias[1]), std::abs(bias[0]));
}

// A glass ball (radius 0.5) in fog (extinction 0.15, albedo 0.8), a light 1.8 above its centre: the
// ball focuses the light into a beam below it (LS+VE, a volumetric caustic), seen from the side.
constexpr float kFogBallHeight = 2.5f, kFogLightHeight = 4.3f;

render::SceneDescription focusedBeam(const test::TempDir& dir, float lightRadius) {
    render::SceneDescription s;
    s.volumes.push_back(fogBox(dir, 40, 0.1, Vec3d(-1.95, -1.95, 0.0), 0.15f, RGB(0.8f), 0.0f));
    s.materials.push_back(test::glassMaterial("/glass", 0.0f));
    render::MeshDesc ball = test::roundSphereMesh(0.5f, 64, 32, 0, Vec3f(0.0f, 0.0f, kFogBallHeight));
    s.meshes.push_back(ball);
    const Vec3d at(0.0, 0.0, kFogLightHeight);
    render::LightDesc light = lightRadius == 0.0f ? test::pointLight("/light", RGB(1.0f), at)
                                                  : test::sphereLight("/light", lightRadius, RGB(1.0f), at);
    light.normalize = true;
    light.radiance = RGB(100.0f);
    s.lights.push_back(light);
    s.camera = test::lookAtOriginCamera(4.0f);
    s.camera->focalLength = 72.0f;
    s.camera->transform = Matrix4::translate({0.0, -4.0, 1.3}) * Matrix4::rotateX(90);
    return s;
}

// Pixels whose centre ray crosses the plane y = 0 within the beam: |x| < halfWidth, z in [zLow, zHigh].
std::vector<bool> beamRegion(const render::SceneDescription& desc, int size, float halfWidth, float zLow, float zHigh) {
    render::Camera camera(*desc.camera, size, size);
    std::vector<bool> region(std::size_t(size) * size, false);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            render::Ray ray = camera.generateRay(float(x) + 0.5f, float(y) + 0.5f);
            const Vec3f p = ray.origin + ray.direction * (-ray.origin.y / ray.direction.y);
            region[std::size_t(y) * size + x] = std::abs(p.x) < halfWidth && p.z > zLow && p.z < zHigh;
        }
    return region;
}

// The beam's light is the caustic's: the region lies in the ball's shadow, where direct light
// reaches the fog only through the glass; the rest is multiple scattering, which path finds.
TEST(SppmMedia, VolumetricCausticOfASmallSphereLightMatchesPath) {
    // A sphere light of radius 0.3: path finds the beam only when a phase-sampled direction from
    // the fog refracts through the ball onto the light, rarely, so it needs many samples.
    test::TempDir dir{"fluence_sppm_fog"};
    const render::SceneDescription desc = focusedBeam(dir, 0.3f);
    constexpr int kSize = 32;
    const std::vector<bool> beam = beamRegion(desc, kSize, 0.1f, 1.35f, 1.95f);
    test::MeanEstimate path = regionMeanOverSeeds(PathTracer(IntegratorSettings{}), desc, kSize, 256, 8, beam);
    test::MeanEstimate sppm =
        regionMeanOverSeeds(Sppm(IntegratorSettings{}, SppmSettings{40000, 0.15f}), desc, kSize, 16, 6, beam);
    expectAgreement("sphere-light beam", "sppm", sppm, "path", path);
}

TEST(SppmMedia, VolumetricCausticOfAPointLightThatPathCannotFind) {
    // The same beam from a point light of the same power: no path from the eye can reach it
    // through the glass, so path sees only the fog's multiple scattering there; sppm sees the beam.
    test::TempDir dir{"fluence_sppm_fog"};
    const render::SceneDescription desc = focusedBeam(dir, 0.0f);
    constexpr int kSize = 32;
    const std::vector<bool> beam = beamRegion(desc, kSize, 0.1f, 1.35f, 1.95f);
    test::MeanEstimate path = regionMeanOverSeeds(PathTracer(IntegratorSettings{}), desc, kSize, 8, 8, beam);
    test::MeanEstimate sppm =
        regionMeanOverSeeds(Sppm(IntegratorSettings{}, SppmSettings{40000, 0.15f}), desc, kSize, 8, 12, beam);
    expectSignificantlyGreater("point-light beam", "sppm", sppm, "path", path);
}

TEST(SppmMedia, RandomWalkSubsurfaceAgreesWithPath) {
    // A subsurface sphere (random walk through media/subsurface_medium.h's interior, mean free
    // path 0.2 of its radius 1, index-matched boundary) under a white sky. Photons walk through
    // the interior and are gathered where they come out, through the boundary's transmission
    // lobe; the mean over the pixels that see the sphere matches path's, per channel.
    render::SceneDescription desc = test::furnaceScene(1.0f);
    render::MaterialDesc& skin = desc.materials[0];
    skin.subsurface = 1.0f;
    skin.subsurfaceColor = RGB(0.8f, 0.5f, 0.3f);
    skin.specular = 0.0f;
    skin.interior = media::subsurfaceMedium(skin.subsurfaceColor, RGB(0.2f), 0.0f);
    constexpr int kSize = 24;
    const std::vector<Image> pathImages = rendersOverSeeds(PathTracer(IntegratorSettings{}), desc, kSize, 8, 8);
    const int alpha = pathImages[0].channelIndex("A");
    std::vector<bool> sphere(kSize * kSize);
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) sphere[std::size_t(y) * kSize + x] = pathImages[0].pixel(x, y)[alpha] == 1.0f;
    const std::vector<Image> sppmImages =
        rendersOverSeeds(Sppm(IntegratorSettings{}, SppmSettings{20000, 0.05f}), desc, kSize, 4, 4);
    for (int c : {0, 2})
        expectAgreement(c == 0 ? "subsurface sphere, red" : "subsurface sphere, blue", "sppm",
                        regionMeanOver(sppmImages, sphere, c), "path", regionMeanOver(pathImages, sphere, c));
}

TEST(SppmMedia, SampleSmokeRendersWithoutNonFiniteValues) {
    // usd_samples/smoke/smoke.usda as the render core takes it: its plume (density and temperature
    // grids, the sample's volume material), ground, sun and sky. Photons scatter through the
    // heterogeneous grid (majorant-grid DDA, chromatic sky), and the hot core's emission is seen.
    render::SceneDescription desc;
    desc.materials.push_back(test::diffuseMaterial("/ground", RGB(0.4f, 0.38f, 0.35f)));
    desc.meshes.push_back(test::quadMesh("/ground", {{{-20, 0, -20}, {-20, 0, 20}, {20, 0, 20}, {20, 0, -20}}}, 0));
    render::VolumeDesc smoke;
    smoke.name = "/Smoke";
    const std::string file = FLUENCE_SOURCE_DIR "/usd_samples/smoke/smoke.vdb";
    smoke.density = render::VolumeFieldDesc{file, "density", -1};
    smoke.temperature = render::VolumeFieldDesc{file, "temperature", -1};
    smoke.params.densityScale = 6.0f;
    smoke.params.albedo = RGB(0.9f);
    smoke.params.anisotropy = 0.2f;
    smoke.params.blackbodyIntensity = 3.0f;
    smoke.params.temperatureScale = 2000.0f;
    smoke.params.temperatureOffset = 500.0f;
    desc.volumes.push_back(smoke);
    render::LightDesc sun =
        test::distantLight("/sun", 0.53f, RGB(3.0f, 2.85f, 2.64f), Matrix4::rotateY(-50) * Matrix4::rotateX(-25));
    sun.normalize = true;
    desc.lights.push_back(sun);
    desc.lights.push_back(test::domeLight("/sky", RGB(0.33f, 0.42f, 0.6f)));
    render::CameraDesc camera;
    camera.focalLength = 30.0f;
    camera.horizontalAperture = 24.0f;
    camera.verticalAperture = 24.0f;
    camera.nearClip = 0.05f;
    camera.transform = Matrix4::translate({0.3, 1.6, 7.5}) * Matrix4::rotateX(-2);
    desc.camera = camera;
    const Sppm sppm(IntegratorSettings{}, SppmSettings{200000, 0.0f});
    const Rendered r = test_support::renderWith(sppm, desc, 24, 4);
    EXPECT_EQ(r.stats.counters.nonFiniteSamples, 0u);
    const int alpha = r.image.channelIndex("A");
    test::MeanEstimate covered = test_support::channelMean(r.image, 0, [&](const float* p) {
        EXPECT_TRUE(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]));
        return p[alpha] > 0.0f;
    });
    std::printf("smoke: %d pixels covered, red %.4f +- %.4f; %s\n", covered.count(), covered.mean(),
                covered.standardError(), r.stats.methodSummary.c_str());
    EXPECT_GT(covered.mean(), 4 * covered.standardError());
}

}  // namespace
}  // namespace fluence::integrators
