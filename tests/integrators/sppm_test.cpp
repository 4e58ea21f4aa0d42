// `sppm` (integrators/sppm.h) and its photon map (integrators/photon_map.h).
//
// Tolerances: sppm's pixels share their photon maps, so its image means are not averages of
// independent pixels; each is instead measured over independent renders (different seeds) and
// its standard error taken from their spread. `path`'s pixels are independent, so its standard
// error comes from them. Photon mapping is biased at a finite radius, by blurring the
// irradiance over the gather disk; the blur moves flux but does not create or destroy it, so a
// mean over a region that holds the blurred features (the caustic, the shadow edge) whole differs
// from the unblurred one only through the O(r^2) curvature of smooth irradiance at the region's
// edge, well under the standard errors here. The checks are therefore 4 combined standard errors.
#include "integrators/sppm.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <set>

#include "integrators/bdpt.h"
#include "integrators/path_tracer.h"
#include "tests/integrators/render_support.h"
#include "tests/support/scenes.h"

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
    EXPECT_FLOAT_EQ(Sppm::radius(2.0f, 0), 2.0f);
    // r_3^2 = r_1^2 (1 + a)/2 (2 + a)/3, a = 2/3.
    const double a = 2.0 / 3.0;
    EXPECT_NEAR(Sppm::radius(2.0f, 2), 2.0 * std::sqrt((1 + a) / 2 * (2 + a) / 3), 1e-6);
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

// The red channel over `region`: its mean, with the standard error of independent pixels.
test::MeanEstimate regionEstimate(const Image& image, const std::vector<bool>& region) {
    test::MeanEstimate e;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            if (region[std::size_t(y) * image.width + x]) e.add(image.pixel(x, y)[0]);
    return e;
}

test::MeanEstimate pathRegionMean(const render::SceneDescription& desc, int size, int spp, const std::vector<bool>& region) {
    return regionEstimate(test_support::renderWith(PathTracer(IntegratorSettings{}), desc, size, spp).image, region);
}

// The region's mean over `renders` sppm renders with seeds 1, 2, ...: independent estimates.
test::MeanEstimate sppmRegionMean(const render::SceneDescription& desc, const SppmSettings& settings, int size, int spp,
                                  int renders, const std::vector<bool>& region) {
    test::MeanEstimate e;
    for (int seed = 1; seed <= renders; ++seed)
        e.add(regionEstimate(test_support::renderWith(Sppm(IntegratorSettings{}, settings), desc, size, spp, 0, seed).image, region)
                  .mean());
    return e;
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
    test::MeanEstimate path = pathRegionMean(desc, kSize, 256, region);
    test::MeanEstimate sppm = sppmRegionMean(desc, settings, kSize, 16, 6, region);
    const double sigma = std::hypot(path.standardError(), sppm.standardError());
    std::printf("diffuse region: path %.5f +- %.5f, sppm %.5f +- %.5f\n", path.mean(), path.standardError(), sppm.mean(),
                sppm.standardError());
    EXPECT_NEAR(sppm.mean(), path.mean(), 4 * sigma);

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
    test::MeanEstimate path = pathRegionMean(desc, kSize, 16, caustic);
    test::MeanEstimate sppm = sppmRegionMean(desc, SppmSettings{20000, 0.03f}, kSize, 8, 4, caustic);
    std::printf("point-light caustic: path %.5f +- %.5f, sppm %.5f +- %.5f\n", path.mean(), path.standardError(), sppm.mean(),
                sppm.standardError());
    // path sees only the indirect light in the glass sphere's shadow.
    EXPECT_GT(sppm.mean(), 5.0 * path.mean() + 4.0 * sppm.standardError());
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
    test::MeanEstimate path = pathRegionMean(desc, kSize, 2048, region);
    test::MeanEstimate sppm = sppmRegionMean(desc, SppmSettings{20000, 0.03f}, kSize, 16, 6, region);
    const double sigma = std::hypot(path.standardError(), sppm.standardError());
    std::printf("area-light caustic region (%d pixels): path %.5f +- %.5f, sppm %.5f +- %.5f\n", path.count(), path.mean(),
                path.standardError(), sppm.mean(), sppm.standardError());
    EXPECT_NEAR(sppm.mean(), path.mean(), 4 * sigma);
    test::MeanEstimate bdpt = regionEstimate(test_support::renderWith(Bdpt(IntegratorSettings{}), desc, kSize, 1024).image, region);
    std::printf("area-light caustic region: bdpt %.5f +- %.5f\n", bdpt.mean(), bdpt.standardError());
    EXPECT_NEAR(sppm.mean(), bdpt.mean(), 4 * std::hypot(bdpt.standardError(), sppm.standardError()));
}

TEST(Sppm, ImagesAreBitIdenticalAcrossThreadCounts) {
    const render::SceneDescription desc = floorScene(true, 0.0f);
    const Sppm sppm(IntegratorSettings{}, SppmSettings{5000, 0.05f});
    Rendered one = test_support::renderWith(sppm, desc, 24, 5, 1, 42);
    Rendered two = test_support::renderWith(sppm, desc, 24, 5, 2, 42);
    ASSERT_EQ(one.image.pixels.size(), two.image.pixels.size());
    EXPECT_EQ(0, std::memcmp(one.image.pixels.data(), two.image.pixels.data(), one.image.pixels.size() * sizeof(float)));
    Rendered otherSeed = test_support::renderWith(sppm, desc, 24, 5, 2, 43);
    EXPECT_NE(0, std::memcmp(one.image.pixels.data(), otherSeed.image.pixels.data(),
                             one.image.pixels.size() * sizeof(float)));
}

}  // namespace
}  // namespace fluence::integrators
