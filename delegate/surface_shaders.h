// Surface shaders -> render::MaterialDesc (the render core's layered parameter set).
//
// UsdPreviewSurface (info:id "UsdPreviewSurface"), with the specification's fallbacks:
// | input              | fallback        | MaterialDesc                                              |
// |--------------------|-----------------|-----------------------------------------------------------|
// | diffuseColor       | (0.18, 0.18, 0.18) | diffuse; also a metal's reflectance                    |
// | emissiveColor      | (0, 0, 0)       | emission                                                  |
// | useSpecularWorkflow| 0               | specularWorkflow                                          |
// | specularColor      | (0, 0, 0)       | specularColor (specular workflow: the F0 colour; the      |
// |                    |                 | metallic workflow leaves it white and takes F0 from ior)  |
// | metallic           | 0               | metallic (metallic workflow only)                         |
// | roughness          | 0.5             | roughness                                                 |
// | clearcoat          | 0               | coat                                                      |
// | clearcoatRoughness | 0.01            | coatRoughness                                             |
// | opacity            | 1               | opacity: straight transparency (no refraction)            |
// | opacityThreshold   | 0               | opacityThreshold: > 0 makes opacity a cut-out mask        |
// | ior                | 1.5             | ior (of the specular lobe's Fresnel)                      |
// | displacement       | 0               | displacement (displacementBinding when a node drives it), |
// |                    |                 | applied when meshes are diced (delegate/displacement.h)   |
// | normal             | —               | only through a texture: a tangent-space normal map        |
// | occlusion          | —               | ignored, as the specification allows path tracers         |
// Any input above may be connected to a UsdUVTexture or primvar reader
// (delegate/shading_network.h): the node then drives it per surface point (emissiveColor too: the
// mesh's triangles are then lights of textured radiance, render/textured_emission.h).
//
// MaterialX Standard Surface (info:id "ND_standard_surface_surfaceshader"), with MaterialX's
// fallbacks: diffuse = base (0.8) * base_color (1); diffuse_roughness (0); metallic = metalness
// (0); specular (1), specular_color (1), roughness = specular_roughness (0.2), ior = specular_IOR
// (1.5), anisotropy = specular_anisotropy (0); transmission (0), transmission_color (1); sheen (0),
// sheen_color (1), sheen_roughness (0.3); coat (0), coat_color (1), coat_roughness (0.1), coatIor
// = coat_IOR (1.5); emission = emission (0) * emission_color (1); opacity = the mean of opacity
// (1, 1, 1); thin_walled (false); subsurface (0), subsurface_color (1), subsurface_radius (1),
// subsurface_scale (1). transmission_depth (0), transmission_scatter (0) and
// transmission_scatter_anisotropy (0): with a depth > 0 on a solid (not thin-walled), the
// transmission colour is no longer a tint at the surface but the colour white light takes after
// travelling `depth` scene units inside, and the material's interior becomes a homogeneous medium
// (transmissionMedium() below, the mapping of Standard Surface and OpenPBR's translucent base).
// subsurface > 0 on a solid makes its interior (unless transmission_depth made one) the random-walk
// medium of media/subsurface_medium.h: mean free path subsurface_radius x subsurface_scale per
// channel, single-scattering albedo inverted from subsurface_color, Henyey-Greenstein g =
// subsurface_anisotropy (0); light enters and leaves it diffusely (render/material_bsdf.h). On a
// thin wall, subsurface is diffuse transmission tinted by subsurface_color. The method is chosen
// per material by the token input subsurface_type, as Arnold's standard_surface names it:
// "randomwalk" (the classic walk; "randomwalk_v2" is read as the same), "randomwalk_guided" (the
// fallback, Fluence's own: the walk guided towards the surface, media/guided_walk.h) or
// "diffusion" (the Christensen-Burley profile, integrators/diffusion_probe.h); another value warns
// and takes the guided walk.
// Inputs not listed (specular_rotation, transmission_dispersion/extra_roughness, thin_film_*,
// coat_anisotropy/affect_*, tangent) are not read; normal only through a normal map. The colour,
// weight and roughness inputs may be driven by UsdUVTexture / primvar-reader nodes and by
// MaterialX image, tiledimage, constant, multiply and mix nodes (base_color keeps base as its
// factor, emission_color emission), normal by a MaterialX normalmap (delegate/shading_network.h);
// nodes computing a constant set the parameter itself, before the interior media are made from
// it; subsurface inputs take their own values. A node driving emission_color (times emission)
// makes the emission textured, seen by rays and sampled as light (render/textured_emission.h).
#pragma once

#include <string>

#include "delegate/shader_inputs.h"
#include "render/scene_description.h"

namespace fluence::delegate {

inline constexpr const char* kStandardSurfaceId = "ND_standard_surface_surfaceshader";

// The interior of a Standard Surface solid with transmission_depth `depth` > 0, per channel:
// extinction sigmaT = -ln(color) / depth (so that exp(-sigmaT depth) = color; color is clamped to
// [kMinTransmissionColor, 1]), scattering sigmaS = scatter / depth, absorption sigmaA = sigmaT -
// sigmaS, all three channels raised together where that is negative (a scatter brighter than
// the colour allows: extinction grows rather than scattering shrink), and the Henyey-Greenstein g
// = anisotropy, clamped to +-kMaxInteriorAnisotropy.
inline constexpr float kMinTransmissionColor = 1e-4f;
inline constexpr float kMaxInteriorAnisotropy = 0.99f;
media::MediumProperties transmissionMedium(const RGB& color, const RGB& scatter, float anisotropy, float depth);

render::MaterialDesc previewSurface(const ShaderInputs& inputs, const std::string& materialPath);
render::MaterialDesc standardSurface(const ShaderInputs& inputs, const std::string& materialPath);

}  // namespace fluence::delegate
