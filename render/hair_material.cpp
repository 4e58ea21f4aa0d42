#include "render/hair_material.h"

#include <algorithm>

#include "render/bsdfs/hair.h"

namespace fluence::render {

namespace {
// Human hair's index (Marschner et al. 2003), used where the material leaves UsdPreviewSurface's.
constexpr float kHairIor = 1.55f;
constexpr float kPreviewSurfaceIor = 1.5f;
// Below this roughness the lobes are too narrow to sample well in float.
constexpr float kMinRoughness = 0.05f;
}  // namespace

HairParams hairFromMaterial(const MaterialParams& material, const RGB& colour) {
    HairParams hair;
    const float roughness = std::clamp(material.roughness, kMinRoughness, 1.0f);
    hair.longitudinalRoughness = roughness;
    hair.azimuthalRoughness = roughness;
    hair.ior = material.ior == kPreviewSurfaceIor || !(material.ior > 1.0f) ? kHairIor : material.ior;
    hair.absorption = hairAbsorptionFromColour(colour, roughness);
    return hair;
}

}  // namespace fluence::render
