// Materials whose path the render index could hold as another kind of render prim: an
// instanceable Material (OpenUSD's testPreviewSurfaceInstancedMaterial.usda, tests/delegate/data)
// is a material, not a native instance; a binding to a prim that is not a Material binds nothing
// (UsdShadeMaterialBindingAPI::ComputeBoundMaterial). Both once read another render prim as a
// material (garbage parameters, std::bad_alloc; AddressSanitizer: heap-buffer-overflow).
#include <gtest/gtest.h>

#include "tests/delegate/delegate_test_support.h"
#include "tests/support/cli.h"

namespace fluence::delegate {
namespace {

using testing::populate;

const render::MaterialDesc* materialOf(const testing::Populated& p, const std::string& meshName) {
    const render::MeshDesc* mesh = p.mesh(meshName);
    if (!mesh || mesh->material < 0) return nullptr;
    return &p.result.scene.materials.at(static_cast<std::size_t>(mesh->material));
}

// The primvar the material's diffuse colour reads, "" when none.
std::string diffusePrimvar(const render::MaterialDesc& m) {
    for (const render::InputBinding& b : m.bindings)
        if (b.input == render::MaterialInput::Diffuse) return b.primvar;
    return "";
}

TEST(InstancedMaterial, AnInstanceableMaterialShadesWithItsOwnInterfaceInputs) {
    testing::Populated p =
        populate(test::slurp(FLUENCE_SOURCE_DIR "/tests/delegate/data/testPreviewSurfaceInstancedMaterial.usda"));
    ASSERT_EQ(p.result.scene.meshes.size(), 2u);
    EXPECT_TRUE(p.result.scene.instances.empty());
    EXPECT_TRUE(p.result.scene.prototypes.empty());

    const render::MaterialDesc* prototype = materialOf(p, "/Scene/Geom/Sphere1");
    ASSERT_NE(prototype, nullptr);
    EXPECT_EQ(prototype->name, "/Scene/Looks/MaterialPrototype");
    EXPECT_FLOAT_EQ(prototype->roughness, 0.3f);
    EXPECT_EQ(diffusePrimvar(*prototype), "mydisplayColor1");

    const render::MaterialDesc* instance = materialOf(p, "/Scene/Geom/Sphere2");
    ASSERT_NE(instance, nullptr);
    EXPECT_EQ(instance->name, "/Scene/Looks/MaterialInstance");
    EXPECT_FLOAT_EQ(instance->roughness, 0.8f);
    EXPECT_EQ(diffusePrimvar(*instance), "mydisplayColor2");
    EXPECT_FALSE(instance->interior);
}

TEST(InstancedMaterial, ABindingToAPrimThatIsNotAMaterialBindsNothing) {
    testing::Populated p = populate(R"(
def Sphere "Ball"
{
    rel material:binding = </Box>
}
def Cube "Box"
{
}
def Xform "Prop" (
    instanceable = true
    references = </_Prop>
)
{
    rel material:binding = </Prop>
}
class Xform "_Prop"
{
    def Cube "Part"
    {
    }
}
)");
    ASSERT_NE(p.mesh("/Ball"), nullptr);
    EXPECT_EQ(p.mesh("/Ball")->material, -1);
    ASSERT_EQ(p.result.scene.prototypes.size(), 1u);
    ASSERT_EQ(p.result.scene.prototypes[0].meshes.size(), 1u);
    EXPECT_EQ(p.result.scene.prototypes[0].meshes[0].material, -1);
    EXPECT_TRUE(p.result.scene.materials.empty());
}

}  // namespace
}  // namespace fluence::delegate
