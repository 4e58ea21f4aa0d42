#include "delegate/mesh_light.h"

#include <algorithm>

#include "delegate/light_adapter.h"
#include "render/mesh_transform.h"

namespace fluence::delegate {

namespace {

MaterialSyncMode syncModeOf(const PrimReader& prim, const std::function<void(const std::string&)>& warn) {
    const std::string mode = prim.token({"light:materialSyncMode"}, "materialGlowTintsLight");
    if (mode == "independent") return MaterialSyncMode::Independent;
    if (mode == "noMaterialResponse") return MaterialSyncMode::NoMaterialResponse;
    if (mode != "materialGlowTintsLight")
        warn("light:materialSyncMode '" + mode + "' is not a UsdLux mode; materialGlowTintsLight is used");
    return MaterialSyncMode::MaterialGlowTintsLight;
}

// Names each authored relationship a mesh light does not read.
void warnUnread(const usd::PrimSpec& prim, const std::function<void(const std::string&)>& warn) {
    for (const usd::RelationshipSpec& r : prim.relationships)
        if (r.name == "light:filters")
            warn("light:filters is not read (Fluence has no light filters); the mesh light is unfiltered");
}

}  // namespace

std::optional<MeshLight> meshLightOf(const PrimReader& prim, const std::function<void(const std::string&)>& warn) {
    if (!appliesSchema(prim.prim(), "MeshLightAPI")) return std::nullopt;
    MeshLight light;
    light.prim = prim.prim().path;
    light.radiance = lightApiRadiance(prim, 1.0, warn);
    light.normalize = prim.boolean({"inputs:normalize", "normalize"}, false);
    light.sync = syncModeOf(prim, warn);
    if (appliesSchema(prim.prim(), "ShapingAPI") || authorsShaping(prim.prim())) light.shaping = shapingOf(prim, warn);
    warnUnread(prim.prim(), warn);
    return light;
}

void applyMeshLight(const MeshLight& light, std::span<render::MeshDesc> parts,
                    const std::vector<render::MaterialDesc>& materials, const Matrix4& lightToWorld) {
    float area = 0.0f;
    for (const render::MeshDesc& part : parts) area += render::surfaceArea(part);
    const RGB radiance = light.normalize ? (area > 0.0f ? light.radiance / area : RGB(0.0f)) : light.radiance;
    for (render::MeshDesc& part : parts) {
        render::MeshLightDesc desc{radiance,       light.sync != MaterialSyncMode::NoMaterialResponse,
                                   light.prim,     -1,
                                   light.shaping,  lightToWorld,
                                   light.normalize};
        if (light.sync == MaterialSyncMode::MaterialGlowTintsLight && part.material >= 0) {
            const RGB& glow = materials[static_cast<std::size_t>(part.material)].emission;
            if (!isBlack(glow)) desc.radiance *= glow;
        }
        part.light = desc;
    }
}

void finishMeshLights(std::span<render::MeshDesc> parts, const std::map<std::string, MeshLight>& lights,
                      const std::vector<render::MaterialDesc>& materials) {
    for (std::size_t first = 0, end = 1; first < parts.size(); first = end, end = first + 1) {
        const std::optional<render::MeshLightDesc>& light = parts[first].light;
        if (!light) continue;
        while (end < parts.size() && parts[end].light && parts[end].light->prim == light->prim &&
               parts[end].light->copy == light->copy)
            ++end;
        if (auto found = lights.find(light->prim); found != lights.end())
            applyMeshLight(found->second, parts.subspan(first, end - first), materials, light->lightToWorld);
    }
}

}  // namespace fluence::delegate
