// Robust interiors (render/solid_orientation.h): a closed mesh wound inward, or mirrored by a
// transform with a negative determinant, renders as its outward-wound twin, with subsurface, with
// glass and with an interior medium; a subsurface mesh that is not closed is named in a warning.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <utility>

#include "integrators/path_tracer.h"
#include "tests/integrators/render_support.h"
#include "tests/support/chi2.h"
#include "tests/support/scenes.h"
#include "tests/support/subsurface_material.h"

namespace fluence::integrators {
namespace {

render::MaterialDesc subsurfaceMaterial() {
    return test::subsurfaceMaterial("/Skin", RGB(0.8f, 0.4f, 0.2f), RGB(0.2f, 0.1f, 0.05f));
}

render::MaterialDesc tintedGlassMaterial() {
    render::MaterialDesc m = test::glassMaterial("/Glass", 0.0f);
    m.interior = media::MediumProperties{RGB(0.2f, 0.6f, 1.2f), RGB(0.3f)};
    return m;
}

// The mesh under a dim sky with a bright sphere light to one side, so that light entering from
// the wrong side shows.
render::SceneDescription litFromTheSide(render::MeshDesc mesh, render::MaterialDesc material) {
    render::SceneDescription s;
    s.materials.push_back(std::move(material));
    mesh.material = 0;
    s.meshes.push_back(std::move(mesh));
    s.lights.push_back(test::domeLight("/Sky", RGB(0.2f)));
    s.lights.push_back(test::sphereLight("/Lamp", 0.5f, RGB(20.0f), Vec3d(3.0, -2.0, 2.0)));
    s.camera = test::lookAtOriginCamera(4.0f);
    return s;
}

Image rendered(const render::SceneDescription& scene) {
    return test_support::renderWith(PathTracer(IntegratorSettings{}), scene, 24, 16).image;
}

// Every triangle's second and third corners swapped, with their normals.
render::MeshDesc woundInward(render::MeshDesc m) {
    for (std::size_t c = 0; c + 2 < m.indices.size(); c += 3) {
        std::swap(m.indices[c + 1], m.indices[c + 2]);
        if (!m.cornerNormals.empty()) std::swap(m.cornerNormals[c + 1], m.cornerNormals[c + 2]);
    }
    return m;
}

// Wound inward, its shading normals pointing inward too: the whole mesh inside out.
render::MeshDesc insideOut(render::MeshDesc m) {
    m = woundInward(std::move(m));
    for (Vec3f& n : m.cornerNormals) n = -n;
    return m;
}

// Mirrored in x as the delegate bakes a scale (-1, 1, 1) into world-space points: the points
// move, the triangles keep their corners, so the winding turns inward.
render::MeshDesc mirroredInX(render::MeshDesc m) {
    for (Vec3f& p : m.positions) p.x = -p.x;
    for (Vec3f& n : m.cornerNormals) n.x = -n.x;
    return m;
}

void expectSameImage(const render::MeshDesc& outward, const render::MeshDesc& other,
                     const render::MaterialDesc& material, const char* what) {
    const Image a = rendered(litFromTheSide(outward, material));
    const Image b = rendered(litFromTheSide(other, material));
    const int alpha = a.channelIndex("A");
    int covered = 0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) covered += a.pixel(x, y)[alpha] == 1.0f;
    ASSERT_GT(covered, 50) << what << ": the object fills part of the image";
    ASSERT_EQ(a.pixels.size(), b.pixels.size());
    std::size_t differing = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) differing += a.pixels[i] != b.pixels[i];
    EXPECT_EQ(differing, 0u) << what << ": " << differing << " of " << a.pixels.size() << " values differ";
}

TEST(Winding, InsideOutSubsurfaceSphereRendersAsItsOutwardTwin) {
    const render::MeshDesc sphere = test::roundSphereMesh(1.0f, 32, 16, 0);
    expectSameImage(sphere, insideOut(sphere), subsurfaceMaterial(), "inside-out subsurface sphere");
    expectSameImage(sphere, woundInward(sphere), subsurfaceMaterial(), "inward-wound, outward normals");
}

TEST(Winding, InsideOutGlassSphereRendersAsItsOutwardTwin) {
    const render::MeshDesc sphere = test::roundSphereMesh(1.0f, 32, 16, 0);
    expectSameImage(sphere, insideOut(sphere), test::glassMaterial("/Glass", 0.2f), "inside-out glass sphere");
}

TEST(Winding, InwardWoundGlassCubeWithAnInteriorMediumRendersAsItsOutwardTwin) {
    const render::MeshDesc cube = test::boxMesh(Vec3f(0.8f), 0);
    expectSameImage(cube, woundInward(cube), tintedGlassMaterial(), "inward-wound tinted glass cube");
}

TEST(Winding, MirroredSubsurfaceSphereRendersAsItsOutwardTwin) {
    // The twin: the mirrored points with the winding a correct mirror gives (reversed).
    const render::MeshDesc mirrored = mirroredInX(test::roundSphereMesh(1.0f, 32, 16, 0));
    expectSameImage(woundInward(mirrored), mirrored, subsurfaceMaterial(), "mirrored subsurface sphere");
}

TEST(Winding, MirroredSubsurfaceInstanceMatchesTheUnmirroredMesh) {
    // A prototype placed by scale (-1, 1, 1): an asymmetric box (off the origin) mirrored, against
    // the same box authored at its mirrored place. Different triangles, same solid: equal means
    // per channel, within the renders' noise.
    render::MeshDesc box = test::boxMesh(Vec3f(0.4f, 0.5f, 0.6f), 0);
    for (Vec3f& p : box.positions) p += Vec3f(0.3f, 0.0f, 0.1f);
    render::SceneDescription instanced = litFromTheSide(box, subsurfaceMaterial());
    instanced.meshes.clear();
    instanced.prototypes.push_back({"/Proto", {box}});
    instanced.instances.push_back({0, Matrix4::scale({-1.0, 1.0, 1.0}), "/Mirrored"});
    render::MeshDesc placed = box;
    for (Vec3f& p : placed.positions) p.x = -p.x;
    const render::SceneDescription authored = litFromTheSide(woundInward(placed), subsurfaceMaterial());
    const Image a = test_support::renderWith(PathTracer(IntegratorSettings{}), instanced, 32, 64).image;
    const Image b = test_support::renderWith(PathTracer(IntegratorSettings{}), authored, 32, 64).image;
    const double z = test::normalQuantile(0.5 * test::sidakAlpha(3));
    for (int c = 0; c < 3; ++c) {
        const test::MeanEstimate ma = test_support::channelMean(a, c, [](const float*) { return true; });
        const test::MeanEstimate mb = test_support::channelMean(b, c, [](const float*) { return true; });
        std::printf("[ measured ] channel %d: instance %.5f +- %.5f, mesh %.5f +- %.5f\n", c, ma.mean(),
                    ma.standardError(), mb.mean(), mb.standardError());
        EXPECT_GT(ma.mean(), 0.05) << "lit, not black";
        EXPECT_NEAR(ma.mean(), mb.mean(), z * std::hypot(ma.standardError(), mb.standardError())) << "channel " << c;
    }
}

TEST(Winding, SubsurfaceOnAnOpenMeshWarnsOnceNamingIt) {
    render::SceneDescription open = litFromTheSide(
        test::quadMesh("/World/Sheet", {Vec3f(-1, 0, -1), Vec3f(1, 0, -1), Vec3f(1, 0, 1), Vec3f(-1, 0, 1)}, 0),
        subsurfaceMaterial());
    const render::RenderScene openScene(open);
    const auto count = std::count_if(openScene.warnings().begin(), openScene.warnings().end(),
                                     [](const render::Warning& w) { return w.where == "/World/Sheet"; });
    EXPECT_EQ(count, 1);
    const render::RenderScene closedScene(litFromTheSide(test::boxMesh(Vec3f(1.0f), 0), subsurfaceMaterial()));
    EXPECT_TRUE(closedScene.warnings().empty());
    const render::RenderScene glassSheet(litFromTheSide(
        test::quadMesh("/World/Pane", {Vec3f(-1, 0, -1), Vec3f(1, 0, -1), Vec3f(1, 0, 1), Vec3f(-1, 0, 1)}, 0),
        test::glassMaterial("/Glass", 0.0f)));
    EXPECT_TRUE(glassSheet.warnings().empty()) << "only subsurface needs a closed mesh to scatter in";
}

}  // namespace
}  // namespace fluence::integrators
