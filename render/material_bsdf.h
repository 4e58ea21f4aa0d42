// The BSDF of a surface point from its MaterialParams: the layers of render/scene_description.h,
// stacked as Autodesk Standard Surface (and MaterialX's standard_surface graph) stacks them, out
// of render/bsdfs/ in a BsdfArena. From the bottom up, with ggx = GgxDistribution::fromRoughness(
// roughness, anisotropy) (alpha = roughness^2, stretched along the surface tangent by MaterialX's
// mapping, render/bsdfs/ggx.h):
//
//   diffuse   Lambertian(diffuse), or OrenNayar(diffuse, sigma = diffuseRoughness) when it is > 0
//   subsurface MixBsdf(that, LambertianTransmission(1), subsurface)     subsurface > 0: light
//             enters and leaves diffusely; the walk inside the material's interior medium
//             (MaterialDesc::interior, from subsurface_color and subsurface_radius) colours it;
//             a thin wall transmits diffusely, tinted by subsurfaceColor, with no walk
//   sheen     LayeredBsdf(CharlieSheen(sheen x sheenColor, sheenRoughness), diffuse)   sheen > 0
//             the base loses the sheen's directional albedo and is normalised so that it
//             returns exactly that (DiffuseBase: render/bsdfs/sheen.h, layered.h)
//   specular  CoatedBsdf(that, eta, ggx, tint)                  when the dielectric lobe reflects:
//             metallic workflow: eta = ior, tint = specular x specularColor;
//             specular workflow: specularColor is F0 itself, one eta per channel (etaFromF0), tint 1;
//             the base loses tint x E(cos), the lobe's albedo, on each side, normalised as a
//             DiffuseBase (render/bsdfs/layered.h), so that it returns what the lobe does not
//             reflect; over subsurface the share kept inside is reflected back in (each layer
//             its share of what the layers below it let out)
//   glass     MixBsdf(that, glass, transmission)                 transmission > 0; the glass is
//             GgxDielectric(ior, ggx, reflection tint, sqrt(transmissionColor)) for a solid, or
//             ThinDielectric(ior, ggx, reflection tint, transmissionColor) when thinWalled
//   metal     MixBsdf(that, energyCompensatedConductor(F0 = diffuse, ggx), metallic): GGX with
//             Kulla & Conty's multiple-scattering lobe (render/bsdfs/ggx_multiple_scattering.h)
//   coat      MixBsdf(that, CoatedBsdf(that, coatIor, coatRoughness^2, filter = coatColor), coat),
//             a DiffuseBase coat when the diffuse base alone is under it; over a plastic, a
//             sheen, a metal or glass (solid or a thin-walled sheet) the light its underside sends
//             back down is returned (render/bsdfs/coat_return.h)
//
// Weights: diffuse (1 - transmission)(1 - metallic), glass transmission (1 - metallic), metal
// metallic, as in Standard Surface; every mix and layer conserves energy, so the material does:
// with white inputs, every configuration (diffuse, plastic, metal, sheen, subsurface, solid and
// thin-walled glass, and a coat over each) reflects and transmits all the light within 1%
// (tests/render/bsdf_energy_test.cpp, tests/integrators/material_furnace_test.cpp). Colours and weights
// are clamped to [0, 1] per channel.
//
// Transmission. Standard Surface's transmission lobe replaces the diffuse by weight, with the
// specular lobe (and its tint) over both: here the glass is a whole dielectric interface carrying
// its own Fresnel reflection, with the same ior, widths and reflection tint as the specular layer
// over the opaque part, so the specular layer covers both halves alike. transmissionColor tints
// the refracted light (Standard Surface's transmission_depth = 0, a tint at the surface): a
// solid's interface multiplies each crossing by sqrt(transmissionColor), so light that enters and
// leaves a closed object is filtered by transmissionColor exactly once (and the BSDF stays
// reciprocal); a thin wall is crossed once and filters by transmissionColor. A thin wall
// (thinWalled) is a dielectric sheet with the same medium on both sides: it reflects, and lets
// light through straight, without bending it (render/bsdfs/thin_dielectric.h). In the specular
// workflow (UsdPreviewSurface, which has no transmission input) the glass reflects untinted.
//
// coatColor tints what passes through the coat: the light the layers below return through it is
// multiplied by coatColor once (sqrt(coatColor) per crossing: Standard Surface's coat_color as a
// filter, not a path-length absorption); the coat's own reflection is white. The coat is
// isotropic (coat_anisotropy is not read).
//
// Not here: opacity (the render core's presence filters let rays through, render/render_scene.h),
// transmission_depth and subsurface's walk (the interior medium the integrators track,
// MaterialDesc::interior). Not modelled: the metal's edge tint (specularColor in the metallic
// workflow tints only the dielectric lobe), thin-film. A material whose lobes are all off is
// exactly Lambertian.
//
// Hair: a curve's hit carries MaterialParams::hair, and its BSDF is HairBsdf(hair) alone
// (render/bsdfs/hair.h; render/hair_material.h derives the parameters from the material).
#pragma once

#include "render/bsdf.h"
#include "render/bsdf_arena.h"
#include "render/scene_description.h"

namespace fluence::render {

// What the subsurface share of a solid becomes: the light that enters it for a walk inside (Walk,
// LambertianTransmission above), or diffuse reflection of its subsurface colour where the caller
// walks no more (Diffuse: `path` with walks-after-diffuse 0, integrators/path_tracer.h), every
// other lobe as it is. A thin wall, which no walk enters, transmits the same either way.
enum class SubsurfaceShare { Walk, Diffuse };

const Bsdf& materialBsdf(const MaterialParams& material, BsdfArena& arena,
                         SubsurfaceShare subsurface = SubsurfaceShare::Walk);

// Where diffusion subsurface scattering brings light back out (integrators/diffusion_probe.h):
// the subsurface lobe's boundary, LambertianTransmission(1), under the same sheen, specular lobe
// and clear coat as materialBsdf() lays over the base, seen from inside (wo.z < 0). For a material
// with subsurface = 1, no transmission and no metal it is materialBsdf() itself, so that a random
// walk reaching the surface from inside leaves it the same way.
const Bsdf& subsurfaceExitBsdf(const MaterialParams& material, BsdfArena& arena);

}  // namespace fluence::render
