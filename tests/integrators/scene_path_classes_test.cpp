// The path classes a scene can produce (integrators/scene_path_classes.h): one small scene per
// rule, with the scene that just falls short of it beside it.
#include "integrators/scene_path_classes.h"

#include <gtest/gtest.h>

#include "integrators/path_classes.h"
#include "tests/support/scenes.h"

namespace fluence::integrators {
namespace {

using render::LightType;
using render::MaterialDesc;
using render::SceneDescription;

render::MeshDesc floorQuad(int material) {
    return test::quadMesh("/Floor", {Vec3f(-1, -1, 0), Vec3f(1, -1, 0), Vec3f(1, 1, 0), Vec3f(-1, 1, 0)}, material);
}

render::LightDesc light(LightType type) {
    render::LightDesc l;
    l.name = "/Light";
    l.type = type;
    return l;
}

MaterialDesc mirror() {
    MaterialDesc m = test::diffuseMaterial("/Mirror", RGB(0.9f));
    m.metallic = 1.0f;
    m.roughness = 0.0f;
    return m;
}

MaterialDesc glass() {
    MaterialDesc m;
    m.name = "/Glass";
    m.transmission = 1.0f;
    m.roughness = 0.0f;
    return m;
}

// A diffuse floor lit by `lights`, with a sphere of `material` on it.
SceneDescription sphereOnFloor(const MaterialDesc& material, std::vector<render::LightDesc> lights) {
    SceneDescription s;
    s.materials = {test::diffuseMaterial("/White", RGB(0.8f)), material};
    s.meshes = {floorQuad(0), test::sphereMesh(0.5f, 16, 8, 1)};
    s.lights = std::move(lights);
    return s;
}

// The classes of a flat quad of `material` under a rect light.
unsigned quadUnderRectLight(const MaterialDesc& material) {
    SceneDescription s;
    s.materials = {material};
    s.meshes = {floorQuad(0)};
    s.lights = {light(LightType::Rect)};
    return scenePathClasses(s);
}

TEST(ScenePathClasses, AnEmptySceneHasNone) { EXPECT_EQ(scenePathClasses({}), 0u); }

TEST(ScenePathClasses, EmittersAreLightsAndEmissiveMaterials) {
    SceneDescription lightOnly;
    lightOnly.lights = {light(LightType::Dome)};
    EXPECT_EQ(scenePathClasses(lightOnly), unsigned(kEmitterSeen));

    SceneDescription glowingQuad;
    glowingQuad.materials = {test::diffuseMaterial("/Glow", RGB(0.0f), RGB(5.0f))};
    glowingQuad.meshes = {floorQuad(0)};
    EXPECT_EQ(scenePathClasses(glowingQuad), unsigned(kEmitterSeen | kDirect)) << "a black diffuse base still counts";
}

TEST(ScenePathClasses, ADiffuseFlatSurfaceIsLitDirectlyOnly) {
    EXPECT_EQ(quadUnderRectLight(test::diffuseMaterial("/White", RGB(0.8f))), unsigned(kEmitterSeen | kDirect));
    SceneDescription noMaterial;
    noMaterial.meshes = {floorQuad(-1)};
    EXPECT_EQ(scenePathClasses(noMaterial), unsigned(kDirect)) << "a mesh without a material is Lambertian";
}

TEST(ScenePathClasses, IndirectNeedsTwoSurfacesOrOneThatIsNotFlat) {
    SceneDescription s;
    s.materials = {test::diffuseMaterial("/White", RGB(0.8f))};
    s.meshes = {floorQuad(0)};
    EXPECT_FALSE(scenePathClasses(s) & kIndirect);
    s.meshes.push_back(test::quadMesh("/Wall", {Vec3f(-1, 1, 0), Vec3f(1, 1, 0), Vec3f(1, 1, 2), Vec3f(-1, 1, 2)}, 0));
    EXPECT_TRUE(scenePathClasses(s) & kIndirect) << "two surfaces";

    s.meshes = {test::boxMesh(Vec3f(1.0f), 0)};
    EXPECT_TRUE(scenePathClasses(s) & kIndirect) << "one box: its inside can light itself";

    s.meshes.clear();
    s.prototypes = {render::PrototypeDesc{"/Proto", {floorQuad(0)}}};
    s.instances = {render::InstanceDesc{}};
    EXPECT_FALSE(scenePathClasses(s) & kIndirect) << "one flat instance";
    s.instances.push_back(render::InstanceDesc{0, Matrix4::translate({0, 0, 1}), ""});
    EXPECT_TRUE(scenePathClasses(s) & kIndirect) << "two instances of it";
}

TEST(ScenePathClasses, SmoothLobesAreDeltaLobes) {
    EXPECT_EQ(quadUnderRectLight(mirror()), unsigned(kEmitterSeen | kSpecularSeen))
        << "a smooth metal has no other lobe";
    EXPECT_EQ(quadUnderRectLight(glass()), unsigned(kEmitterSeen | kSpecularSeen));

    MaterialDesc roughMetal = mirror();
    roughMetal.roughness = 0.5f;
    EXPECT_EQ(quadUnderRectLight(roughMetal), unsigned(kEmitterSeen | kDirect)) << "a rough lobe is glossy";

    MaterialDesc coated = test::diffuseMaterial("/Coated", RGB(0.5f));
    coated.coat = 1.0f;
    coated.coatRoughness = 0.01f;
    EXPECT_EQ(quadUnderRectLight(coated), unsigned(kEmitterSeen | kDirect | kSpecularSeen));

    MaterialDesc plastic = test::diffuseMaterial("/Plastic", RGB(0.5f));
    plastic.specular = 1.0f;
    plastic.roughness = 0.01f;
    EXPECT_EQ(quadUnderRectLight(plastic), unsigned(kEmitterSeen | kDirect | kSpecularSeen)) << "smooth specular layer";
    plastic.roughness = 0.2f;
    EXPECT_EQ(quadUnderRectLight(plastic), unsigned(kEmitterSeen | kDirect));

    render::InputBinding roughnessTexture;
    roughnessTexture.input = render::MaterialInput::Roughness;
    MaterialDesc textured = roughMetal;
    textured.bindings.push_back(roughnessTexture);
    EXPECT_EQ(quadUnderRectLight(textured), unsigned(kEmitterSeen | kDirect | kSpecularSeen))
        << "a texture can make the roughness anything";
}

TEST(ScenePathClasses, CausticsNeedADeltaLobeAReceiverAndALightOfTheirKind) {
    const unsigned underRect = scenePathClasses(sphereOnFloor(glass(), {light(LightType::Rect)}));
    EXPECT_TRUE(underRect & kCaustics);
    EXPECT_FALSE(underRect & (kDeltaLightCaustics | kDeltaLights));

    render::LightDesc point = light(LightType::Sphere);
    point.treatAsPoint = true;
    const unsigned underPoint = scenePathClasses(sphereOnFloor(mirror(), {point}));
    EXPECT_EQ(underPoint & (kCaustics | kDeltaLightCaustics | kDeltaLights),
              unsigned(kDeltaLightCaustics | kDeltaLights));

    SceneDescription mirrorBesideFloor;
    mirrorBesideFloor.materials = {test::diffuseMaterial("/White", RGB(0.8f)), mirror()};
    mirrorBesideFloor.meshes = {
        floorQuad(0), test::quadMesh("/Mirror", {Vec3f(-1, 1, 0), Vec3f(1, 1, 0), Vec3f(1, 1, 2), Vec3f(-1, 1, 2)}, 1)};
    mirrorBesideFloor.lights = {light(LightType::Rect)};
    EXPECT_TRUE(scenePathClasses(mirrorBesideFloor) & kCaustics) << "two flat surfaces";
    mirrorBesideFloor.meshes.pop_back();
    EXPECT_FALSE(scenePathClasses(mirrorBesideFloor) & kCaustics) << "a mirror that is nowhere";

    SceneDescription glassAlone;
    glassAlone.materials = {glass()};
    glassAlone.meshes = {test::sphereMesh(0.5f, 16, 8, 0)};
    glassAlone.lights = {light(LightType::Rect), point};
    EXPECT_FALSE(scenePathClasses(glassAlone) & (kCaustics | kDeltaLightCaustics)) << "nothing to receive them";
    glassAlone.volumes = {render::VolumeDesc{}};
    EXPECT_TRUE(scenePathClasses(glassAlone) & kCaustics) << "a volume receives them";
    EXPECT_TRUE(scenePathClasses(glassAlone) & kDeltaLightCaustics);

    EXPECT_FALSE(scenePathClasses(
                     sphereOnFloor(test::diffuseMaterial("/Red", RGB(0.8f, 0.1f, 0.1f)), {light(LightType::Rect)})) &
                 kCaustics)
        << "no delta lobe";
}

TEST(ScenePathClasses, DeltaLightsArePointsLinesAndSuns) {
    auto classesOf = [](const render::LightDesc& l) {
        SceneDescription s;
        s.lights = {l};
        return scenePathClasses(s);
    };
    render::LightDesc spot = light(LightType::Sphere);
    spot.treatAsPoint = true;
    spot.shaping = render::LightShapingDesc{};
    render::LightDesc line = light(LightType::Cylinder);
    line.treatAsLine = true;
    render::LightDesc sun = light(LightType::Distant);
    for (const render::LightDesc& delta : {spot, line, sun}) EXPECT_TRUE(classesOf(delta) & kDeltaLights);

    sun.angleDegrees = 0.53f;
    for (const render::LightDesc& area :
         {sun, light(LightType::Sphere), light(LightType::Cylinder), light(LightType::Disk)})
        EXPECT_EQ(classesOf(area), unsigned(kEmitterSeen));
}

TEST(ScenePathClasses, VolumesAndScatteringInteriors) {
    SceneDescription s;
    s.volumes = {render::VolumeDesc{}};
    EXPECT_EQ(scenePathClasses(s), unsigned(kVolumes));

    MaterialDesc murky = glass();
    murky.interior = media::MediumProperties();
    murky.interior->sigmaA = RGB(0.1f);
    EXPECT_FALSE(quadUnderRectLight(murky) & kVolumes) << "an interior that only absorbs";
    murky.interior->sigmaS = RGB(0.5f);
    EXPECT_TRUE(quadUnderRectLight(murky) & kVolumes);
}

TEST(ScenePathClasses, Subsurface) {
    MaterialDesc skin = test::diffuseMaterial("/Skin", RGB(0.8f, 0.5f, 0.4f));
    EXPECT_FALSE(quadUnderRectLight(skin) & kSubsurface);
    skin.subsurface = 0.5f;
    EXPECT_TRUE(quadUnderRectLight(skin) & kSubsurface);
}

}  // namespace
}  // namespace fluence::integrators
