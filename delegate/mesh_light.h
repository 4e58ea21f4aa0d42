// UsdLuxMeshLightAPI: a Mesh (or another gprim rendered as one) that is an area light, read into
// the render::MeshLightDesc of each part the prim renders as (render/scene_description.h).
//
// | attribute                                   | fallback               | rule                                    |
// |---------------------------------------------|------------------------|-----------------------------------------|
// | intensity, exposure, color,                 | 1, 0, (1,1,1),         | L = intensity * 2^exposure * color (*   |
// | enableColorTemperature, colorTemperature    | false, 6500            | the temperature's tint), as every light |
// | normalize                                   | false                  | L divided by the world-space area of    |
// |                                             |                        | every triangle the prim renders as (its |
// |                                             |                        | subsets and diced subdivision included) |
// | light:materialSyncMode                      | materialGlowTintsLight | below                                   |
//
// The mesh emits L from the front of its surface (the side its normals face by its orientation),
// as a RectLight emits along its -Z, in place of its material's emission: Fluence draws one
// emission per surface, so what the camera sees and what lights the scene agree. Of the modes:
// - materialGlowTintsLight: L is multiplied by the glow of the part's bound material (its
//   constant emission colour) when it has one that is not black; a part without a material, or
//   whose material does not glow, emits L untinted. The material reflects light as usual.
// - independent: L alone; the material reflects light as usual.
// - noMaterialResponse: L alone, and the surface reflects and transmits nothing (black).
// Another token warns and is read as the fallback.
// Light and shadow linking (collection:lightLink, collection:shadowLink) as every light's
// (delegate/light_links.h): the collections on the mesh's prim, applied to every triangle of every
// part the prim renders as.
// Shaping (ShapingAPI applied, or any shaping input authored) as every area light's
// (delegate/light_adapter.h, render/light_shaping.h): cone, focus and IES profile, each triangle's
// emission shaped about its front normal (a RectLight's primary axis, its -Z, is its front normal
// too), the profile's azimuth from the prim's local X and Y.
// Not read, named in one warning: light:filters.
// A mesh light inside a native instance or a point instancer's prototype is read with the
// prototype (delegate/instancing.h, finishMeshLights below): each instance is an emitter of its own,
// and a normalized one divides by its own placed area (render/render_scene.cpp).
// A camera ray sees the surface as its material shades it, not the light (unless the sync mode is
// noMaterialResponse), as Arnold, hdPrman and Storm show it; rays from surfaces still see the light
// (render::Ray::fromCamera; docs/USDLUX.md says where this departs from UsdLux's wording and why).
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "delegate/prim_reader.h"
#include "render/scene_description.h"

namespace fluence::delegate {

enum class MaterialSyncMode { MaterialGlowTintsLight, Independent, NoMaterialResponse };

struct MeshLight {
    std::string prim;    // its path: where its light and shadow links are read (delegate/light_links.h)
    RGB radiance{1.0f};  // intensity * 2^exposure * color (* colour temperature tint)
    bool normalize = false;
    MaterialSyncMode sync = MaterialSyncMode::MaterialGlowTintsLight;
    std::optional<render::LightShapingDesc> shaping;
};

// The prim's mesh light, or nullopt when it does not apply MeshLightAPI. `warn` gets the message
// for each attribute left unread.
std::optional<MeshLight> meshLightOf(const PrimReader& prim, const std::function<void(const std::string&)>& warn);

// Gives each part of one mesh light prim its render::MeshLightDesc: the parts in world space, or
// in a prototype's space; `lightToWorld`: the prim's own local-to-world (or -to-prototype) transform.
void applyMeshLight(const MeshLight& light, std::span<render::MeshDesc> parts,
                    const std::vector<render::MaterialDesc>& materials, const Matrix4& lightToWorld);

// Completes the parts of a prototype's mesh lights (delegate/instancing.h: each part of such a
// prim carries a MeshDesc::light naming it, with lightToWorld its space), once their materials are
// known: each run of consecutive parts of one copy of one prim (MeshLightDesc::copy: two copies in
// one place are two emitters) is one mesh light, given its render::MeshLightDesc by applyMeshLight
// from `lights` (by prim path).
void finishMeshLights(std::span<render::MeshDesc> parts, const std::map<std::string, MeshLight>& lights,
                      const std::vector<render::MaterialDesc>& materials);

}  // namespace fluence::delegate
