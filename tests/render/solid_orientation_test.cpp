// render/solid_orientation.h: which meshes are closed, their signed volume, and turning an
// inward-wound closed mesh outward with its per-corner data.
#include "render/solid_orientation.h"

#include <gtest/gtest.h>

#include <utility>

#include "tests/support/scenes.h"

namespace fluence::render {
namespace {

void reverseEachTriangle(MeshDesc& m) {
    for (std::size_t c = 0; c + 2 < m.indices.size(); c += 3) std::swap(m.indices[c + 1], m.indices[c + 2]);
}

TEST(SolidOrientation, ABoxIsClosedAndAQuadIsNot) {
    const MeshDesc box = test::boxMesh(Vec3f(1.0f), 0);  // each face has its own four points
    EXPECT_TRUE(isClosed(box.positions, box.indices));
    const MeshDesc quad = test::quadMesh("/Quad", {Vec3f(0, 0, 0), Vec3f(1, 0, 0), Vec3f(1, 1, 0), Vec3f(0, 1, 0)}, 0);
    EXPECT_FALSE(isClosed(quad.positions, quad.indices));
    MeshDesc open = box;
    open.indices.resize(open.indices.size() - 6);  // one face missing
    EXPECT_FALSE(isClosed(open.positions, open.indices));
}

TEST(SolidOrientation, ASphereWhosePolesAndSeamAreComputedTwiceIsClosed) {
    // sphereMesh computes its seam and pole points once per segment: they differ in their last bits.
    const MeshDesc sphere = test::sphereMesh(1.0f, 24, 12, 0);
    EXPECT_TRUE(isClosed(sphere.positions, sphere.indices));
}

TEST(SolidOrientation, TrianglesWithTwoCornersAtOnePointDoNotOpenAMesh) {
    // As the triangulated quads at a UV sphere's poles give: one half of each quad is degenerate.
    MeshDesc box = test::boxMesh(Vec3f(1.0f), 0);
    box.positions.push_back(box.positions[0]);  // a second point where the first is
    const auto twin = static_cast<std::uint32_t>(box.positions.size() - 1);
    box.indices.insert(box.indices.end(), {0u, twin, 1u, 2u, 2u, 3u});
    EXPECT_TRUE(isClosed(box.positions, box.indices));
}

TEST(SolidOrientation, SignedVolumeIsPositiveWoundOutwardAndNegativeWoundInward) {
    MeshDesc box = test::boxMesh(Vec3f(1.0f, 2.0f, 0.5f), 0);
    EXPECT_NEAR(signedVolume(box.positions, box.indices), 8.0, 1e-9);
    reverseEachTriangle(box);
    EXPECT_NEAR(signedVolume(box.positions, box.indices), -8.0, 1e-9);
}

TEST(SolidOrientation, AnInwardWoundMeshIsTurnedBackWithItsCornerData) {
    MeshDesc outward = test::roundSphereMesh(1.0f, 16, 8, 0);
    outward.cornerColors.resize(outward.indices.size());
    outward.primvars.push_back({"st", 2, {}});
    for (std::size_t c = 0; c < outward.indices.size(); ++c) {
        outward.cornerColors[c] = RGB(float(c));
        outward.primvars[0].values.insert(outward.primvars[0].values.end(), {float(c), -float(c)});
    }
    // Its inside-out twin: every triangle, its corner data and its shading normals reversed.
    MeshDesc inward = outward;
    for (std::size_t c = 0; c + 2 < inward.indices.size(); c += 3) {
        std::swap(inward.indices[c + 1], inward.indices[c + 2]);
        std::swap(inward.cornerNormals[c + 1], inward.cornerNormals[c + 2]);
        std::swap(inward.cornerColors[c + 1], inward.cornerColors[c + 2]);
        std::vector<float>& st = inward.primvars[0].values;
        std::swap_ranges(st.begin() + std::ptrdiff_t(2 * (c + 1)), st.begin() + std::ptrdiff_t(2 * (c + 2)),
                         st.begin() + std::ptrdiff_t(2 * (c + 2)));
    }
    for (Vec3f& n : inward.cornerNormals) n = -n;

    ASSERT_TRUE(orientClosedMeshOutward(inward.positions,
                                        {inward.indices, inward.cornerNormals, inward.cornerColors, inward.primvars}));
    EXPECT_EQ(inward.indices, outward.indices);
    EXPECT_EQ(inward.cornerColors, outward.cornerColors);
    EXPECT_EQ(inward.primvars[0].values, outward.primvars[0].values);
    for (std::size_t c = 0; c < outward.cornerNormals.size(); ++c)
        ASSERT_EQ(inward.cornerNormals[c], outward.cornerNormals[c]) << "corner " << c;

    MeshDesc untouched = outward;  // already outward: nothing changes
    ASSERT_TRUE(orientClosedMeshOutward(
        untouched.positions, {untouched.indices, untouched.cornerNormals, untouched.cornerColors, untouched.primvars}));
    EXPECT_EQ(untouched.indices, outward.indices);
}

TEST(SolidOrientation, AnOpenMeshIsLeftAsItIs) {
    MeshDesc quad = test::quadMesh("/Quad", {Vec3f(0, 0, 0), Vec3f(0, 1, 0), Vec3f(1, 1, 0), Vec3f(1, 0, 0)}, 0);
    const std::vector<std::uint32_t> before = quad.indices;
    EXPECT_FALSE(
        orientClosedMeshOutward(quad.positions, {quad.indices, quad.cornerNormals, quad.cornerColors, quad.primvars}));
    EXPECT_EQ(quad.indices, before);
}

TEST(SolidOrientation, SolidsAreGlassSubsurfaceOrInteriorMediaThatAreNotThinWalled) {
    MaterialDesc m;
    EXPECT_FALSE(fillsItsInside(m));
    m.transmission = 1.0f;
    EXPECT_TRUE(fillsItsInside(m));
    m.thinWalled = true;
    EXPECT_FALSE(fillsItsInside(m));
    MaterialDesc skin;
    skin.subsurface = 0.5f;
    EXPECT_TRUE(fillsItsInside(skin));
    MaterialDesc murky;
    murky.interior = media::MediumProperties{RGB(1.0f), RGB(0.0f)};
    EXPECT_TRUE(fillsItsInside(murky));
}

}  // namespace
}  // namespace fluence::render
