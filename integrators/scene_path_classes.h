// The classes of light paths (integrators/path_classes.h) a scene can produce, read from what it
// holds, without rendering it. Every rule errs towards claiming a class: it is claimed whenever
// the scene holds what the paths need, even where the geometry keeps the light from arriving (a
// mirror facing away from every lamp). So an integrator that covers every claimed class misses
// nothing, and one that lacks a claimed class may still, by luck of the layout, render it right.
//
// What a surface's material has, over all its points (an input that a texture or primvar drives
// can take any value in [0, 1]; render/material_bsdf.h has the stack of lobes):
//   diffuse/glossy lobe  the diffuse base (weight (1 - transmission)(1 - metallic) > 0, whatever
//                        its colour), or a specular, glass, metal or coat lobe that is rough
//   delta lobe           a specular, glass, metal or coat lobe that is smooth: GGX alpha below
//                        render::kGgxSmoothAlpha (render/bsdfs/ggx.h), i.e. roughness below ~0.03
// A mesh without a material is Lambertian. A delta light is a SphereLight with treatAsPoint (a
// spot light is one with shaping), a CylinderLight with treatAsLine or a DistantLight of angle 0;
// every other light, and every emissive surface, has an area (or solid angle) a ray can hit.
// Light leaving a surface can reach another surface point when there are two or more surfaces
// (each instance counting as one), or one that is not flat (its points not all in one plane; a
// closed convex mesh is not flat: its inside could be seen). A receiver of caustics is a surface
// with a diffuse/glossy lobe, or a volume.
//
//   kEmitterSeen         a light, or a surface whose material emits
//   kDirect              a surface with a diffuse/glossy lobe
//   kSpecularSeen        a surface with a delta lobe
//   kIndirect            a surface with a diffuse/glossy lobe, and light can reach another
//                        surface point
//   kCaustics            a delta lobe; a receiver; light can reach another surface point, or
//                        there is a volume; and a light that is not delta, or an emissive surface
//   kDeltaLightCaustics  the same with a delta light
//   kDeltaLights         a delta light
//   kVolumes             a volume, or a transmissive material whose interior medium scatters
//   kSubsurface          a material with subsurface > 0
#pragma once

#include "render/scene_description.h"

namespace fluence::integrators {

// The PathClass bits `scene` can produce, by the rules above.
unsigned scenePathClasses(const render::SceneDescription& scene);

}  // namespace fluence::integrators
