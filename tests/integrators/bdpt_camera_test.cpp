// bdpt's light tracing (t = 1) through a thin lens and from a moving camera (render/camera.h,
// "Importance"; integrators/bdpt.h): it agrees with `path` within their combined noise on the
// open box seen through a lens with depth of field and by a camera that moves and turns during the
// shutter, keeping t = 1 on (the summary says nothing is left out); and t = 1 alone reproduces a
// defocused diffuse plane: a point light under a mirror lights the plane only through the mirror
// (LSDE, which no other strategy draws from a delta light), and the image is `path`'s of the
// same plane lit by the light's mirror image with no mirror (which `path` renders by next-event
// estimation), the plane, the black blocker in front of it and the blocker's shadow all out of focus.
#include <gtest/gtest.h>

#include "integrators/bdpt.h"
#include "integrators/path_tracer.h"
#include "tests/integrators/bdpt_agreement.h"
#include "tests/integrators/render_support.h"
#include "tests/support/scenes.h"

namespace fluence::integrators {
namespace {

using namespace bdpt_agreement;

// Light tracing is on: bdpt's summary names nothing it left out.
void expectLightTracing(const render::SceneDescription& scene) {
    const Bdpt bdpt{IntegratorSettings{}};
    EXPECT_EQ(test_support::renderWith(bdpt, scene, 8, 1).stats.methodSummary, "");
}

// The box focused on its front edge (2.5 from the camera) at f/8: its back wall (4.5 away) is
// blurred by about 4 pixels.
render::SceneDescription defocusedBox() {
    render::SceneDescription s = cornellBox();
    s.camera->fStop = 8.0f;
    s.camera->focusDistance = 2.5f;
    s.camera->apertureBlades = 6;
    return s;
}

TEST(BdptThroughALens, AgreesWithPathOnADefocusedBox) {
    expectLightTracing(defocusedBox());
    expectAgreement(defocusedBox(), 256, 256);
}

// The box seen by a camera that slides and turns during the shutter.
render::SceneDescription boxFromAMovingCamera() {
    render::SceneDescription s = cornellBox();
    s.camera->motionTransforms = {s.camera->transform,
                                  Matrix4::translate({0.4, 0.3, 0.2}) * Matrix4::rotateZ(8.0) * s.camera->transform};
    return s;
}

TEST(BdptWithAMovingCamera, AgreesWithPath) {
    expectLightTracing(boxFromAMovingCamera());
    expectAgreement(boxFromAMovingCamera(), 256, 256);
}

// A plane (white for x < 0, grey beyond) at z = 0 seen from 3 above, focused at 1.5 through an
// aperture of radius 0.5 (f/5 at 50 mm): about 7 pixels of blur. A point light at z = 2 under a
// perfect mirror at z = 4 (its image at z = 6), a black blocker just under the light shadowing the
// whole plane from it directly. Paths hold at most two scattering vertices (the mirror, the plane).
// Without the mirror, the light is put at its image.
render::SceneDescription planeUnderAMirror(bool mirror) {
    render::SceneDescription s;
    s.materials.push_back(test::diffuseMaterial("/white", RGB(0.8f)));
    s.materials.push_back(test::diffuseMaterial("/grey", RGB(0.3f)));
    s.materials.push_back(test::diffuseMaterial("/black", RGB(0.0f)));
    s.materials.push_back(test::metalMaterial("/mirror", RGB(1.0f), 0.0f));
    s.meshes.push_back(
        test::quadMesh("/white", {{{-2.5f, -2.5f, 0}, {0, -2.5f, 0}, {0, 2.5f, 0}, {-2.5f, 2.5f, 0}}}, 0));
    s.meshes.push_back(test::quadMesh("/grey", {{{0, -2.5f, 0}, {2.5f, -2.5f, 0}, {2.5f, 2.5f, 0}, {0, 2.5f, 0}}}, 1));
    s.meshes.push_back(test::quadMesh(
        "/blocker", {{{-0.2f, -0.2f, 1.9f}, {0.2f, -0.2f, 1.9f}, {0.2f, 0.2f, 1.9f}, {-0.2f, 0.2f, 1.9f}}}, 2));
    if (mirror)
        s.meshes.push_back(
            test::quadMesh("/mirror", {{{-1.5f, -1.5f, 4}, {-1.5f, 1.5f, 4}, {1.5f, 1.5f, 4}, {1.5f, -1.5f, 4}}}, 3));
    s.lights.push_back(test::pointLight("/point", RGB(12000.0f), {0.0, 0.0, mirror ? 2.0 : 6.0}));
    render::CameraDesc camera;  // looking down -Z
    camera.focalLength = 50.0f;
    camera.horizontalAperture = camera.verticalAperture = 36.0f;
    camera.nearClip = 0.01f;
    camera.transform = Matrix4::translate({0.0, 0.0, 3.0});
    camera.fStop = 5.0f;
    camera.focusDistance = 1.5f;
    s.camera = camera;
    return s;
}

TEST(BdptThroughALens, LightTracingAloneReproducesADefocusedPlane) {
    const IntegratorSettings settings{.maxDepth = 2, .parameters = {}, .lightPathAovs = {}};
    expectLightTracing(planeUnderAMirror(true));
    const Estimates traced = estimates(Bdpt(settings), planeUnderAMirror(true), 256);
    const Estimates path = estimates(PathTracer(settings), planeUnderAMirror(false), 64);
    expectAgreement(traced, path);
    for (int c = 0; c < 3; ++c) EXPECT_GT(traced.imageMean[c], 0.1) << "channel " << c;
}

}  // namespace
}  // namespace fluence::integrators
