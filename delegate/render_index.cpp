#include "delegate/render_index.h"

#include <set>

#include "delegate/camera_adapter.h"
#include "delegate/geom_subset.h"
#include "delegate/implicit_geometry.h"
#include "delegate/light_adapter.h"
#include "delegate/xform.h"
#include "render/mesh_transform.h"

namespace fluence::delegate {

namespace {

bool isXformAttribute(const std::string& name) { return name.starts_with("xformOp"); }

bool animated(const usd::AttributeSpec& a) { return a.timeSamples.size() > 1; }

// Whether any attribute of the prim (and, when `recursive`, of its descendants) has time
// samples that change; transform attributes count only when `withTransforms`.
bool hasAnimatedData(const usd::PrimSpec& prim, bool recursive, bool withTransforms) {
    for (const usd::AttributeSpec& a : prim.attributes)
        if ((withTransforms || !isXformAttribute(a.name)) && animated(a)) return true;
    if (recursive)
        for (const auto& child : prim.children)
            if (hasAnimatedData(*child, true, withTransforms)) return true;
    return false;
}

struct WorldTransform {
    Matrix4 matrix = Matrix4::identity();
    bool animated = false;
};

// Composes local transforms from the root down to `path` (honouring !resetXformStack!).
WorldTransform worldTransformOf(const usd::Stage& stage, const std::string& path, double time) {
    WorldTransform result;
    for (std::size_t slash = path.find('/', 1);; slash = path.find('/', slash + 1)) {
        if (const usd::PrimSpec* prim = stage.prim(path.substr(0, slash))) {
            LocalTransform local = localTransform(PrimReader(*prim, time));
            result.matrix = local.resetsXformStack ? local.matrix : result.matrix * local.matrix;
            if (local.resetsXformStack) result.animated = false;
            for (const usd::AttributeSpec& a : prim->attributes)
                if (isXformAttribute(a.name) && animated(a)) result.animated = true;
        }
        if (slash == std::string::npos) break;
    }
    return result;
}

}  // namespace

bool isAtOrBelow(const std::string& path, const std::string& root) {
    if (root == "/") return true;
    return path == root || (path.size() > root.size() && path.starts_with(root) && path[root.size()] == '/');
}

void RenderPrim::sync(const SyncContext& context) {
    if (dirty_ == kClean) return;
    if (dirty_ & kDirtyTransform) {
        WorldTransform w = worldTransformOf(context.stage, path_, context.time);
        world_ = w.matrix;
        transformAnimated_ = w.animated;
    }
    const usd::PrimSpec* prim = context.stage.prim(sourcePath());
    syncData(context, prim, dirty_);
    dataAnimated_ = prim && readsAnimatedData(*prim);
    dirty_ = kClean;
    ++syncCount_;
}

bool RenderPrim::readsAnimatedData(const usd::PrimSpec& source) const { return hasAnimatedData(source, false, false); }

void MeshRprim::syncData(const SyncContext& context, const usd::PrimSpec* spec, std::uint32_t bits) {
    if (!spec || (bits & ~std::uint32_t(kDirtyTransform)) == 0) return;  // a moved mesh keeps its object-space data
    const usd::PrimSpec& prim = *spec;
    ++dataReads_;
    auto warn = [&](const std::string& message) { context.warn(prim.path, message); };
    parts_.clear();
    if (prim.typeName == "Mesh") {
        for (MeshPart& part : meshPartsFromPrim(context.stage, prim, context.time, Matrix4::identity(),
                                                context.convertColor, warn))
            parts_.push_back({std::move(part.mesh), std::move(part.materialPath)});
    } else {
        parts_.push_back({implicitMeshFromPrim(PrimReader(prim, context.time), Matrix4::identity(), context.convertColor, warn),
                          boundMaterialPath(context.stage, prim)});
    }
}

std::vector<MeshRprim::Part> MeshRprim::worldParts() const {
    std::vector<Part> out;
    out.reserve(parts_.size());
    for (const Part& p : parts_) out.push_back({render::transformMesh(p.objectSpace, world()), p.materialPath});
    return out;
}

void PrototypeRprim::syncData(const SyncContext& context, const usd::PrimSpec*, std::uint32_t) {
    ++dataReads_;
    parts_.clear();
    for (MeshPart& part : prototypeParts(context.stage, source_, includeSourceTransform_, context.time,
                                         context.convertColor, context.warn))
        parts_.push_back({std::move(part.mesh), std::move(part.materialPath)});
}

bool PrototypeRprim::readsAnimatedData(const usd::PrimSpec& source) const {
    // Transforms below the source move geometry inside the prototype; the source's own does
    // only when it is included.
    for (const auto& child : source.children)
        if (hasAnimatedData(*child, true, true)) return true;
    return hasAnimatedData(source, false, includeSourceTransform_);
}

void InstanceRprim::syncData(const SyncContext&, const usd::PrimSpec* prim, std::uint32_t) {
    if (prim) prototypeKey_ = instancePrototypeKey(*prim);
}

void PointInstancerRprim::syncData(const SyncContext& context, const usd::PrimSpec* prim, std::uint32_t) {
    if (!prim) return;
    instances_ = pointInstancesFromPrim(PrimReader(*prim, context.time),
                                        [&](const std::string& message) { context.warn(prim->path, message); });
}

void VolumeRprim::syncData(const SyncContext& context, const usd::PrimSpec* prim, std::uint32_t) {
    if (!prim) return;
    fields_.clear();
    for (const usd::RelationshipSpec& rel : prim->relationships) {
        if (!rel.name.starts_with("field:") || rel.targets.empty()) continue;
        Field field;
        field.name = rel.name.substr(6);
        field.assetPrim = resolveTargetPath(prim->path, rel.targets.front());
        const usd::PrimSpec* asset = context.stage.prim(field.assetPrim);
        if (!asset || (asset->typeName != "OpenVDBAsset" && asset->typeName != "Field3DAsset")) {
            context.warn(prim->path, "field '" + field.name + "' targets " + field.assetPrim +
                                         (asset ? ", a " + asset->typeName + ", not an OpenVDBAsset" : ", which does not exist"));
            continue;
        }
        PrimReader reader(*asset, context.time);
        field.filePath = reader.token({"filePath"}, "");
        field.gridName = reader.token({"fieldName"}, "");
        field.fieldIndex = static_cast<int>(reader.number({"fieldIndex"}, -1.0));
        fields_.push_back(std::move(field));
    }
}

bool MaterialSprim::readsAnimatedData(const usd::PrimSpec& source) const { return hasAnimatedData(source, true, false); }

void CameraSprim::syncData(const SyncContext& context, const usd::PrimSpec* prim, std::uint32_t) {
    if (prim) camera_ = cameraFromPrim(PrimReader(*prim, context.time), world());
}

void LightSprim::syncData(const SyncContext& context, const usd::PrimSpec* prim, std::uint32_t) {
    if (!prim) return;
    light_ = lightFromPrim(PrimReader(*prim, context.time), world(),
                           [&](const std::string& message) { context.warn(prim->path, message); });
}

void MaterialSprim::syncData(const SyncContext& context, const usd::PrimSpec*, std::uint32_t) {
    // A missing material prim is warned about by materialFromPath, which returns the default.
    material_ = materialFromPath(context.stage, path(), context.time, context.convertColor, context.warn);
}

void RenderIndex::insert(std::unique_ptr<RenderPrim> prim) {
    std::string path = prim->path();
    prims_[path] = std::move(prim);
}

RenderPrim* RenderIndex::find(const std::string& path) const {
    auto it = prims_.find(path);
    return it == prims_.end() ? nullptr : it->second.get();
}

void RenderIndex::removeSubtree(const std::string& path) {
    for (auto it = prims_.begin(); it != prims_.end();) it = isAtOrBelow(it->first, path) ? prims_.erase(it) : std::next(it);
}

void RenderIndex::markSubtreeDirty(const std::string& path, std::uint32_t bits, std::optional<RenderPrim::Kind> kind) {
    for (auto& [p, prim] : prims_)
        if (isAtOrBelow(p, path) && (!kind || prim->kind() == *kind)) prim->markDirty(bits);
}

std::size_t RenderIndex::sync(const SyncContext& context) {
    std::size_t synced = 0;
    std::set<std::string> materials;
    for (auto& [path, prim] : prims_) {
        if (prim->kind() == RenderPrim::Kind::Material) continue;
        if (prim->dirtyBits() != kClean) {
            prim->sync(context);
            ++synced;
        }
        if (const auto* surface = dynamic_cast<const SurfaceRprim*>(prim.get()))
            for (const auto& part : surface->parts())
                if (!part.materialPath.empty()) materials.insert(part.materialPath);
    }
    for (const std::string& m : materials)
        if (!find(m)) insert(std::make_unique<MaterialSprim>(m));
    for (auto& [path, prim] : prims_)
        if (prim->kind() == RenderPrim::Kind::Material && prim->dirtyBits() != kClean) {
            prim->sync(context);
            ++synced;
        }
    return synced;
}

}  // namespace fluence::delegate
