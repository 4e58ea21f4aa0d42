#include "delegate/render_index.h"

#include <set>

#include "delegate/material_binding.h"
#include "delegate/camera_adapter.h"
#include "delegate/curves_rprim.h"
#include "delegate/geom_subset.h"
#include "delegate/implicit_geometry.h"
#include "delegate/light_adapter.h"
#include "delegate/mesh_source.h"
#include "delegate/skel_binding.h"
#include "delegate/points_rprim.h"
#include "delegate/polygon_dicing.h"
#include "delegate/xform.h"
#include "render/mesh_transform.h"
#include "scene/asset_path.h"

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

}  // namespace

WorldTransform worldTransformOf(const usd::Stage& stage, const std::string& path, double time, const Warn& warn) {
    WorldTransform result;
    for (std::size_t slash = path.find('/', 1);; slash = path.find('/', slash + 1)) {
        if (const usd::PrimSpec* prim = stage.prim(path.substr(0, slash))) {
            LocalTransform local =
                localTransform(PrimReader(*prim, time), [&](const std::string& message) { warn(prim->path, message); });
            result.matrix = local.resetsXformStack ? local.matrix : result.matrix * local.matrix;
            if (local.resetsXformStack) result.animated = false;
            for (const usd::AttributeSpec& a : prim->attributes)
                if (isXformAttribute(a.name) && animated(a)) result.animated = true;
        }
        if (slash == std::string::npos) break;
    }
    return result;
}

bool assetFileExists(const std::string& path) {
    return usd::assetExists(path);  // scene/asset_path.h: files, UDIM sets and USDZ package entries
}

bool isFieldAssetType(const std::string& typeName) { return typeName == "OpenVDBAsset" || typeName == "Field3DAsset"; }

bool isAtOrBelow(const std::string& path, const std::string& root) {
    if (root == "/") return true;
    return path == root || (path.size() > root.size() && path.starts_with(root) && path[root.size()] == '/');
}

void RenderPrim::sync(const SyncContext& context) {
    if (dirty_ == kClean) return;
    const usd::PrimSpec* prim = context.stage.prim(sourcePath());
    const std::uint32_t bits = failed() ? kAllDirty : dirty_;  // what failed may be half read
    try {
        if (bits & kDirtyTransform) {
            WorldTransform w = worldTransformOf(context.stage, path_, context.time, context.warn);
            world_ = w.matrix;
            transformAnimated_ = w.animated;
        }
        syncData(context, prim, bits);
        failure_.clear();
    } catch (const MissingAssetError&) {
        throw;
    } catch (const SceneError& e) {
        if (context.strict) throw;
        if (failure_ != e.what()) context.warn(path_, malformedWarning("not rendered", e.what()));
        failure_ = e.what();
    }
    dataAnimated_ = prim && readsAnimatedData(*prim);
    dirty_ = kClean;
    ++syncCount_;
}

bool RenderPrim::readsAnimatedData(const usd::PrimSpec& source) const { return hasAnimatedData(source, false, false); }

void MeshRprim::syncData(const SyncContext& context, const usd::PrimSpec* spec, std::uint32_t bits) {
    // A moved mesh keeps its object-space data, unless it is skinned: its points are placed by its
    // skeleton, whatever its own transform.
    if (!spec || ((bits & ~std::uint32_t(kDirtyTransform)) == 0 && !skinned_)) return;
    const MeshSource source = meshSource(context.stage, *spec, context.time, context.warn);
    skinned_ = source.pose.has_value();
    skinAnimated_ = source.pose && source.pose->animated;
    const usd::PrimSpec& prim = source.prim(*spec);
    ++dataReads_;
    auto warn = [&](const std::string& message) { context.warn(prim.path, message); };
    meshLight_ = meshLightOf(PrimReader(*spec, context.time), warn);
    if ((bits & ~std::uint32_t(kDirtyTransform | kDirtyPoints)) == 0 && subdivided_.size() == 1) {
        // Only the points moved: the subdivision topology stays.
        subdivided_[0].mesh = subdivided_[0].mesh->withPoints(prim, context.time);
        return;
    }
    parts_.clear();
    subdivided_.clear();
    if (prim.typeName == "Mesh" && SubdivisionMesh::isSubdivided(prim, context.time)) {
        subdivided_.push_back(
            {std::make_shared<const SubdivisionMesh>(context.stage, prim, context.time, context.convertColor, warn),
             Matrix4::identity()});
    } else if (prim.typeName == "Mesh") {
        for (MeshPart& part : meshPartsFromPrim(context.stage, prim, context.time, Matrix4::identity(),
                                                context.convertColor, warn, context.velocityFrame))
            parts_.push_back({std::move(part.mesh), std::move(part.materialPath)});
    } else {
        render::MeshDesc surface =
            implicitMeshFromPrim(PrimReader(prim, context.time), Matrix4::identity(), context.convertColor, warn);
        const std::optional<bool> posed = skinSurface(context.stage, prim, context.time, context.warn, surface);
        skinned_ = posed.has_value();
        skinAnimated_ = posed.value_or(false);
        parts_.push_back({std::move(surface), boundMaterialPath(context.stage, prim)});
    }
}

bool MeshRprim::readsAnimatedData(const usd::PrimSpec& source) const {
    return skinAnimated_ || RenderPrim::readsAnimatedData(source);
}

std::vector<std::string> SurfaceRprim::materialPaths() const {
    std::set<std::string> paths;
    for (const Part& p : parts_) paths.insert(p.materialPath);
    for (const Subdivided& s : subdivided_)
        for (const std::string& m : s.mesh->materialPaths()) paths.insert(m);
    for (const PrototypeCurves& c : curves_) paths.insert(c.materialPath);
    for (const PrototypePoints& p : points_) paths.insert(p.materialPath);
    paths.erase("");
    return {paths.begin(), paths.end()};
}

std::vector<MeshRprim::Part> MeshRprim::worldParts(const DicingContext& dicing) const {
    std::vector<Part> out;
    out.reserve(parts_.size());
    for (const Part& p : parts_) {
        std::optional<render::MeshDesc> displaced = displacedPart(p.objectSpace, p.materialPath, {world()}, dicing);
        out.push_back({render::transformMesh(displaced ? *displaced : p.objectSpace, world()), p.materialPath});
    }
    for (const Subdivided& s : subdivided_)
        for (MeshPart& part : s.mesh->tessellate({world() * s.placement}, dicing))
            out.push_back({render::transformMesh(part.mesh, world() * s.placement), std::move(part.materialPath)});
    return out;
}

void PrototypeRprim::syncData(const SyncContext& context, const usd::PrimSpec*, std::uint32_t) {
    ++dataReads_;
    parts_.clear();
    subdivided_.clear();
    PrototypeContents contents = prototypeContents(context, source_, includeSourceTransform_);
    for (MeshPart& part : contents.parts) parts_.push_back({std::move(part.mesh), std::move(part.materialPath)});
    for (PrototypeContents::Subdivided& s : contents.subdivided)
        subdivided_.push_back({std::move(s.mesh), s.placement});
    curves_ = std::move(contents.curves);
    points_ = std::move(contents.points);
    lights_ = std::move(contents.lights);
    meshLights_ = std::move(contents.meshLights);
    malformed_ = std::move(contents.malformed);
    posedByAnimation_ = contents.posedByAnimation;
}

bool PrototypeRprim::readsAnimatedData(const usd::PrimSpec& source) const {
    // Transforms below the source move geometry inside the prototype; the source's own does
    // only when it is included. A skinned prim's animation may lie outside (a point-instancer
    // prototype bound to a shared SkelAnimation).
    if (posedByAnimation_) return true;
    for (const auto& child : source.children)
        if (hasAnimatedData(*child, true, true)) return true;
    return hasAnimatedData(source, false, includeSourceTransform_);
}

void InstanceRprim::syncData(const SyncContext&, const usd::PrimSpec* prim, std::uint32_t) {
    if (prim) prototypeKey_ = instancePrototypeKey(*prim);
}

void PointInstancerRprim::syncData(const SyncContext& context, const usd::PrimSpec* prim, std::uint32_t) {
    if (!prim) return;
    instances_ = pointInstancesFromPrim(
        PrimReader(*prim, context.time), [&](const std::string& message) { context.warn(prim->path, message); },
        &context);
}

void VolumeRprim::syncData(const SyncContext& context, const usd::PrimSpec* prim, std::uint32_t) {
    if (!prim) return;
    fields_.clear();
    for (const usd::RelationshipSpec& rel : prim->relationships) {
        if (!rel.name.starts_with("field:") || rel.targets.empty()) continue;
        Field field{rel.name.substr(6), resolveTargetPath(prim->path, rel.targets.front())};
        const usd::PrimSpec* asset = context.stage.prim(field.assetPrim);
        if (!asset || !isFieldAssetType(asset->typeName)) {
            context.warn(prim->path,
                         "field '" + field.name + "' targets " + field.assetPrim +
                             (asset ? ", a " + asset->typeName + ", not an OpenVDBAsset" : ", which does not exist"));
            continue;
        }
        fields_.push_back(std::move(field));
    }
    material_ = volumeMaterialOf(context.stage, *prim, context.time, context.convertColor, context.warn);
}

void FieldBprim::syncData(const SyncContext& context, const usd::PrimSpec* prim, std::uint32_t) {
    if (!prim) return;
    PrimReader reader(*prim, context.time);
    filePath_ = reader.token({"filePath"}, "");
    gridName_ = reader.token({"fieldName"}, "");
    fieldIndex_ = static_cast<int>(reader.number({"fieldIndex"}, -1.0));
    fileFound_ = assetFileExists(filePath_);
}

void TextureBprim::syncData(const SyncContext& context, const usd::PrimSpec* prim, std::uint32_t) {
    if (!prim) return;
    PrimReader reader(*prim, context.time);
    filePath_ = reader.token({"inputs:file"}, "");
    sourceColorSpace_ = reader.token({"inputs:sourceColorSpace"}, "auto");
    wrapS_ = reader.token({"inputs:wrapS"}, "useMetadata");
    wrapT_ = reader.token({"inputs:wrapT"}, "useMetadata");
    fileFound_ = assetFileExists(filePath_);
}

bool MaterialSprim::readsAnimatedData(const usd::PrimSpec& source) const {
    return hasAnimatedData(source, true, false);
}

void CameraSprim::syncData(const SyncContext& context, const usd::PrimSpec* prim, std::uint32_t) {
    if (prim) camera_ = cameraFromPrim(PrimReader(*prim, context.time), world());
}

void LightSprim::syncData(const SyncContext& context, const usd::PrimSpec* prim, std::uint32_t) {
    if (!prim) return;
    light_ = lightFromPrim(PrimReader(*prim, context.time), world(), context.stage.upAxis(),
                           [&](const std::string& message) { context.warn(prim->path, message); });
}

void MaterialSprim::syncData(const SyncContext& context, const usd::PrimSpec* prim, std::uint32_t) {
    // A missing material prim is warned about by materialFromPath, which returns the default.
    material_ = materialFromPath(context.stage, path(), context.time, context.convertColor, context.warn);
    textures_.clear();
    if (!prim) return;
    usd::Stage::traverse(*prim, [&](const usd::PrimSpec& p) {
        if (p.typeName == "Shader" && PrimReader(p, context.time).token({"info:id"}, "") == "UsdUVTexture")
            textures_.push_back(p.path);
        return true;
    });
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
    for (auto it = prims_.begin(); it != prims_.end();)
        it = isAtOrBelow(it->first, path) ? prims_.erase(it) : std::next(it);
}

void RenderIndex::markSubtreeDirty(const std::string& path, std::uint32_t bits, std::optional<RenderPrim::Kind> kind) {
    for (auto& [p, prim] : prims_)
        if (isAtOrBelow(p, path) && (!kind || prim->kind() == *kind)) prim->markDirty(bits);
}

std::size_t RenderIndex::sync(const SyncContext& context) {
    std::size_t synced = 0;
    auto syncKind = [&](auto&& selected) {
        for (auto& [path, prim] : prims_)
            if (selected(prim->kind()) && prim->dirtyBits() != kClean) {
                prim->sync(context);
                ++synced;
            }
    };
    using Kind = RenderPrim::Kind;
    syncKind([](Kind k) { return k != Kind::Material && k != Kind::Texture; });
    std::set<std::string> materials;
    for (auto& [path, prim] : prims_) {
        if (const auto* surface = dynamic_cast<const SurfaceRprim*>(prim.get()); surface && !surface->failed())
            for (const std::string& m : surface->materialPaths()) materials.insert(m);
        if (const auto* curves = dynamic_cast<const CurvesRprim*>(prim.get());
            curves && !curves->failed() && !curves->materialPath().empty())
            materials.insert(curves->materialPath());
        if (const auto* points = dynamic_cast<const PointsRprim*>(prim.get());
            points && !points->failed() && !points->materialPath().empty())
            materials.insert(points->materialPath());
    }
    for (const std::string& m : materials)
        if (!find(m)) insert(std::make_unique<MaterialSprim>(m));
    syncKind([](Kind k) { return k == Kind::Material; });
    std::set<std::string> textures;
    for (auto& [path, prim] : prims_)
        if (prim->kind() == Kind::Material && !prim->failed())
            for (const std::string& t : static_cast<const MaterialSprim&>(*prim).textures()) textures.insert(t);
    for (const std::string& t : textures)
        if (!find(t)) insert(std::make_unique<TextureBprim>(t));
    syncKind([](Kind k) { return k == Kind::Texture; });
    return synced;
}

}  // namespace fluence::delegate
