#include "delegate/scene_delegate.h"

#include <algorithm>
#include <map>
#include <set>
#include <unordered_map>

#include "delegate/camera_adapter.h"
#include "delegate/light_adapter.h"
#include "delegate/mesh_adapter.h"
#include "delegate/xform.h"

namespace fluence::delegate {

namespace {

// Types that carry no geometry of their own and need no warning.
bool isStructuralType(const std::string& t) {
    static const std::set<std::string> kTypes = {"",          "Xform",          "Scope",        "Material",
                                                 "Shader",    "NodeGraph",      "GeomSubset",   "RenderSettings",
                                                 "RenderProduct", "RenderVar",  "RenderPass",   "Camera"};
    return kTypes.contains(t);
}

std::string parentPathOf(const std::string& path) {
    auto slash = path.rfind('/');
    return slash == 0 || slash == std::string::npos ? "/" : path.substr(0, slash);
}

std::optional<RenderSettingsInfo> findRenderSettings(const usd::Stage& stage, double time) {
    const usd::PrimSpec* settings = nullptr;
    if (const usd::MetadataEntry* e = usd::findMetadata(stage.rootLayer().metadata, "renderSettingsPrimPath"))
        settings = stage.prim(e->value.asString().value_or(""));
    if (!settings)
        stage.traverse([&](const usd::PrimSpec& p) {
            if (!settings && p.typeName == "RenderSettings") settings = &p;
            return !settings;
        });
    if (!settings) return std::nullopt;
    RenderSettingsInfo info;
    info.path = settings->path;
    PrimReader reader(*settings, time);
    if (auto r = reader.value("resolution")) {
        if (!r->isNumeric() || r->numbers.size() != 2 || r->numbers[0] < 1 || r->numbers[1] < 1)
            reader.fail("resolution must be an int2 of positive values, got " + r->toString());
        info.resolution = std::make_pair(static_cast<int>(r->numbers[0]), static_cast<int>(r->numbers[1]));
    }
    if (const usd::RelationshipSpec* cam = settings->relationship("camera"); cam && !cam->targets.empty())
        info.cameraPath = resolveTargetPath(settings->path, cam->targets.front());
    return info;
}

}  // namespace

DelegateResult populateScene(const usd::Stage& stage, const DelegateOptions& options) {
    DelegateResult result;
    render::SceneDescription& scene = result.scene;
    const double time = options.time;
    result.renderSettings = findRenderSettings(stage, time);

    std::unordered_map<std::string, Matrix4> worldOf{{"/", Matrix4::identity()}};
    std::map<std::string, int> materialIndex;
    std::map<std::string, std::pair<std::size_t, std::string>> unsupported;  // type -> (count, first prim)
    std::vector<std::pair<std::string, Matrix4>> cameras;

    auto warnFor = [&](const std::string& path) {
        return [&options, path](const std::string& message) { options.warn(path, message); };
    };

    stage.traverse([&](const usd::PrimSpec& prim) {
        ++result.primsVisited;
        PrimReader reader(prim, time);
        if (reader.token({"visibility"}, "inherited") == "invisible") return false;
        std::string purpose = reader.token({"purpose"}, "default");
        if (purpose == "guide" || purpose == "proxy") return false;

        LocalTransform local = localTransform(reader);
        const Matrix4 world = local.resetsXformStack ? local.matrix : worldOf.at(parentPathOf(prim.path)) * local.matrix;
        worldOf[prim.path] = world;

        const std::string& type = prim.typeName;
        if (type == "Mesh") {
            render::MeshDesc mesh = meshFromPrim(reader, world, options.convertColor);
            std::string material = boundMaterialPath(stage, prim);
            if (!material.empty()) {
                auto [it, inserted] = materialIndex.try_emplace(material, static_cast<int>(scene.materials.size()));
                if (inserted)
                    scene.materials.push_back(materialFromPath(stage, material, time, options.convertColor, options.warn));
                mesh.material = it->second;
                mesh.cornerColors.clear();  // a bound material replaces displayColor
            }
            if (!mesh.indices.empty()) scene.meshes.push_back(std::move(mesh));
        } else if (type == "Camera") {
            cameras.emplace_back(prim.path, world);
        } else if (isLightType(type)) {
            if (auto light = lightFromPrim(reader, world, warnFor(prim.path))) scene.lights.push_back(std::move(*light));
        } else if (!isStructuralType(type)) {
            auto& [count, first] = unsupported[type];
            if (count++ == 0) first = prim.path;
        }
        return true;
    });

    for (const auto& [type, entry] : unsupported)
        options.warn(entry.second, "prim type '" + type + "' is not supported yet; skipped " + std::to_string(entry.first) +
                                       (entry.first == 1 ? " prim" : " prims"));

    // The camera: the one asked for, else the render settings' camera, else the first one found.
    std::string wanted = options.cameraPath;
    if (wanted.empty() && result.renderSettings) wanted = result.renderSettings->cameraPath;
    if (!wanted.empty()) {
        const usd::PrimSpec* prim = stage.prim(wanted);
        if (!prim) throw SceneError("camera " + wanted + " does not exist in the scene");
        if (prim->typeName != "Camera")
            throw SceneError("camera " + wanted + " is a " + (prim->typeName.empty() ? "typeless prim" : prim->typeName) +
                             ", not a Camera");
        auto it = std::find_if(cameras.begin(), cameras.end(), [&](const auto& c) { return c.first == wanted; });
        if (it == cameras.end()) throw SceneError("camera " + wanted + " is not active, defined and visible in the scene");
        scene.camera = cameraFromPrim(PrimReader(*prim, time), it->second);
        result.cameraPath = wanted;
    } else if (!cameras.empty()) {
        scene.camera = cameraFromPrim(PrimReader(*stage.prim(cameras.front().first), time), cameras.front().second);
        result.cameraPath = cameras.front().first;
    } else {
        throw SceneError("the scene has no camera: add a Camera prim, or name one with -c/--camera");
    }
    return result;
}

}  // namespace fluence::delegate
