#include "delegate/mesh_light.h"

#include <algorithm>

#include "delegate/light_adapter.h"

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

// Names each authored attribute or relationship a mesh light does not read.
void warnUnread(const usd::PrimSpec& prim, const std::function<void(const std::string&)>& warn) {
    if (authorsShaping(prim))
        warn("shaping inputs (ShapingAPI) are not applied to a mesh light; it emits as an unshaped area light");
    for (const usd::RelationshipSpec& r : prim.relationships)
        if (r.name == "light:filters")
            warn("light:filters is not read (Fluence has no light filters); the mesh light is unfiltered");
        else if (r.name.starts_with("collection:lightLink:") || r.name.starts_with("collection:shadowLink:"))
            warn(r.name + " is not applied to a mesh light: it lights and shadows every prim");
}

float worldArea(const render::MeshDesc& mesh) {
    float area = 0.0f;
    for (std::size_t c = 0; c + 2 < mesh.indices.size(); c += 3) {
        const Vec3f& p0 = mesh.positions[mesh.indices[c]];
        area +=
            0.5f * length(cross(mesh.positions[mesh.indices[c + 1]] - p0, mesh.positions[mesh.indices[c + 2]] - p0));
    }
    return area;
}

}  // namespace

std::optional<MeshLight> meshLightOf(const PrimReader& prim, const std::function<void(const std::string&)>& warn) {
    if (!appliesSchema(prim.prim(), "MeshLightAPI")) return std::nullopt;
    MeshLight light;
    light.radiance = lightApiRadiance(prim, 1.0, warn);
    light.normalize = prim.boolean({"inputs:normalize", "normalize"}, false);
    light.sync = syncModeOf(prim, warn);
    warnUnread(prim.prim(), warn);
    return light;
}

void applyMeshLight(const MeshLight& light, std::span<render::MeshDesc> parts,
                    const std::vector<render::MaterialDesc>& materials) {
    float area = 0.0f;
    for (const render::MeshDesc& part : parts) area += worldArea(part);
    const RGB radiance = light.normalize ? (area > 0.0f ? light.radiance / area : RGB(0.0f)) : light.radiance;
    for (render::MeshDesc& part : parts) {
        render::MeshLightDesc desc{radiance, light.sync != MaterialSyncMode::NoMaterialResponse};
        if (light.sync == MaterialSyncMode::MaterialGlowTintsLight && part.material >= 0) {
            const RGB& glow = materials[static_cast<std::size_t>(part.material)].emission;
            if (!isBlack(glow)) desc.radiance *= glow;
        }
        part.light = desc;
    }
}

}  // namespace fluence::delegate
