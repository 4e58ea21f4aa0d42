// A binding's shading graph (render::ShadingNode) evaluated by MaterialShader through
// RenderScene::intersect: multiply and mix of a texture, a primvar and constants at texel centres,
// opacity from a graph in the presence test, and malformed graphs refused naming the material.
#include <gtest/gtest.h>

#include "render/render_scene.h"
#include "tests/support/scenes.h"
#include "tests/support/temp_dir.h"
#include "tests/texture/image_writer.h"

namespace fluence::render {
namespace {

// The unit square in z = 0 with st = (x, y) and a one-component primvar "w" = x.
SceneDescription squareWith(const MaterialDesc& material) {
    SceneDescription s;
    s.materials.push_back(material);
    MeshDesc m = test::quadMesh("/square", {Vec3f(0, 0, 0), Vec3f(1, 0, 0), Vec3f(1, 1, 0), Vec3f(0, 1, 0)}, 0);
    CornerPrimvar st{"st", 2, {}}, w{"w", 1, {}};
    for (std::uint32_t i : m.indices) {
        st.values.insert(st.values.end(), {m.positions[i].x, m.positions[i].y});
        w.values.push_back(m.positions[i].x);
    }
    m.primvars = {st, w};
    s.meshes.push_back(m);
    return s;
}

ShadingNode constantNode(float r, float g, float b) {
    ShadingNode n;
    n.constant[0] = r, n.constant[1] = g, n.constant[2] = b;
    return n;
}

ShadingNode sourceNode(int source) {
    ShadingNode n;
    n.op = ShadingNode::Op::Source;
    n.source = source;
    return n;
}

ShadingNode opNode(ShadingNode::Op op, int a, int b, int c = -1) {
    ShadingNode n;
    n.op = op;
    n.operands[0] = a, n.operands[1] = b, n.operands[2] = c;
    return n;
}

void expectNear(const RGB& got, const RGB& expected) {
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], expected[c], 1e-6f) << "channel " << c;
}

class ShadingGraph : public ::testing::Test {
protected:
    // Top-left red, top-right green, bottom-left blue, bottom-right white.
    InputBinding quadrants() {
        const std::string path = dir.file("quadrants.exr");
        test::writeImage<float>(path, 2, 2, 3, OIIO::TypeDesc::FLOAT, {1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1});
        InputBinding b;
        b.texture.emplace().file = path;
        return b;
    }
    static InputBinding primvarW() {
        InputBinding b;
        b.primvar = "w";
        b.channels = 1;
        return b;
    }
    static MaterialParams at(const RenderScene& scene, float x, float y) {
        return scene.intersect(Ray{{x, y, 1.0f}, {0.0f, 0.0f, -1.0f}})->material;
    }
    test::TempDir dir;
};

TEST_F(ShadingGraph, MixOfATextureAndAConstantByAPrimvarTimesAConstant) {
    // diffuse = mix(fg = texture, bg = (0, 0, 0.5), mix = w * 0.5) * 2
    MaterialDesc m = test::diffuseMaterial("/m", RGB(0.5f));
    InputBinding b;
    b.input = MaterialInput::Diffuse;
    b.factor = 2.0f;
    b.sources = {quadrants(), primvarW()};
    b.nodes = {sourceNode(0),
               constantNode(0, 0, 0.5f),
               sourceNode(1),
               constantNode(0.5f, 0.5f, 0.5f),
               opNode(ShadingNode::Op::Multiply, 2, 3),
               opNode(ShadingNode::Op::Mix, 0, 1, 4)};
    m.bindings.push_back(b);
    RenderScene scene(squareWith(m));
    EXPECT_TRUE(scene.warnings().empty());
    // (0.25, 0.75): red, w = 0.25, mix 0.125.  (0.75, 0.25): white, w = 0.75, mix 0.375.
    // (w is interpolated across the triangle: to within rounding.)
    expectNear(at(scene, 0.25f, 0.75f).diffuse, (RGB(0, 0, 0.5f) * 0.875f + RGB(1, 0, 0) * 0.125f) * 2.0f);
    expectNear(at(scene, 0.75f, 0.25f).diffuse, (RGB(0, 0, 0.5f) * 0.625f + RGB(1, 1, 1) * 0.375f) * 2.0f);
    EXPECT_EQ(at(scene, 0.75f, 0.25f).roughness, m.roughness) << "other parameters keep their values";
}

TEST_F(ShadingGraph, OpacityFromAGraphCutsHoles) {
    // opacity = texture.r * w: zero over the left column's blue and the right column's green.
    MaterialDesc m = test::diffuseMaterial("/m", RGB(0.5f));
    m.opacityThreshold = 0.5f;
    InputBinding b;
    b.input = MaterialInput::Opacity;
    b.channels = 1;
    b.sources = {quadrants(), primvarW()};
    b.nodes = {sourceNode(0), sourceNode(1), opNode(ShadingNode::Op::Multiply, 0, 1)};
    m.bindings.push_back(b);
    RenderScene scene(squareWith(m));
    EXPECT_TRUE(scene.intersect(Ray{{0.75f, 0.25f, 1.0f}, {0.0f, 0.0f, -1.0f}})) << "white: 1 * 0.75";
    EXPECT_FALSE(scene.intersect(Ray{{0.25f, 0.75f, 1.0f}, {0.0f, 0.0f, -1.0f}})) << "red: 1 * 0.25";
    EXPECT_FALSE(scene.intersect(Ray{{0.75f, 0.75f, 1.0f}, {0.0f, 0.0f, -1.0f}})) << "green: 0 * 0.75";
}

TEST_F(ShadingGraph, MalformedGraphsAreRefusedNamingTheMaterial) {
    MaterialDesc m = test::diffuseMaterial("/Looks/Broken", RGB(0.5f));
    InputBinding b;
    b.sources = {primvarW()};
    b.nodes = {sourceNode(0), opNode(ShadingNode::Op::Multiply, 0, 1)};  // operand 1 is itself
    m.bindings = {b};
    try {
        RenderScene scene(squareWith(m));
        ADD_FAILURE() << "a node reading itself was accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("/Looks/Broken"), std::string::npos) << e.what();
    }
    m.bindings[0].nodes = {sourceNode(1)};  // no such source
    EXPECT_THROW(RenderScene scene(squareWith(m)), std::invalid_argument);
    m.bindings[0].nodes.assign(kMaxShadingNodes + 1, constantNode(1, 1, 1));
    EXPECT_THROW(RenderScene scene(squareWith(m)), std::invalid_argument);
}

}  // namespace
}  // namespace fluence::render
