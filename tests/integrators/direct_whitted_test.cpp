// `direct` and `whitted` (integrators/direct_lighting.h, integrators/whitted.h): each computes the
// light paths its class says, checked against `path` limited to the same paths or against closed
// forms, and each misses, measurably, the paths outside its class.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>

#include "integrators/direct_lighting.h"
#include "integrators/path_tracer.h"
#include "integrators/whitted.h"
#include "tests/integrators/render_support.h"
#include "tests/support/chi2.h"
#include "tests/support/scenes.h"

namespace fluence::integrators {
namespace {

using test_support::renderWith;

// The statistical checks below, one per channel: agreement with `path` at depth 1 and the furnace
// (6), the box and the glass furnace for both methods (9), the caustic in the umbra and on the
// floor (2), the absorbing cube and the absorbing interior (6); family-wide 1%, two-sided where a
// value is checked, one-sided where a shortfall must show.
constexpr double kChecks = 23;
const double kTwoSidedZ = test::normalQuantile(0.5 * test::sidakAlpha(kChecks));
const double kOneSidedZ = test::normalQuantile(test::sidakAlpha(kChecks));

using test_support::meanDifference;
bool everyPixel(int, int) { return true; }

// A sphere of radius r at c with smooth shading normals.
render::MeshDesc roundSphere(float r, const Vec3f& c, int material) {
    return test::roundSphereMesh(r, 32, 16, material, c);
}

render::MaterialDesc smoothGlass() {
    render::MaterialDesc m;
    m.name = "/glass";
    m.diffuse = RGB(0.0f);  // the albedo AOV tells glass from the floor
    m.transmission = 1.0f;
    m.roughness = 0.0f;
    m.ior = 1.5f;
    return m;
}

// Every light kind (rect, sphere, point, angle-0 and wide distant, dome, an emissive panel) over
// a diffuse floor, a glossy sphere, rough glass and a mirror sphere (whose delta lobe shows the
// emitters it reflects: LSE, which `path` at depth 1 has too).
render::SceneDescription everyLightScene() {
    render::SceneDescription s;
    s.materials.push_back(test::diffuseMaterial("/grey", RGB(0.5f)));
    render::MaterialDesc glossy = test::diffuseMaterial("/glossy", RGB(0.7f, 0.3f, 0.1f));
    glossy.specular = 1.0f;
    glossy.roughness = 0.25f;
    s.materials.push_back(glossy);
    render::MaterialDesc roughGlass = smoothGlass();
    roughGlass.roughness = 0.35f;
    s.materials.push_back(roughGlass);
    render::MaterialDesc mirror = test::diffuseMaterial("/mirror", RGB(0.9f, 0.8f, 0.6f));
    mirror.metallic = 1.0f;
    mirror.roughness = 0.0f;
    s.materials.push_back(mirror);
    s.materials.push_back(test::diffuseMaterial("/glow", RGB(0.2f), RGB(0.5f, 2.0f, 1.0f)));
    s.meshes.push_back(test::quadMesh("/floor", {{{-4, -4, -1}, {4, -4, -1}, {4, 4, -1}, {-4, 4, -1}}}, 0));
    s.meshes.push_back(roundSphere(0.6f, {-0.9f, 0.2f, -0.4f}, 1));
    s.meshes.push_back(roundSphere(0.5f, {0.9f, 0.0f, -0.5f}, 2));
    s.meshes.push_back(roundSphere(0.4f, {0.0f, 1.0f, -0.6f}, 3));
    s.meshes.push_back(
        test::quadMesh("/panel", {{{-1.5f, 2, -1}, {1.5f, 2, -1}, {1.5f, 2.5f, 1.5f}, {-1.5f, 2.5f, 1.5f}}}, 4));

    s.lights.push_back(test::rectLight("/rect", 1.5f, 1.0f, RGB(6.0f, 5.0f, 4.0f),
                                       Matrix4::translate({1.5, -0.5, 2.5}) * Matrix4::rotateY(30)));
    s.lights.push_back(test::sphereLight("/bulb", 0.3f, RGB(8.0f), {-1.8, -0.8, 0.5}));
    s.lights.push_back(test::pointLight("/point", RGB(40.0f, 30.0f, 20.0f), {0.5, -1.5, 0.8}));
    s.lights.push_back(test::distantLight("/sun", 0.0f, RGB(0.8f), Matrix4::rotateX(35) * Matrix4::rotateY(-20)));
    render::LightDesc wideSun =
        test::distantLight("/wideSun", 20.0f, RGB(0.8f), Matrix4::rotateX(-25) * Matrix4::rotateY(40));
    wideSun.normalize = true;
    s.lights.push_back(wideSun);
    s.lights.push_back(test::domeLight("/dome", RGB(0.1f, 0.15f, 0.3f)));
    s.camera = test::lookAtOriginCamera(5.0f);
    return s;
}

TEST(DirectLighting, AgreesWithPathAtDepthOneUnderEveryLightKind) {
    // `direct` is `path` with maxDepth 1 (emitters seen, direct lighting by NEE and MIS, emitters
    // through the first delta lobe). Independent renders (seeds 1 and 2): every channel's mean
    // difference over the image is 0 within its noise.
    const render::SceneDescription scene = everyLightScene();
    const Image direct = renderWith(DirectLighting(IntegratorSettings{}), scene, 64, 64, 0, 1).image;
    const Image path = renderWith(PathTracer(IntegratorSettings{.maxDepth = 1, .parameters = {}, .lightPathAovs = {}}),
                                  scene, 64, 64, 0, 2)
                           .image;
    for (int c = 0; c < 3; ++c) {
        const test::MeanEstimate d = meanDifference(direct, path, c, everyPixel);
        const test::MeanEstimate level = test_support::channelMean(direct, c, [](const float*) { return true; });
        std::printf("[ measured ] channel %d: direct %.5f, direct - path(depth 1) %+.6f +- %.6f\n", c, level.mean(),
                    d.mean(), d.standardError());
        EXPECT_GT(d.standardError(), 0.0);
        EXPECT_NEAR(d.mean(), 0.0, kTwoSidedZ * d.standardError()) << "channel " << c;
    }
}

TEST(DirectLighting, ConvexSphereUnderAUniformDomeReadsItsAlbedo) {
    // A convex diffuse sphere sees only the dome, so all its light is direct: L = albedo x 1.
    const test_support::Rendered r = renderWith(DirectLighting(IntegratorSettings{}), test::furnaceScene(0.5f), 48, 16);
    const int a = r.image.channelIndex("A");
    for (int c = 0; c < 3; ++c) {
        const test::MeanEstimate sphere =
            test_support::channelMean(r.image, c, [&](const float* p) { return p[a] == 1.0f; });
        std::printf("[ measured ] channel %d: %.5f +- %.5f over %d pixels (expected 0.5)\n", c, sphere.mean(),
                    sphere.standardError(), sphere.count());
        ASSERT_GT(sphere.count(), 500);
        EXPECT_NEAR(sphere.mean(), 0.5, kTwoSidedZ * sphere.standardError() + 1e-6) << "channel " << c;
    }
}

// Inside a closed diffuse box (albedo 0.7) lit by a rect light under its ceiling.
render::SceneDescription closedBox() {
    render::SceneDescription s;
    s.materials.push_back(test::diffuseMaterial("/white", RGB(0.7f, 0.7f, 0.5f)));
    s.meshes.push_back(test::boxMesh(Vec3f(1.0f), 0));
    s.lights.push_back(
        test::rectLight("/ceilingLight", 0.6f, 0.6f, RGB(10.0f), Matrix4::translate({0, 0, 0.99})));  // emits down (-Z)
    s.camera = test::lookAtOriginCamera(0.95f);
    return s;
}

TEST(DirectLighting, MissesTheIndirectLightOfAClosedBox) {
    // In a closed box of albedo 0.7 most light has bounced more than once: `path` is brighter
    // than `direct` by many standard errors of the difference, in every channel.
    const render::SceneDescription scene = closedBox();
    const Image direct = renderWith(DirectLighting(IntegratorSettings{}), scene, 32, 16, 0, 1).image;
    const Image path = renderWith(PathTracer(IntegratorSettings{}), scene, 32, 16, 0, 2).image;
    for (int c = 0; c < 3; ++c) {
        const test::MeanEstimate missing = meanDifference(path, direct, c, everyPixel);
        const test::MeanEstimate level = test_support::channelMean(path, c, [](const float*) { return true; });
        std::printf(
            "[ measured ] channel %d: path %.4f, path - direct %.4f +- %.4f (%.0f%% of the light is indirect)\n", c,
            level.mean(), missing.mean(), missing.standardError(), 100.0 * missing.mean() / level.mean());
        EXPECT_GT(missing.mean(), kOneSidedZ * missing.standardError()) << "channel " << c;
    }
}

TEST(Whitted, IsDirectWhereThereIsNoDeltaLobe) {
    // With nothing specular the two methods trace the same rays with the same random numbers.
    const render::SceneDescription scene = closedBox();
    const Image direct = renderWith(DirectLighting(IntegratorSettings{}), scene, 16, 4, 0, 3).image;
    const Image whitted = renderWith(Whitted(IntegratorSettings{}), scene, 16, 4, 0, 3).image;
    ASSERT_EQ(direct.pixels.size(), whitted.pixels.size());
    EXPECT_EQ(0, std::memcmp(direct.pixels.data(), whitted.pixels.data(), direct.pixels.size() * sizeof(float)));
}

// A camera at height h looking straight down (-Z) at the origin, with the field of view of
// lookAtOriginCamera (apertures 36 mm, focal length 50 mm).
render::CameraDesc lookingDown(float h) {
    render::CameraDesc c = test::lookAtOriginCamera(1.0f);
    c.transform = Matrix4::translate({0, 0, h});
    return c;
}

TEST(Whitted, MirrorShowsTheCeilingLitDirectlyTimesItsReflectance) {
    // A mirror floor (z = 0, Schlick reflectance of F0 per channel) under a diffuse ceiling (z = 2)
    // lit by a point light (z = 1), seen from above. Each camera ray reflects at the floor to the
    // ceiling, where the point light's direct lighting is exact (one delta light: no noise).
    // Unfolding the mirror (the ceiling and the light reflected to z = -2 and z = -1, no mirror)
    // gives the same ceiling point along the same camera ray: `whitted` on the mirror scene is F
    // times `direct` on the unfolded one, pixel by pixel, with F between F0 and Schlick's value at
    // the widest angle of the frame. `direct` sees the mirror black: LDSE is not its class.
    const RGB f0(0.9f, 0.6f, 0.3f);
    const float ceiling = 2.0f;
    const double lightHeight = 1.0;
    auto scene = [&](bool mirror) {
        render::SceneDescription s;
        s.materials.push_back(test::diffuseMaterial("/ceiling", RGB(0.5f)));
        render::MaterialDesc metal = test::diffuseMaterial("/mirror", f0);
        metal.metallic = 1.0f;
        metal.roughness = 0.0f;
        s.materials.push_back(metal);
        const float z = mirror ? ceiling : -ceiling;
        s.meshes.push_back(test::quadMesh("/ceiling", {{{-5, -5, z}, {5, -5, z}, {5, 5, z}, {-5, 5, z}}}, 0));
        if (mirror)
            s.meshes.push_back(test::quadMesh("/mirror", {{{-5, -5, 0}, {5, -5, 0}, {5, 5, 0}, {-5, 5, 0}}}, 1));
        s.lights.push_back(test::pointLight("/point", RGB(50.0f), {0.3, -0.2, mirror ? lightHeight : -lightHeight}));
        s.camera = lookingDown(1.5f);
        return s;
    };
    const Image whitted = renderWith(Whitted(IntegratorSettings{}), scene(true), 16, 4, 0, 5).image;
    const Image unfolded = renderWith(DirectLighting(IntegratorSettings{}), scene(false), 16, 4, 0, 5).image;
    const Image direct = renderWith(DirectLighting(IntegratorSettings{}), scene(true), 16, 4, 0, 5).image;
    // The widest angle to the mirror's normal: the frame's corner, half-apertures 18 mm at 50 mm.
    const double tanWidest = std::sqrt(2.0) * 18.0 / 50.0, cosWidest = 1.0 / std::sqrt(1.0 + tanWidest * tanWidest);
    // The reflected ray starts 2^-16 above the mirror (render/ray.h's offset near the origin), so it
    // reaches the ceiling up to 2^-16 tan(widest angle) away from the unfolded ray's point, where
    // the light's irradiance h / (r^2 + h^2)^(3/2) changes by at most 3 / (2h) per unit length
    // (relative); and float rounding adds a few ulps (2^-23) per operation over some tens of them.
    const double slack =
        std::ldexp(1.0, -16) * tanWidest * 3.0 / (2.0 * (ceiling - lightHeight)) + 64 * std::ldexp(1.0, -23);
    double worst = 0.0, directMax = 0.0;
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x)
            for (int c = 0; c < 3; ++c) {
                const double w = whitted.pixel(x, y)[c], u = unfolded.pixel(x, y)[c];
                const double lo = f0[c] * u, hi = (f0[c] + (1.0 - f0[c]) * std::pow(1.0 - cosWidest, 5.0)) * u;
                ASSERT_GT(u, 0.0) << "every pixel sees the lit ceiling";
                EXPECT_GE(w, lo * (1.0 - slack)) << x << "," << y << " channel " << c;
                EXPECT_LE(w, hi * (1.0 + slack)) << x << "," << y << " channel " << c;
                worst = std::max(worst, std::abs(w / (f0[c] * u) - 1.0));
                directMax = std::max(directMax, double(direct.pixel(x, y)[c]));
            }
    std::printf("[ measured ] whitted / (F0 x direct unfolded) - 1: at most %.2e; direct's mirror: at most %g\n", worst,
                directMax);
    EXPECT_EQ(directMax, 0.0);
}

TEST(Whitted, SmoothGlassSphereVanishesInAWhiteFurnace) {
    // A smooth, untinted glass sphere under a dome of radiance 1: every chain of reflections and
    // refractions ends in the dome with its weight, so `whitted` reads 1 (L S+ E). `direct` follows
    // one delta lobe only: the refracted ray ends inside the glass, and it reads far less.
    render::SceneDescription s = test::furnaceScene(1.0f);
    s.materials[0] = smoothGlass();
    s.meshes[0] = roundSphere(1.0f, Vec3f(0.0f), 0);
    const test_support::Rendered whitted = renderWith(Whitted(IntegratorSettings{}), s, 32, 16, 0, 1);
    const test_support::Rendered direct = renderWith(DirectLighting(IntegratorSettings{}), s, 32, 16, 0, 1);
    const int a = whitted.image.channelIndex("A");
    for (int c = 0; c < 3; ++c) {
        auto onSphere = [&](const float* p) { return p[a] == 1.0f; };
        const test::MeanEstimate w = test_support::channelMean(whitted.image, c, onSphere);
        const test::MeanEstimate d = test_support::channelMean(direct.image, c, onSphere);
        std::printf("[ measured ] channel %d: whitted %.5f +- %.5f, direct %.5f +- %.5f over %d pixels\n", c, w.mean(),
                    w.standardError(), d.mean(), d.standardError(), w.count());
        ASSERT_GT(w.count(), 200);
        EXPECT_NEAR(w.mean(), 1.0, kTwoSidedZ * w.standardError() + 1e-6) << "channel " << c;
        EXPECT_LT(d.mean(), 1.0 - kOneSidedZ * d.standardError()) << "channel " << c;
    }
}

TEST(Whitted, MissesTheCausticUnderAGlassSphere) {
    // A glass ball on a diffuse floor under a sphere light, nothing else, all grey: every path to
    // the floor that `whitted` lacks passes through or off the glass (LS+DE; the floor is flat, so
    // it cannot light itself). `whitted` sees the ball's umbra black in every sample; `path` sees
    // the caustic there, and over the whole floor it is brighter by that light.
    render::SceneDescription s;
    s.materials.push_back(test::diffuseMaterial("/floor", RGB(0.5f)));
    s.materials.push_back(smoothGlass());
    s.meshes.push_back(test::quadMesh("/floor", {{{-5, -5, 0}, {5, -5, 0}, {5, 5, 0}, {-5, 5, 0}}}, 0));
    s.meshes.push_back(roundSphere(0.5f, {0.0f, 0.0f, 0.5f}, 1));
    s.lights.push_back(test::sphereLight("/bulb", 1.0f, RGB(20.0f), {0, 0, 4}));
    s.camera = test::lookAtOriginCamera(1.0f);
    s.camera->transform = Matrix4::translate({0, -2.6f, 1.5f}) * Matrix4::rotateX(60);  // 30 degrees down
    const Image whitted = renderWith(Whitted(IntegratorSettings{}), s, 48, 16, 0, 1).image;
    const Image path = renderWith(PathTracer(IntegratorSettings{}), s, 48, 128, 0, 2).image;
    const Image pathAgain = renderWith(PathTracer(IntegratorSettings{}), s, 48, 128, 0, 3).image;
    const int albedo = whitted.channelIndex("albedo.R");
    auto onFloor = [&](int x, int y) { return whitted.pixel(x, y)[albedo] == 0.5f; };  // the glass's albedo is 0
    // In the umbra: the mean of the two `path` renders, whose noise variance per pixel (a - b)^2 / 4
    // is unbiased whatever the caustic's shape (pixels differ in expected value, not in the
    // difference of two renders).
    double umbraSum = 0.0, umbraNoise = 0.0;
    int umbraPixels = 0;
    for (int y = 0; y < 48; ++y)
        for (int x = 0; x < 48; ++x)
            if (onFloor(x, y) && whitted.pixel(x, y)[0] == 0.0f) {
                const double a = path.pixel(x, y)[0], b = pathAgain.pixel(x, y)[0];
                umbraSum += 0.5 * (a + b);
                umbraNoise += 0.25 * (a - b) * (a - b);
                ++umbraPixels;
            }
    const double umbraMean = umbraSum / umbraPixels, umbraError = std::sqrt(umbraNoise) / umbraPixels;
    const test::MeanEstimate floor = meanDifference(path, whitted, 0, onFloor);
    std::printf(
        "[ measured ] path in whitted's umbra %.4f +- %.4f over %d pixels; "
        "path - whitted on the floor %.4f +- %.4f over %d\n",
        umbraMean, umbraError, umbraPixels, floor.mean(), floor.standardError(), floor.count());
    ASSERT_GT(umbraPixels, 20);
    EXPECT_GT(umbraMean, kOneSidedZ * umbraError);
    EXPECT_GT(floor.mean(), kOneSidedZ * floor.standardError());
}

TEST(Whitted, AbsorbingGlassCubeMatchesItsInternalReflections) {
    // Seen head-on, a smooth glass cube of side L (F = ((n - 1) / (n + 1))^2 at normal incidence)
    // whose interior absorbs sigmaA, in a sky of radiance 1: with a = exp(-sigmaA L), the ray's
    // chains between the front and back faces give test_support::glassSlabSeenHeadOn(F, a), all of
    // it L S+ E, with every segment inside attenuated by ratio tracking.
    const RGB sigmaA(0.2f, 0.5f, 1.0f);
    const float side = 2.0f, F = 0.04f;
    render::SceneDescription s = test::furnaceScene(1.0f);
    s.materials[0] = smoothGlass();
    s.materials[0].interior = media::MediumProperties{sigmaA, RGB(0.0f)};
    s.meshes[0] = test::boxMesh(Vec3f(side / 2.0f), 0);
    const render::RenderScene scene(s);
    const render::Ray ray{{0.1f, -5.0f, 0.2f}, {0.0f, 1.0f, 0.0f}};
    const std::array<test::MeanEstimate, 3> e =
        test_support::radianceAlong(Whitted{IntegratorSettings{}}, scene, ray, 50000, 11);
    for (int c = 0; c < 3; ++c) {
        const double expected = test_support::glassSlabSeenHeadOn(F, std::exp(-sigmaA[c] * side));
        std::printf("[ measured ] channel %d: %.5f +- %.5f (expected %.5f)\n", c, e[c].mean(), e[c].standardError(),
                    expected);
        EXPECT_NEAR(e[c].mean(), expected, kTwoSidedZ * e[c].standardError()) << "channel " << c;
    }
}

TEST(Whitted, ShadowRaysInsideAnAbsorbingInteriorAreAttenuated) {
    // A diffuse plate and a point light 0.5 above it, both inside a closed smooth glass box whose
    // interior absorbs sigmaA, seen straight down through the box's top, 1.5 above the plate. The
    // camera ray inside and the shadow ray cross 2 units of the medium in all: the radiance is
    // exp(-2 sigmaA) times that of the same box with a clear interior (the Fresnel choices at the
    // top, the only noise, are the same in both).
    const RGB sigmaA(0.1f, 0.4f, 0.9f);
    auto radiance = [&](const RGB& absorption) {
        render::SceneDescription s;
        s.materials.push_back(smoothGlass());
        s.materials[0].interior = media::MediumProperties{absorption, RGB(0.0f)};
        s.materials.push_back(test::diffuseMaterial("/plate", RGB(0.6f)));
        s.meshes.push_back(test::boxMesh(Vec3f(1.0f), 0));
        const float h = -0.5f;
        s.meshes.push_back(
            test::quadMesh("/plate", {{{-0.8f, -0.8f, h}, {0.8f, -0.8f, h}, {0.8f, 0.8f, h}, {-0.8f, 0.8f, h}}}, 1));
        s.lights.push_back(test::pointLight("/point", RGB(20.0f), {0.0, 0.0, 0.0}));
        s.camera = lookingDown(5.0f);
        const render::RenderScene scene(s);
        const render::Ray ray{{0.0f, 0.0f, 5.0f}, {0.0f, 0.0f, -1.0f}};
        return test_support::radianceAlong(Whitted{IntegratorSettings{}}, scene, ray, 20000, 13);
    };
    const std::array<test::MeanEstimate, 3> clear = radiance(RGB(0.0f)), absorbing = radiance(sigmaA);
    for (int c = 0; c < 3; ++c) {
        const double t = std::exp(-2.0 * sigmaA[c]), expected = clear[c].mean() * t;
        const double error = std::hypot(absorbing[c].standardError(), clear[c].standardError() * t);
        std::printf("[ measured ] channel %d: %.5f +- %.5f, clear x exp(-2 sigmaA) %.5f\n", c, absorbing[c].mean(),
                    absorbing[c].standardError(), expected);
        ASSERT_GT(clear[c].mean(), 0.0);
        EXPECT_NEAR(absorbing[c].mean(), expected, kTwoSidedZ * error) << "channel " << c;
    }
}

TEST(DirectLighting, RegistryEntriesOfBothDeclareTheirPathClasses) {
    const IntegratorInfo* direct = findIntegrator("direct");
    const IntegratorInfo* whitted = findIntegrator("whitted");
    ASSERT_TRUE(direct && whitted);
    EXPECT_EQ(direct->covers, unsigned(kEmitterSeen | kDirect | kDeltaLights));
    EXPECT_EQ(whitted->covers, direct->covers | kSpecularSeen);
    EXPECT_EQ(whitted->pathClasses, "LD?S*E");
}

}  // namespace
}  // namespace fluence::integrators
