// Materials driven by textures and primvars, through RenderScene::intersect: which texel a hit
// sees, the tangent frame, normal maps, cut-outs and partial opacity, primvar readers, missing
// files, and the pixel footprint's filtering.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include "render/camera.h"
#include "render/render_scene.h"
#include "tests/support/scenes.h"
#include "tests/support/temp_dir.h"
#include "tests/texture/image_writer.h"

namespace fluence::render {
namespace {

// The unit square in z = 0 (normal +Z) with st = (x, y), or st = (1 - x, y) when `mirrored`.
MeshDesc unitSquare(int material, bool mirrored = false) {
    MeshDesc m = test::quadMesh("/square", {Vec3f(0, 0, 0), Vec3f(1, 0, 0), Vec3f(1, 1, 0), Vec3f(0, 1, 0)}, material);
    CornerPrimvar st{"st", 2, {}};
    for (std::uint32_t i : m.indices) {
        const Vec3f& p = m.positions[i];
        st.values.insert(st.values.end(), {mirrored ? 1.0f - p.x : p.x, p.y});
    }
    m.primvars.push_back(st);
    return m;
}

InputBinding textureBinding(MaterialInput input, const std::string& file, int first = 0, int channels = 3) {
    InputBinding b;
    b.input = input;
    b.firstChannel = first;
    b.channels = channels;
    b.texture.emplace().file = file;
    return b;
}

std::optional<SurfaceHit> hitFromAbove(const RenderScene& scene, float x, float y) {
    return scene.intersect(Ray{{x, y, 1.0f}, {0.0f, 0.0f, -1.0f}});
}

class TexturedSurface : public ::testing::Test {
protected:
    // Top-left red, top-right green, bottom-left blue, bottom-right white (linear floats).
    std::string quadrants() {
        std::string path = dir.file("quadrants.exr");
        test::writeImage<float>(path, 2, 2, 3, OIIO::TypeDesc::FLOAT, {1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1});
        return path;
    }
    // One RGBA texel of the given value.
    std::string constant(const std::string& name, std::vector<float> rgba) {
        std::string path = dir.file(name + ".exr");
        test::writeImage<float>(path, 1, 1, 4, OIIO::TypeDesc::FLOAT, rgba);
        return path;
    }
    SceneDescription withMaterial(const MaterialDesc& m, bool mirrored = false) {
        SceneDescription s;
        s.materials.push_back(m);
        s.meshes.push_back(unitSquare(0, mirrored));
        return s;
    }
    test::TempDir dir;
};

TEST_F(TexturedSurface, HitsSeeTheTexelAtTheirSt) {
    MaterialDesc m = test::diffuseMaterial("/m", RGB(0.5f));
    m.bindings.push_back(textureBinding(MaterialInput::Diffuse, quadrants()));
    RenderScene scene(withMaterial(m));
    EXPECT_EQ(hitFromAbove(scene, 0.25f, 0.75f)->material.diffuse, RGB(1, 0, 0));
    EXPECT_EQ(hitFromAbove(scene, 0.75f, 0.75f)->material.diffuse, RGB(0, 1, 0));
    EXPECT_EQ(hitFromAbove(scene, 0.25f, 0.25f)->material.diffuse, RGB(0, 0, 1));
    EXPECT_EQ(hitFromAbove(scene, 0.75f, 0.25f)->material.diffuse, RGB(1, 1, 1));
    EXPECT_TRUE(scene.warnings().empty());
}

TEST_F(TexturedSurface, ScaleBiasChannelsAndTransform) {
    MaterialDesc m = test::diffuseMaterial("/m", RGB(0.5f));
    InputBinding green = textureBinding(MaterialInput::Roughness, quadrants(), 1, 1);  // outputs:g
    green.texture->scale[1] = 0.5f;
    green.texture->bias[1] = 0.25f;
    green.texture->uvTransform.scale[0] = 2.0f;  // st' = (2s, t): the texture repeats twice across
    m.bindings.push_back(green);
    RenderScene scene(withMaterial(m));
    EXPECT_FLOAT_EQ(hitFromAbove(scene, 0.125f, 0.75f)->material.roughness, 0.25f) << "red texel: g = 0";
    EXPECT_FLOAT_EQ(hitFromAbove(scene, 0.375f, 0.75f)->material.roughness, 0.75f) << "green texel: g = 1";
    EXPECT_FLOAT_EQ(hitFromAbove(scene, 0.625f, 0.75f)->material.roughness, 0.25f) << "repeated";
}

TEST_F(TexturedSurface, TangentFollowsS) {
    MaterialDesc m = test::diffuseMaterial("/m", RGB(0.5f));
    m.bindings.push_back(textureBinding(MaterialInput::Diffuse, quadrants()));
    RenderScene plain(withMaterial(m)), mirrored(withMaterial(m, true));
    Vec3f t = hitFromAbove(plain, 0.3f, 0.6f)->tangent;
    EXPECT_NEAR(t.x, 1.0f, 1e-5f);
    EXPECT_NEAR(t.y, 0.0f, 1e-5f);
    EXPECT_NEAR(hitFromAbove(mirrored, 0.3f, 0.6f)->tangent.x, -1.0f, 1e-5f);
}

TEST_F(TexturedSurface, NormalMapsTiltTheShadingNormalInTheTangentFrame) {
    // Stored (n + 1) / 2 for the tangent-space normal n = (sin 30deg, 0, cos 30deg), read back with
    // scale 2 and bias -1 as UsdPreviewSurface files do.
    const float s = 0.5f, c = std::sqrt(3.0f) / 2.0f;
    MaterialDesc m = test::diffuseMaterial("/m", RGB(0.5f));
    InputBinding normal =
        textureBinding(MaterialInput::Normal, constant("normal", {(s + 1) / 2, 0.5f, (c + 1) / 2, 1}));
    normal.texture->colorSpace = texture::SourceColorSpace::Raw;
    for (int i = 0; i < 3; ++i) {
        normal.texture->scale[i] = 2.0f;
        normal.texture->bias[i] = -1.0f;
    }
    m.bindings.push_back(normal);
    for (bool mirrored : {false, true}) {
        RenderScene scene(withMaterial(m, mirrored));
        SurfaceHit hit = *hitFromAbove(scene, 0.4f, 0.4f);
        EXPECT_NEAR(hit.shadingNormal.x, mirrored ? -s : s, 1e-4f) << "x follows dp/ds";
        EXPECT_NEAR(hit.shadingNormal.y, 0.0f, 1e-4f);
        EXPECT_NEAR(hit.shadingNormal.z, c, 1e-4f);
        EXPECT_NEAR(hit.geometricNormal.z, 1.0f, 1e-6f);
        EXPECT_NEAR(dot(hit.tangent, hit.shadingNormal), 0.0f, 1e-5f);
    }
}

TEST_F(TexturedSurface, CutOutsLetEveryRayThroughTheirHoles) {
    // Alpha 0 on the left half, 1 on the right; a floor below catches what passes.
    std::string path = dir.file("mask.exr");
    test::writeImage<float>(path, 2, 1, 4, OIIO::TypeDesc::FLOAT, {1, 1, 1, 0, 1, 1, 1, 1});
    MaterialDesc m = test::diffuseMaterial("/m", RGB(0.5f));
    m.opacityThreshold = 0.5f;
    m.bindings.push_back(textureBinding(MaterialInput::Opacity, path, 3, 1));
    SceneDescription desc = withMaterial(m);
    desc.meshes.push_back(
        test::quadMesh("/floor", {Vec3f(-5, -5, -1), Vec3f(5, -5, -1), Vec3f(5, 5, -1), Vec3f(-5, 5, -1)}, -1));
    RenderScene scene(desc);
    for (float y : {0.1f, 0.5f, 0.9f}) {
        EXPECT_NEAR(hitFromAbove(scene, 0.2f, y)->point.z, -1.0f, 1e-5f) << "through the hole";
        EXPECT_NEAR(hitFromAbove(scene, 0.8f, y)->point.z, 0.0f, 1e-5f) << "stopped by the surface";
        EXPECT_FALSE(scene.occluded({0.2f, y, 1.0f}, {0, 0, -1}, 1.5f)) << "shadow rays pass the hole too";
        EXPECT_TRUE(scene.occluded({0.8f, y, 1.0f}, {0, 0, -1}, 1.5f));
    }
}

TEST_F(TexturedSurface, PartialOpacityStopsThatFractionOfRaysDeterministically) {
    MaterialDesc m = test::diffuseMaterial("/m", RGB(0.5f));
    m.opacity = 0.3f;
    RenderScene scene(withMaterial(m));
    const int n = 4000;
    int stopped = 0, shadowed = 0;
    for (int i = 0; i < n; ++i) {
        float x = (i % 64 + 0.5f) / 64.0f, y = (i / 64 + 0.5f) / 64.0f;
        std::optional<SurfaceHit> hit = hitFromAbove(scene, x, y);
        stopped += hit.has_value();
        EXPECT_EQ(hit.has_value(), hitFromAbove(scene, x, y).has_value()) << "the same ray decides the same way";
        shadowed += scene.occluded({x, y, 1.0f}, {0, 0, -1}, 2.0f);
    }
    // Binomial: 4 standard errors of the fraction.
    const double tolerance = 4.0 * std::sqrt(0.3 * 0.7 / n);
    EXPECT_NEAR(double(stopped) / n, 0.3, tolerance);
    EXPECT_NEAR(double(shadowed) / n, 0.3, tolerance);
}

TEST_F(TexturedSurface, PrimvarReadersInterpolateCorners) {
    MaterialDesc m = test::diffuseMaterial("/m", RGB(0.5f));
    InputBinding tint;
    tint.input = MaterialInput::Diffuse;
    tint.primvar = "tint";
    m.bindings.push_back(tint);
    SceneDescription desc = withMaterial(m);
    CornerPrimvar values{"tint", 3, {}};
    for (std::uint32_t i : desc.meshes[0].indices)
        values.values.insert(values.values.end(), {desc.meshes[0].positions[i].x, 0.0f, 1.0f});
    desc.meshes[0].primvars.push_back(values);
    RenderScene scene(desc);
    RGB d = hitFromAbove(scene, 0.3f, 0.6f)->material.diffuse;
    EXPECT_NEAR(d.x, 0.3f, 1e-5f);
    EXPECT_NEAR(d.z, 1.0f, 1e-5f);

    m.bindings[0].primvar = "absent";
    m.bindings[0].primvarFallback[1] = 0.7f;
    RenderScene fallback(withMaterial(m));
    EXPECT_EQ(hitFromAbove(fallback, 0.3f, 0.6f)->material.diffuse, RGB(0.0f, 0.7f, 0.0f));
}

TEST_F(TexturedSurface, UnreadableTexturesWarnAndUseTheirFallback) {
    MaterialDesc m = test::diffuseMaterial("/m", RGB(0.5f));
    InputBinding b = textureBinding(MaterialInput::Diffuse, dir.file("nowhere.png"));
    b.texture->fallback[0] = 0.2f;
    m.bindings.push_back(b);
    RenderScene scene(withMaterial(m));
    ASSERT_EQ(scene.warnings().size(), 1u);
    EXPECT_EQ(scene.warnings()[0].where, "/m");
    EXPECT_NE(scene.warnings()[0].message.find("nowhere.png"), std::string::npos);
    EXPECT_EQ(hitFromAbove(scene, 0.5f, 0.5f)->material.diffuse, RGB(0.2f, 0.0f, 0.0f));
}

TEST_F(TexturedSurface, TheCamerasPixelFootprintFiltersDistantTextures) {
    // A 256x256 one-texel checkerboard seen from far away covers a few pixels: each pixel spans
    // dozens of texels, so the filtered value is their mean; without a camera, one texel.
    const int n = 256;
    std::string path = dir.file("checker.exr");
    test::writeTexelChecker(path, n);
    MaterialDesc m = test::diffuseMaterial("/m", RGB(0.5f));
    m.bindings.push_back(textureBinding(MaterialInput::Diffuse, path));
    RenderScene scene(withMaterial(m));
    const float x = (100 + 0.5f) / n, y = (100 + 0.5f) / n;
    EXPECT_EQ(hitFromAbove(scene, x, y)->material.diffuse.x, 1.0f) << "point-sampled: texel (100, 155)";
    CameraDesc far;
    far.transform = Matrix4::translate(Vec3d(0.5, 0.5, 50.0));
    scene.setTextureFilterCamera(Camera(far, 64, 64));
    EXPECT_NEAR(hitFromAbove(scene, x, y)->material.diffuse.x, 0.5f, 0.05f);
}

}  // namespace
}  // namespace fluence::render
