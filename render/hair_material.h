// The hair BSDF's parameters from a curve's material (render/bsdfs/hair.h), as Cycles' principled
// hair ("absorption from colour") and Arnold's standard_hair read a plain material: the diffuse
// colour (UsdPreviewSurface diffuseColor, Standard Surface base_color x base, or displayColor) is
// the colour the fibre shows after multiple scattering, turned into the absorption coefficient by
// Chiang et al.'s fit; roughness (specular_roughness) is both the longitudinal and the azimuthal
// roughness; the index of refraction is the material's ior when it is authored away from
// UsdPreviewSurface's 1.5 default, else hair's 1.55; the cuticle tilt is 2 degrees.
#pragma once

#include "render/scene_description.h"

namespace fluence::render {

// `colour` is the fibre's colour at this point (the material's diffuse, or the curve's displayColor).
HairParams hairFromMaterial(const MaterialParams& material, const RGB& colour);

}  // namespace fluence::render
