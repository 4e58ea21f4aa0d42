// A UsdLux mesh light (render::MeshLightDesc) seen by the camera: with every integrator, a camera
// ray that meets its surface sees the surface as its material shades it, not the light's radiance
// (RenderScene::intersect, render::Ray::fromCamera; docs/USDLUX.md), as Arnold (light_visible
// off), hdPrman and Storm show a mesh light.
#include <gtest/gtest.h>

#include "integrators/integrator.h"
#include "tests/integrators/render_support.h"
#include "tests/support/scenes.h"

namespace fluence::integrators {
namespace {

using test_support::channelMean;

constexpr float kAlbedo = 0.5f;
const RGB kRadiance(5.0f);

// A 2 x 2 quad in the plane y = 0 facing the camera at (0, -4, 0) (its front, the side of
// cross(p1 - p0, p2 - p0), is -Y), a mesh light of radiance kRadiance over a diffuse material.
render::SceneDescription meshLightFacingTheCamera() {
    render::SceneDescription s;
    s.materials.push_back(test::diffuseMaterial("/mat", RGB(kAlbedo)));
    render::MeshDesc quad =
        test::quadMesh("/L", {Vec3f(-1, 0, -1), Vec3f(1, 0, -1), Vec3f(1, 0, 1), Vec3f(-1, 0, 1)}, 0);
    quad.light = render::MeshLightDesc{.radiance = kRadiance, .prim = "/L"};
    s.meshes.push_back(std::move(quad));
    s.camera = test::lookAtOriginCamera(4.0f);
    return s;
}

// Covered pixels, and whether each of them reads `expected` exactly in every channel.
void expectCoveredPixelsRead(const Image& image, const RGB& expected, const char* name) {
    const int a = image.channelIndex("A");
    int covered = 0;
    for (std::size_t p = 0; p < image.pixels.size(); p += image.channels.size()) {
        if (image.pixels[p + std::size_t(a)] != 1.0f) continue;
        ++covered;
        for (int c : {0, 1, 2})
            EXPECT_EQ(image.pixels[p + std::size_t(c)], expected[c])
                << name << " at pixel " << p / image.channels.size();
    }
    EXPECT_GT(covered, 50) << name;
}

// Alone in the scene, nothing lights the quad (its light leaves its front, away from itself): every
// integrator shows it black where it covers a pixel whole, exactly; it showed kRadiance there before.
TEST(MeshLightCameraVisibility, EveryIntegratorShowsTheSurfaceNotTheLight) {
    const render::SceneDescription desc = meshLightFacingTheCamera();
    for (const IntegratorInfo& info : integratorRegistry()) {
        const std::unique_ptr<Integrator> integrator = info.create(IntegratorSettings{});
        expectCoveredPixelsRead(test_support::renderWith(*integrator, desc, 24, 4).image, RGB(0.0f), info.name.c_str());
    }
}

// Under a dome of radiance 1 hidden from the camera, the quad's front sees the dome over its whole
// hemisphere, so its Lambertian material reflects exactly kAlbedo towards the camera, and that is
// what the path tracer shows on it (not kRadiance + kAlbedo). The pixels are independent estimates:
// their mean is within five standard errors of kAlbedo but with probability below 1e-6.
TEST(MeshLightCameraVisibility, TheCameraSeesTheSurfaceAsItsMaterialShadesIt) {
    render::SceneDescription desc = meshLightFacingTheCamera();
    desc.lights.push_back(test::domeLight("/dome", RGB(1.0f)));
    desc.lights.back().visibleToCamera = false;
    const std::unique_ptr<Integrator> path = findIntegrator("path")->create(IntegratorSettings{});
    const Image image = test_support::renderWith(*path, desc, 24, 16).image;
    const int a = image.channelIndex("A");
    for (int c : {0, 1, 2}) {
        const test::MeanEstimate seen = channelMean(image, c, [&](const float* px) { return px[a] == 1.0f; });
        ASSERT_GT(seen.count(), 50);
        EXPECT_NEAR(seen.mean(), kAlbedo, 5.0 * seen.standardError() + 1e-6) << "channel " << c;
    }
}

// Under materialSyncMode noMaterialResponse there is no material to see: the camera sees the
// light's radiance itself, as it sees a canonical light, with every integrator.
TEST(MeshLightCameraVisibility, WithoutAMaterialResponseTheCameraSeesTheLight) {
    render::SceneDescription desc = meshLightFacingTheCamera();
    desc.meshes.back().light->materialResponse = false;
    for (const IntegratorInfo& info : integratorRegistry()) {
        const std::unique_ptr<Integrator> integrator = info.create(IntegratorSettings{});
        expectCoveredPixelsRead(test_support::renderWith(*integrator, desc, 24, 4).image, kRadiance, info.name.c_str());
    }
}

// A shaped mesh light of radiance 0 (an intensity faded to 0) has no triangle lights: where a ray
// sees its emission it reads black, not another light's (or no light's: index -1) emission.
TEST(MeshLightCameraVisibility, ABlackShapedMeshLightSeenByARayIsBlack) {
    render::SceneDescription desc = meshLightFacingTheCamera();
    desc.meshes.back().light->materialResponse = false;
    desc.meshes.back().light->radiance = RGB(0.0f);
    render::LightShapingDesc cone;
    cone.coneAngleDegrees = 60.0f;
    desc.meshes.back().light->shaping = cone;
    const std::unique_ptr<Integrator> path = findIntegrator("path")->create(IntegratorSettings{});
    expectCoveredPixelsRead(test_support::renderWith(*path, desc, 24, 4).image, RGB(0.0f), "path");
}

// Only the camera ray is hidden from a mesh light: a mirror facing the camera (metal of colour 1,
// roughness 0: a delta lobe, no light sample competes) shows a large mesh light behind the camera
// at its full radiance, exactly, in every covered pixel (the light's own material is black, so
// nothing bounces between the two). A bounce ray that kept the camera ray's flag would show it black.
TEST(MeshLightCameraVisibility, AMirrorShowsTheMeshLightBehindTheCamera) {
    render::SceneDescription s;
    s.materials.push_back(test::diffuseMaterial("/black", RGB(0.0f)));  // no light between mirror and light
    s.materials.push_back(test::metalMaterial("/mirror", RGB(1.0f), 0.0f));
    s.meshes.push_back(
        test::quadMesh("/Mirror", {Vec3f(-1, 0, -1), Vec3f(1, 0, -1), Vec3f(1, 0, 1), Vec3f(-1, 0, 1)}, 1));
    render::MeshDesc light = test::quadMesh(
        "/L", {Vec3f(-10, -6, -10), Vec3f(-10, -6, 10), Vec3f(10, -6, 10), Vec3f(10, -6, -10)}, 0);  // front +Y
    light.light = render::MeshLightDesc{.radiance = kRadiance, .prim = "/L"};
    s.meshes.push_back(std::move(light));
    s.camera = test::lookAtOriginCamera(4.0f);
    for (const char* name : {"path", "bdpt"}) {
        const std::unique_ptr<Integrator> integrator = findIntegrator(name)->create(IntegratorSettings{});
        expectCoveredPixelsRead(test_support::renderWith(*integrator, s, 24, 4).image, kRadiance, name);
    }
}

}  // namespace
}  // namespace fluence::integrators
