#include "delegate/scene_delegate.h"

#include <algorithm>
#include <map>
#include <set>

#include "delegate/implicit_geometry.h"
#include "delegate/light_adapter.h"

namespace fluence::delegate {

namespace {

// Types that carry no geometry of their own and need no warning.
bool isStructuralType(const std::string& t) {
    static const std::set<std::string> kTypes = {"",          "Xform",          "Scope",        "Material",
                                                 "Shader",    "NodeGraph",      "GeomSubset",   "RenderSettings",
                                                 "RenderProduct", "RenderVar",  "RenderPass",   "Camera",
                                                 "OpenVDBAsset", "Field3DAsset"};
    return kTypes.contains(t);
}

bool isGeometryType(const std::string& t) { return t == "Mesh" || isImplicitType(t); }

// Whether a prim's subtree is rendered at all: visibility and purpose prune it.
bool rendered(const usd::PrimSpec& prim, double time) {
    PrimReader reader(prim, time);
    if (reader.token({"visibility"}, "inherited") == "invisible") return false;
    std::string purpose = reader.token({"purpose"}, "default");
    return purpose != "guide" && purpose != "proxy";
}

// Mesh attributes by the dirty bit an edit of them sets.
std::uint32_t meshBitsFor(const std::string& name) {
    if (name == "points") return kDirtyPoints;
    if (name == "normals" || name.starts_with("primvars:")) return kDirtyPrimvars;
    return kDirtyTopology;  // faceVertex*, holeIndices, orientation, radius, size, height, axis, ...
}

}  // namespace

SceneDelegate::SceneDelegate(usd::Stage& stage, DelegateOptions options) : stage_(stage), options_(std::move(options)) {
    renderSettings_ = renderSettingsFromStage(stage_, options_.settingsPath, options_.time);
    populate("/");
}

void SceneDelegate::populate(const std::string& root) {
    std::map<std::string, std::pair<std::size_t, std::string>> unsupported;  // type -> (count, first prim)
    stage_.traverse([&](const usd::PrimSpec& prim) {
        if (!isAtOrBelow(prim.path, root)) return isAtOrBelow(root, prim.path) && rendered(prim, options_.time);
        if (!rendered(prim, options_.time)) return false;
        const std::string& type = prim.typeName;
        if (isGeometryType(type))
            index_.insert(std::make_unique<MeshRprim>(prim.path));
        else if (type == "Volume")
            index_.insert(std::make_unique<VolumeRprim>(prim.path));
        else if (type == "Camera")
            index_.insert(std::make_unique<CameraSprim>(prim.path));
        else if (isLightType(type))
            index_.insert(std::make_unique<LightSprim>(prim.path));
        else if (!isStructuralType(type)) {
            auto& [count, first] = unsupported[type];
            if (count++ == 0) first = prim.path;
        }
        return true;
    });
    for (const auto& [type, entry] : unsupported)
        options_.warn(entry.second, "prim type '" + type + "' is not supported yet; skipped " + std::to_string(entry.first) +
                                        (entry.first == 1 ? " prim" : " prims"));
}

std::size_t SceneDelegate::sync() {
    std::size_t synced = index_.sync(context());
    chooseCamera();
    return synced;
}

void SceneDelegate::chooseCamera() {
    // The camera asked for, else the rendered product's (or the settings') camera, else the first
    // one in traversal order.
    std::string wanted = options_.cameraPath;
    if (wanted.empty() && renderSettings_) wanted = renderSettings_->renderedCamera();
    if (!wanted.empty()) {
        const usd::PrimSpec* prim = stage_.prim(wanted);
        if (!prim) throw SceneError("camera " + wanted + " does not exist in the scene");
        if (prim->typeName != "Camera")
            throw SceneError("camera " + wanted + " is a " + (prim->typeName.empty() ? "typeless prim" : prim->typeName) +
                             ", not a Camera");
        if (!index_.find(wanted)) throw SceneError("camera " + wanted + " is not active, defined and visible in the scene");
        cameraPath_ = wanted;
        return;
    }
    cameraPath_.clear();
    stage_.traverse([&](const usd::PrimSpec& prim) {
        if (cameraPath_.empty() && prim.typeName == "Camera" && index_.find(prim.path)) cameraPath_ = prim.path;
        return cameraPath_.empty();
    });
    if (cameraPath_.empty()) throw SceneError("the scene has no camera: add a Camera prim, or name one with -c/--camera");
}

render::SceneDescription SceneDelegate::sceneDescription() const {
    // In the stage's traversal order, so the description (and the render) does not depend on
    // the order prims entered the index; materials in the order meshes first bind them.
    render::SceneDescription scene;
    std::map<std::string, int> materialIndex;
    std::size_t volumes = 0;
    auto materialFor = [&](const std::string& path) {
        auto [it, inserted] = materialIndex.try_emplace(path, static_cast<int>(scene.materials.size()));
        if (inserted) scene.materials.push_back(static_cast<const MaterialSprim&>(*index_.find(path)).material());
        return it->second;
    };
    stage_.traverse([&](const usd::PrimSpec& spec) {
        const RenderPrim* prim = index_.find(spec.path);
        if (!prim) return true;
        switch (prim->kind()) {
            case RenderPrim::Kind::Light:
                if (const auto& light = static_cast<const LightSprim&>(*prim).light()) scene.lights.push_back(*light);
                break;
            case RenderPrim::Kind::Camera:
                if (spec.path == cameraPath_) scene.camera = static_cast<const CameraSprim&>(*prim).camera();
                break;
            case RenderPrim::Kind::Mesh:
                for (MeshRprim::Part& part : static_cast<const MeshRprim&>(*prim).worldParts()) {
                    if (part.objectSpace.indices.empty()) continue;
                    if (!part.materialPath.empty()) {
                        part.objectSpace.material = materialFor(part.materialPath);
                        part.objectSpace.cornerColors.clear();  // a bound material replaces displayColor
                    }
                    scene.meshes.push_back(std::move(part.objectSpace));
                }
                break;
            case RenderPrim::Kind::Volume:
                ++volumes;
                break;
            case RenderPrim::Kind::Material:
                break;
        }
        return true;
    });
    if (volumes > 0)
        options_.warn("/", std::to_string(volumes) + (volumes == 1 ? " volume is" : " volumes are") +
                               " read but not rendered yet (volume rendering is issue #7)");
    if (!scene.camera) throw SceneError("the scene has no camera: add a Camera prim, or name one with -c/--camera");
    return scene;
}

void SceneDelegate::setTime(double time) {
    options_.time = time;
    renderSettings_ = renderSettingsFromStage(stage_, options_.settingsPath, time);
    for (const auto& [path, prim] : index_.prims()) {
        if (prim->transformAnimated()) prim->markDirty(kDirtyTransform);
        if (prim->dataAnimated()) prim->markDirty(kAllDirty & ~std::uint32_t(kDirtyTransform));
    }
}

void SceneDelegate::setAttribute(const std::string& primPath, const std::string& name, const usd::Value& value) {
    if (!stage_.setAttribute(primPath, name, value))
        throw SceneError("cannot set " + primPath + "." + name + ": the prim does not exist");
    if (name == "visibility" || name == "purpose") {
        index_.removeSubtree(primPath);
        populate(primPath);
        return;
    }
    if (name.starts_with("xformOp")) {
        index_.markSubtreeDirty(primPath, kDirtyTransform);
        return;
    }
    if (RenderPrim* prim = index_.find(primPath)) {
        prim->markDirty(prim->kind() == RenderPrim::Kind::Mesh ? meshBitsFor(name) : kDirtyParams);
        return;
    }
    // Inside a material (a shader input, an interface input), or a GeomSubset under a mesh.
    for (std::string p = primPath; p.size() > 1; p = p.substr(0, std::max<std::size_t>(p.rfind('/'), 1)))
        if (RenderPrim* owner = index_.find(p)) {
            owner->markDirty(owner->kind() == RenderPrim::Kind::Mesh ? kDirtyTopology : kDirtyParams);
            return;
        }
}

void SceneDelegate::setVariantSelection(const std::string& primPath, const std::string& variantSet,
                                        const std::string& selection) {
    stage_.setVariantSelection(primPath, variantSet, selection);
    index_.removeSubtree(primPath);
    populate(primPath);
}

DelegateResult populateScene(usd::Stage& stage, const DelegateOptions& options) {
    SceneDelegate delegate(stage, options);
    delegate.sync();
    return {delegate.sceneDescription(), delegate.cameraPath(), delegate.renderSettings()};
}

}  // namespace fluence::delegate
