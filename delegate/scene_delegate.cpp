#include "delegate/scene_delegate.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <span>

#include "delegate/camera_adapter.h"
#include "delegate/curves_adapter.h"
#include "delegate/curves_rprim.h"
#include "delegate/shape_material.h"
#include "delegate/default_lights.h"
#include "delegate/displacement.h"
#include "delegate/light_groups.h"
#include "delegate/light_links.h"
#include "delegate/imageable.h"
#include "delegate/instancing.h"
#include "delegate/light_adapter.h"
#include "delegate/material_binding.h"
#include "delegate/mesh_light.h"
#include "delegate/points_rprim.h"
#include "delegate/polygon_dicing.h"
#include "delegate/skinned_instances.h"
#include "delegate/motion_samples.h"
#include "render/mesh_transform.h"

namespace fluence::delegate {

namespace {

// Types that carry no geometry of their own and need no warning (a SpatialAudio is sound, which
// no renderer reads; UsdSkel's prims pose the meshes bound to them, delegate/skel_binding.h).
bool isStructuralType(const std::string& t) {
    static const std::set<std::string> kTypes = {"",
                                                 "Xform",
                                                 "Scope",
                                                 "Material",
                                                 "Shader",
                                                 "NodeGraph",
                                                 "GeomSubset",
                                                 "RenderSettings",
                                                 "RenderProduct",
                                                 "RenderVar",
                                                 "RenderPass",
                                                 "Camera",
                                                 "SpatialAudio",
                                                 "SkelRoot",
                                                 "Skeleton",
                                                 "SkelAnimation",
                                                 "BlendShape"};
    return kTypes.contains(t);
}

// Mesh attributes by the dirty bit an edit of them sets.
std::uint32_t meshBitsFor(const std::string& name) {
    if (name == "points") return kDirtyPoints;
    if (name == "normals" || name.starts_with("primvars:")) return kDirtyPrimvars;
    return kDirtyTopology;  // faceVertex*, holeIndices, orientation, radius, size, height, axis, ...
}

// The uniform refinement of subdivision surfaces the default camera is framed on: their limit
// points on a grid of 4 x 4 per cage face, whose bounds come within a few percent of the limit
// surface's (a Catmull-Clark cube: 2%) for a fraction of a camera's dicing.
constexpr int kFramingSubdivisionLevel = 2;

// Prototype keys: one namespace for native-instancing keys, one for point-instancer roots.
std::string nativeKey(const std::string& key) { return "instance:" + key; }
std::string pointInstancerKey(const std::string& root) { return "root:" + root; }

// A mesh part as the render core takes it: a bound material (`materialFor`: its index, -1 when
// it failed to sync) replaces displayColor, and the part keeps only the primvars its material's
// nodes read and those in `aovPrimvars`.
void appendPart(SurfaceRprim::Part part, std::vector<render::MeshDesc>& meshes,
                const std::function<int(const std::string&)>& materialFor,
                const std::vector<render::MaterialDesc>& materials, const std::set<std::string>& aovPrimvars) {
    render::MeshDesc& mesh = part.objectSpace;
    if (mesh.indices.empty()) return;
    const render::MaterialDesc* material = nullptr;
    if (!part.materialPath.empty() && (mesh.material = materialFor(part.materialPath)) >= 0) {
        mesh.cornerColors.clear();
        material = &materials[static_cast<std::size_t>(mesh.material)];
    }
    std::erase_if(mesh.primvars, [&](const render::CornerPrimvar& pv) {
        if (aovPrimvars.contains(pv.name)) return false;
        bool read = false;
        if (material)
            for (const render::InputBinding& b : material->bindings)
                render::forEachSource(b, [&](const render::InputBinding& s) {
                    read = read || (s.texture ? s.texture->uvPrimvar : s.primvar) == pv.name;
                });
        return !read;
    });
    meshes.push_back(std::move(mesh));
}

// Where renderSettingsFromStage reports a renderSettingsPrimPath that names no prim: nowhere
// under --strict (it is an error then), else the delegate's warnings (a no-op when it has none).
Warn settingsWarning(const DelegateOptions& options) {
    if (options.strict) return nullptr;
    if (options.warn) return options.warn;
    return [](const std::string&, const std::string&) {};
}

}  // namespace

SceneDelegate::SceneDelegate(usd::Stage& stage, DelegateOptions options) : stage_(stage), options_(std::move(options)) {
    renderSettings_ = renderSettingsFromStage(stage_, options_.settingsPath, options_.time, settingsWarning(options_));
    try {
        if (options_.purposes)
            purposes_ = IncludedPurposes::fromNames(*options_.purposes);
        else if (renderSettings_)
            purposes_ = IncludedPurposes::fromNames(renderSettings_->includedPurposes);
    } catch (const std::invalid_argument& e) {
        throw SceneError((options_.purposes ? std::string("--purpose") : renderSettings_->path + ": includedPurposes") +
                         ": " + e.what());
    }
    populate("/");
}

void SceneDelegate::populate(const std::string& root) {
    std::map<std::string, std::pair<std::size_t, std::string>> unsupported;  // type -> (count, first prim)
    std::string instanceRoot;  // the instance whose proxies are being visited, "" outside instances
    std::erase_if(walkMalformed_, [&](const auto& entry) { return isAtOrBelow(entry.first, root); });
    const SyncContext sync = context();
    auto imaged = [&](const usd::PrimSpec& prim) {
        return isImaged(prim, options_.time, purposes_, [&](const SceneError& e) {
            walkMalformed_.insert_or_assign(prim.path, skipMalformed(sync, prim.path, e, kReadAsNotAuthored).reason);
        });
    };
    stage_.traverse([&](const usd::PrimSpec& prim) {
        if (!isAtOrBelow(prim.path, root)) return isAtOrBelow(root, prim.path) && imaged(prim);
        if (!imaged(prim)) return false;
        warnUnusableBindings(stage_, prim, options_.warn);
        const std::string& type = prim.typeName;
        if (!instanceRoot.empty() && !isAtOrBelow(prim.path, instanceRoot)) instanceRoot.clear();
        // An instanceable Material is a material like any other (its path is what meshes bind),
        // not a native instance of geometry.
        if (instanceRoot.empty() && !isGeometryType(type) && type != "Material" &&
            !instancePrototypeKey(prim).empty()) {
            const std::optional<PerInstancePose> posed = perInstancePose(stage_, prim);
            if (!posed) {
                index_.insert(std::make_unique<InstanceRprim>(prim.path));
                instanceRoot = prim.path;  // its geometry is the prototype's; lights and cameras stay per prim
                return true;
            }
            // Posed per instance (delegate/skinned_instances.h): its prims are prims of their own.
            options_.warn(prim.path, deinstancedWarning(*posed));
        }
        if (isGeometryType(type) || type == "PointInstancer") {
            // In an instance, the prototype holds them; a point instancer's prototypes, lights
            // included, render only through it, so nothing below it is a prim of its own.
            if (!instanceRoot.empty()) return type != "PointInstancer";
            if (type == "PointInstancer") {
                index_.insert(std::make_unique<PointInstancerRprim>(prim.path));
                return false;  // what lies below renders only through the instancer
            }
            index_.insert(std::make_unique<MeshRprim>(prim.path));
        } else if (isCurvesType(type) || type == "Points") {
            if (!instanceRoot.empty()) return true;  // the prototype holds them
            if (type == "Points")
                index_.insert(std::make_unique<PointsRprim>(prim.path));
            else
                index_.insert(std::make_unique<CurvesRprim>(prim.path));
        } else if (type == "Volume")
            index_.insert(std::make_unique<VolumeRprim>(prim.path));
        else if (isFieldAssetType(type))
            index_.insert(std::make_unique<FieldBprim>(prim.path));
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
        options_.warn(entry.second, "prim type '" + type + "' is not supported yet; skipped " +
                                        std::to_string(entry.first) + (entry.first == 1 ? " prim" : " prims"));
    reconcilePrototypes();
}

void SceneDelegate::reconcilePrototypes() {
    // The prototypes the index's instances need, each read from its first source in path order.
    std::map<std::string, std::pair<std::string, bool>> wanted;  // key -> (source prim, include its transform)
    for (const auto& [path, prim] : index_.prims()) {
        if (prim->kind() == RenderPrim::Kind::Instance) {
            if (const usd::PrimSpec* spec = stage_.prim(path))
                wanted.try_emplace(nativeKey(instancePrototypeKey(*spec)), path, false);
        } else if (prim->kind() == RenderPrim::Kind::PointInstancer) {
            if (const usd::PrimSpec* spec = stage_.prim(path))
                for (const std::string& root : pointInstancerPrototypes(*spec))
                    wanted.try_emplace(pointInstancerKey(root), root, true);
        }
    }
    for (auto it = prototypes_.begin(); it != prototypes_.end();) {
        if (wanted.contains(it->first)) {
            ++it;
            continue;
        }
        index_.removeSubtree(it->second);
        it = prototypes_.erase(it);
    }
    for (const auto& [key, source] : wanted) {
        auto [it, inserted] = prototypes_.try_emplace(key, "/__Prototype_" + std::to_string(nextPrototype_));
        if (inserted) {
            ++nextPrototype_;
            index_.insert(std::make_unique<PrototypeRprim>(it->second, source.first, source.second));
            continue;
        }
        auto& prototype = static_cast<PrototypeRprim&>(*index_.find(it->second));
        if (prototype.source() != source.first) prototype.setSource(source.first);
    }
}

void SceneDelegate::repopulate(const std::string& primPath) {
    index_.removeSubtree(primPath);
    populate(primPath);
    markPrototypesReading(primPath);
}

bool SceneDelegate::markPrototypesReading(const std::string& primPath, const std::string& attribute) {
    bool marked = false;
    for (const auto& [key, path] : prototypes_) {
        auto& prototype = static_cast<PrototypeRprim&>(*index_.find(path));
        bool below = isAtOrBelow(primPath, prototype.source());
        if (!below && !isAtOrBelow(prototype.source(), primPath)) continue;
        // A native instance's own transform places it; it is not part of the prototype.
        if (primPath == prototype.source() && attribute.starts_with("xformOp") && !prototype.includesSourceTransform())
            continue;
        // Above the source only a structural edit (a new variant, visibility) changes it.
        if (!below && !attribute.empty()) continue;
        prototype.markDirty(kAllDirty);
        marked = true;
    }
    return marked;
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
            throw SceneError("camera " + wanted + " is a " +
                             (prim->typeName.empty() ? "typeless prim" : prim->typeName) + ", not a Camera");
        const RenderPrim* camera = index_.find(wanted);
        if (!camera) throw SceneError("camera " + wanted + " is not active, defined and visible in the scene");
        if (camera->failed()) throw SceneError("camera " + wanted + " cannot be used: " + camera->failure());
        cameraPath_ = wanted;
        return;
    }
    cameraPath_.clear();
    stage_.traverse([&](const usd::PrimSpec& prim) {
        const RenderPrim* camera = prim.typeName == "Camera" ? index_.find(prim.path) : nullptr;
        if (cameraPath_.empty() && camera && !camera->failed()) cameraPath_ = prim.path;
        return cameraPath_.empty();
    });
    if (cameraPath_.empty())
        options_.warn("/", "the stage has no camera; framing the whole scene with a default camera, as usdrecord does");
}

render::SceneDescription SceneDelegate::sceneDescription() const {
    const auto* cameraPrim = cameraPath_.empty() ? nullptr : dynamic_cast<const CameraSprim*>(index_.find(cameraPath_));
    if (!cameraPath_.empty() && !cameraPrim) throw SceneError("camera " + cameraPath_ + " is not in the render index");
    auto [width, height] = resolution();
    std::size_t subdivisionTriangles = 0;
    render::CameraDesc cameraDesc;
    if (cameraPrim) {
        cameraDesc = cameraPrim->camera();
    } else {  // framed on the scene with subdivision surfaces refined uniformly, a camera's dicing unknown yet
        DicingSettings coarse = options_.dicing;
        coarse.uniformLevel = kFramingSubdivisionLevel;
        render::Camera provisional(framingCamera({}, stage_.upAxis()), width, height, framing());
        cameraDesc = framingCamera(describe(provisional, coarse, 1.0f, subdivisionTriangles), stage_.upAxis());
    }
    std::unique_ptr<render::Camera> camera;
    try {
        camera = std::make_unique<render::Camera>(cameraDesc, width, height, framing());
    } catch (const std::invalid_argument& e) {
        throw SceneError(e.what());
    }
    render::SceneDescription scene = describe(*camera, options_.dicing, 1.0f, subdivisionTriangles);
    // Over the scene budget: every rate scaled down until the subdivision surfaces fit (rates are
    // clamped and rounded, so the first guess can miss).
    const std::size_t budget = options_.dicing.sceneTriangleBudget, wanted = subdivisionTriangles;
    float scale = 1.0f;
    for (int attempt = 0; subdivisionTriangles > budget && attempt < 8; ++attempt) {
        scale *= 0.95f * std::sqrt(static_cast<float>(budget) / static_cast<float>(subdivisionTriangles));
        scene = describe(*camera, options_.dicing, scale, subdivisionTriangles);
    }
    if (wanted > budget)
        options_.warn("/", "subdivision surfaces would take " + std::to_string(wanted) +
                               " triangles, over the scene budget of " + std::to_string(budget) +
                               "; diced coarser, to " + std::to_string(subdivisionTriangles));
    scene.camera = cameraDesc;
    if (options_.defaultLight && (!renderSettings_ || renderSettings_->defaultLight) && !emitsLight(scene)) {
        for (render::LightDesc& light : defaultLights(cameraDesc)) scene.lights.push_back(std::move(light));
        options_.warn("/",
                      "nothing in the scene emits light (no light, emissive surface or volume); lit by a default "
                      "distant light from the camera and a dim dome, as usdview does (--no-default-light, or "
                      "fluence:defaultLight = false on the render settings, turns them off)");
    }
    resolveLightLinks(stage_, options_.time, scene, options_.warn);
    resolveLightGroups(stage_, options_.time, scene, options_.warn);
    return scene;
}

std::optional<render::VolumeDesc> SceneDelegate::volumeDesc(const VolumeRprim& volume) const {
    const VolumeMaterial& material = volume.material();
    render::VolumeDesc desc;
    desc.params = material.params;
    desc.name = volume.path();
    desc.transform = volume.world();
    bool fileMissing = false;
    auto field = [&](const std::string& name) -> std::optional<render::VolumeFieldDesc> {
        for (const VolumeRprim::Field& f : volume.fields()) {
            if (f.name != name) continue;
            const auto* asset = dynamic_cast<const FieldBprim*>(index_.find(f.assetPrim));
            if (!asset || asset->failed()) return std::nullopt;
            if (!asset->fileFound()) {
                const std::string what = "field '" + name + "': OpenVDB file " +
                                         (asset->filePath().empty() ? "(not authored)" : asset->filePath()) +
                                         " not found";
                if (!options_.allowMissing) throw MissingAssetError(volume.path() + ": " + what);
                options_.warn(volume.path(), what + "; the volume is not rendered (--allow-missing)");
                fileMissing = true;
                return std::nullopt;
            }
            return render::VolumeFieldDesc{asset->filePath(), asset->gridName(), asset->fieldIndex()};
        }
        return std::nullopt;
    };
    desc.density = field(material.densityField);
    desc.temperature = field(material.temperatureField);
    desc.color = field(material.colorField);
    if (fileMissing) return std::nullopt;
    if (!desc.density) {
        options_.warn(volume.path(), "no field:" + material.densityField +
                                         " relationship to an OpenVDBAsset; the volume is not rendered");
        return std::nullopt;
    }
    return desc;
}

render::SceneDescription SceneDelegate::describe(const render::Camera& camera, const DicingSettings& dicingSettings,
                                                 float scale, std::size_t& subdivisionTriangles) const {
    // In the stage's traversal order, so the description (and the render) does not depend on
    // the order prims entered the index; materials in the order meshes first bind them.
    render::SceneDescription scene;
    subdivisionTriangles = 0;
    std::map<std::string, int> materialIndex;
    std::function<int(const std::string&)> materialFor = [&](const std::string& path) {
        const auto& sprim = static_cast<const MaterialSprim&>(*index_.find(path));
        if (sprim.failed()) return -1;  // the default material
        auto [it, inserted] = materialIndex.try_emplace(path, static_cast<int>(scene.materials.size()));
        if (inserted) scene.materials.push_back(sprim.material());
        return it->second;
    };
    MaterialDisplacements displacements(options_.textures.get(), options_.warn);
    DicingContext dicing{camera, dicingSettings,
                         [&](const std::string& material) -> const MaterialDisplacement* {
                             const auto* sprim = dynamic_cast<const MaterialSprim*>(index_.find(material));
                             return sprim && !sprim->failed() ? displacements.of(sprim->material()) : nullptr;
                         },
                         options_.warn, scale};
    auto countSubdivided = [&](const std::vector<render::MeshDesc>& meshes, std::size_t from) {
        for (std::size_t i = from; i < meshes.size(); ++i) subdivisionTriangles += meshes[i].indices.size() / 3;
    };

    // Prototypes get an index when their first instance is met, and their geometry once every
    // placement is known (subdivision surfaces are diced for the nearest instances).
    std::map<std::string, int> prototypeIndex;  // key -> index into scene.prototypes
    std::vector<std::vector<Matrix4>> placements;
    auto prototypeFor = [&](const std::string& key, const Matrix4& placement) {
        auto [it, inserted] = prototypeIndex.try_emplace(key, static_cast<int>(scene.prototypes.size()));
        if (inserted) {
            scene.prototypes.push_back(
                {static_cast<const PrototypeRprim&>(*index_.find(prototypes_.at(key))).source(), {}});
            placements.emplace_back();
        }
        placements[static_cast<std::size_t>(it->second)].push_back(placement);
        return it->second;
    };
    stage_.traverse([&](const usd::PrimSpec& spec) {
        const RenderPrim* prim = index_.find(spec.path);
        if (!prim || prim->failed()) return true;
        switch (prim->kind()) {
            case RenderPrim::Kind::Light:
                if (const auto& light = static_cast<const LightSprim&>(*prim).light()) scene.lights.push_back(*light);
                break;
            case RenderPrim::Kind::Camera:  // the chosen one is sceneDescription()'s
                break;
            case RenderPrim::Kind::Mesh: {
                const auto& mesh = static_cast<const MeshRprim&>(*prim);
                std::size_t first = scene.meshes.size();
                for (MeshRprim::Part& part : mesh.worldParts(dicing))
                    appendPart(std::move(part), scene.meshes, materialFor, scene.materials, options_.aovPrimvars);
                if (!mesh.subdivided().empty()) countSubdivided(scene.meshes, first);
                if (mesh.meshLight())
                    applyMeshLight(*mesh.meshLight(), std::span(scene.meshes).subspan(first), scene.materials,
                                   mesh.world());
                break;
            }
            case RenderPrim::Kind::Instance:
                scene.instances.push_back(
                    {prototypeFor(nativeKey(static_cast<const InstanceRprim&>(*prim).prototypeKey()), prim->world()),
                     prim->world(), spec.path});
                break;
            case RenderPrim::Kind::PointInstancer: {
                const PointInstances& points = static_cast<const PointInstancerRprim&>(*prim).instances();
                for (const PointInstances::Instance& instance : points.instances) {
                    Matrix4 placement = prim->world() * instance.transform;
                    scene.instances.push_back(
                        {prototypeFor(pointInstancerKey(points.prototypes[instance.prototype]), placement), placement,
                         spec.path + "[" + std::to_string(instance.id) + "]"});
                }
                break;
            }
            case RenderPrim::Kind::Curves: {
                const auto& curves = static_cast<const CurvesRprim&>(*prim);
                render::CurvesDesc desc = withBoundMaterial(curves.worldCurves(), curves.materialPath(), materialFor);
                if (!desc.segments.empty()) scene.curves.push_back(std::move(desc));
                break;
            }
            case RenderPrim::Kind::Points: {
                const auto& points = static_cast<const PointsRprim&>(*prim);
                scene.points.push_back(withBoundMaterial(points.worldPoints(), points.materialPath(), materialFor));
                break;
            }
            case RenderPrim::Kind::Volume:
                if (std::optional<render::VolumeDesc> volume = volumeDesc(static_cast<const VolumeRprim&>(*prim)))
                    scene.volumes.push_back(std::move(*volume));
                break;
            case RenderPrim::Kind::Material:
            case RenderPrim::Kind::Prototype:
            case RenderPrim::Kind::Field:
            case RenderPrim::Kind::Texture: break;
        }
        return true;
    });
    for (const auto& [key, index] : prototypeIndex) {
        const auto& prototype = static_cast<const PrototypeRprim&>(*index_.find(prototypes_.at(key)));
        if (prototype.failed()) continue;  // its instances place nothing
        for (const Matrix4& instance : placements[static_cast<std::size_t>(index)])
            for (render::LightDesc light : prototype.lights()) {
                light.transform = instance * light.transform;
                scene.lights.push_back(std::move(light));
            }
        render::PrototypeDesc& desc = scene.prototypes[static_cast<std::size_t>(index)];
        for (const PrototypeCurves& c : prototype.curves())
            if (!c.curves.segments.empty())
                desc.curves.push_back(withBoundMaterial(c.curves, c.materialPath, materialFor));
        for (const PrototypePoints& p : prototype.points())
            desc.points.push_back(withBoundMaterial(p.points, p.materialPath, materialFor));
        std::vector<render::MeshDesc>& meshes = desc.meshes;
        for (const SurfaceRprim::Part& part : prototype.parts()) {
            std::optional<render::MeshDesc> displaced =
                displacedPart(part.objectSpace, part.materialPath, placements[static_cast<std::size_t>(index)], dicing);
            appendPart(displaced ? SurfaceRprim::Part{std::move(*displaced), part.materialPath} : part, meshes,
                       materialFor, scene.materials, options_.aovPrimvars);
        }
        int subdividedCopy = 0;  // each entry is a copy of its prim (MeshLightDesc::copy)
        for (const SurfaceRprim::Subdivided& sub : prototype.subdivided()) {
            std::vector<Matrix4> where;
            for (const Matrix4& instance : placements[static_cast<std::size_t>(index)])
                where.push_back(instance * sub.placement);
            std::size_t first = meshes.size();
            const bool light = prototype.meshLights().contains(sub.mesh->path());
            for (MeshPart& part : sub.mesh->tessellate(where, dicing)) {
                if (light) part.mesh.light = render::MeshLightDesc{.prim = sub.mesh->path(), .copy = subdividedCopy};
                appendPart({render::transformMesh(part.mesh, sub.placement), std::move(part.materialPath)}, meshes,
                           materialFor, scene.materials, options_.aovPrimvars);
            }
            countSubdivided(meshes, first);
            subdividedCopy += 1;
        }
        finishMeshLights(meshes, prototype.meshLights(), scene.materials);
    }
    return scene;
}

void SceneDelegate::setTime(double time) {
    options_.time = time;
    renderSettings_ = renderSettingsFromStage(stage_, options_.settingsPath, time, settingsWarning(options_));
    markTimeDependent(false);
}

void SceneDelegate::markTimeDependent(bool byVelocities) {
    for (const auto& [path, prim] : index_.prims()) {
        if (prim->failed()) prim->markDirty(kAllDirty);  // it may be well formed at this time
        if (prim->transformAnimated()) prim->markDirty(kDirtyTransform);
        const bool prototype = prim->kind() == RenderPrim::Kind::Prototype;  // its contents move by theirs
        const usd::PrimSpec* spec =
            !byVelocities || prim->dataAnimated()
                ? nullptr
                : stage_.prim(prototype ? static_cast<const PrototypeRprim&>(*prim).source() : path);
        if (prim->dataAnimated() ||
            (spec && (prototype ? movesByVelocitiesAtOrBelow(*spec) : movesByVelocities(*spec))))
            prim->markDirty(kAllDirty & ~std::uint32_t(kDirtyTransform));
    }
}

void SceneDelegate::setMotionStep(double time, double velocityFrame) {
    options_.time = time;
    options_.velocityFrame = velocityFrame;
    options_.warn = [](const std::string&, const std::string&) {};
    markTimeDependent(true);
}

void SceneDelegate::setAttribute(const std::string& primPath, const std::string& name, const usd::Value& value) {
    for (std::string p = primPath; p.size() > 1;) {
        p = parentPath(p);
        if (const RenderPrim* owner = index_.find(p); owner && owner->kind() == RenderPrim::Kind::Instance)
            throw SceneError("cannot set " + primPath + "." + name + ": it lies inside the instance " + p +
                             ", and USD instance proxies are read-only (edit what the instance references, or make " +
                             p + " non-instanceable)");
    }
    if (!stage_.setAttribute(primPath, name, value))
        throw SceneError("cannot set " + primPath + "." + name + ": the prim does not exist");
    if (name == "visibility" || name == "purpose") {
        repopulate(primPath);
        return;
    }
    bool prototypeMarked = markPrototypesReading(primPath, name);
    if (name.starts_with("xformOp")) {
        index_.markSubtreeDirty(primPath, kDirtyTransform);
        return;
    }
    if (RenderPrim* prim = index_.find(primPath)) {
        prim->markDirty(prim->kind() == RenderPrim::Kind::Mesh ? meshBitsFor(name) : kDirtyParams);
        return;
    }
    if (prototypeMarked) return;
    // Inside a material (a shader input, an interface input), or a GeomSubset under a mesh.
    for (std::string p = primPath; p.size() > 1; p = parentPath(p))
        if (RenderPrim* owner = index_.find(p)) {
            owner->markDirty(owner->kind() == RenderPrim::Kind::Mesh ? kDirtyTopology : kDirtyParams);
            return;
        }
}

void SceneDelegate::setVariantSelection(const std::string& primPath, const std::string& variantSet,
                                        const std::string& selection) {
    stage_.setVariantSelection(primPath, variantSet, selection);
    repopulate(primPath);
}

std::vector<MalformedPrim> SceneDelegate::malformedPrims() const {
    std::map<std::string, std::string> all = walkMalformed_;
    for (const auto& [path, prim] : index_.prims()) {
        if (prim->failed()) all.try_emplace(path, prim->failure());
        if (prim->kind() == RenderPrim::Kind::Prototype)
            for (const MalformedPrim& m : static_cast<const PrototypeRprim&>(*prim).malformed())
                all.try_emplace(m.path, m.reason);
    }
    std::vector<MalformedPrim> result;
    for (auto& [path, reason] : all) result.push_back({path, std::move(reason)});
    return result;
}

std::pair<int, int> SceneDelegate::resolution() const {
    if (options_.resolution) return *options_.resolution;
    if (renderSettings_) {
        if (const RenderProductDesc* product = renderSettings_->renderedProduct()) return product->resolution;
        return renderSettings_->resolution;
    }
    return options_.defaultResolution;
}

render::ImageFraming SceneDelegate::framing() const {
    return renderSettings_ ? renderSettings_->renderedFraming() : render::ImageFraming{};
}

DelegateResult populateScene(usd::Stage& stage, const DelegateOptions& options) {
    SceneDelegate delegate(stage, options);
    delegate.sync();
    DelegateResult result{delegate.sceneDescription(), delegate.cameraPath(), delegate.renderSettings(),
                          delegate.resolution(), delegate.framing()};
    if (options.motionBlur && !(result.renderSettings && result.renderSettings->motionBlurDisabled()))
        addMotion(delegate, stage, options, *result.scene.camera, result.scene);
    return result;
}

}  // namespace fluence::delegate
