// The BSDF of a surface point from its MaterialDesc: the layers of render/scene_description.h
// built out of render/bsdfs/ in a BsdfArena.
//
//   base      Lambertian(diffuse)
//   specular  CoatedBsdf(base, eta, roughness^2)                   when the dielectric specular lobe
//             is on: `specular` > 0, or in the specular workflow a non-black specularColor
//             (eta from its luminance as F0); a plastic-like glossy layer over the diffuse
//   metal     MixBsdf(that, GgxConductor(F0 = albedo, roughness^2), metallic)
//   coat      MixBsdf(that, CoatedBsdf(that, coatIor, coatRoughness^2), coat)
//
// Not rendered yet (the delegate warns): transmission, sheen, opacity, subsurface. Simplified:
// the specular weight and tint only switch the dielectric lobe on or off, and coatColor and
// anisotropy are not applied. A material whose lobes are all off is exactly Lambertian.
#pragma once

#include "render/bsdf.h"
#include "render/bsdf_arena.h"
#include "render/scene_description.h"

namespace fluence::render {

const Bsdf& materialBsdf(const MaterialParams& material, BsdfArena& arena);

}  // namespace fluence::render
