#include "delegate/instancing.h"

#include <cmath>
#include <map>
#include <set>

#include "delegate/material_binding.h"
#include "delegate/curves_adapter.h"
#include "delegate/curves_rprim.h"
#include "delegate/imageable.h"
#include "delegate/implicit_geometry.h"
#include "delegate/light_adapter.h"
#include "delegate/motion_samples.h"
#include "delegate/points_adapter.h"
#include "delegate/points_rprim.h"
#include "delegate/mesh_source.h"
#include "delegate/xform.h"
#include "render/mesh_transform.h"

namespace fluence::delegate {

namespace {

// The ids an int64 list-op metadata field names, its entries applied in authored order.
std::set<long long> listOpIds(const usd::Metadata& metadata, const std::string& key) {
    std::set<long long> ids;
    for (const usd::MetadataEntry& entry : metadata) {
        if (entry.key != key || !entry.value.isNumeric()) continue;
        if (entry.op == usd::ListOpKind::Explicit) ids.clear();
        for (double id : entry.value.numbers) {
            if (entry.op == usd::ListOpKind::Delete)
                ids.erase(static_cast<long long>(id));
            else if (entry.op != usd::ListOpKind::Reorder)
                ids.insert(static_cast<long long>(id));
        }
    }
    return ids;
}

// An optional per-instance array: its values when it has `count` elements, else nullopt (with a
// warning when it is authored at the wrong length).
std::optional<std::vector<double>> perInstance(const PrimReader& prim, const std::string& name, int components,
                                               std::size_t count, const std::function<void(const std::string&)>& warn) {
    std::optional<std::vector<double>> values = prim.numbers(name, components);
    if (!values) return std::nullopt;
    if (values->size() != count * components) {
        warn("'" + name + "' has " + std::to_string(values->size() / components) + " elements for " +
             std::to_string(count) + " instances; ignored");
        return std::nullopt;
    }
    return values;
}

Matrix4 rotationOf(const double* q) {  // USD order: real part first
    double norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    if (!(norm > 0.0) || !std::isfinite(norm)) return Matrix4::identity();
    return Matrix4::fromQuaternion(q[0] / norm, q[1] / norm, q[2] / norm, q[3] / norm);
}

}  // namespace

std::string instancePrototypeKey(const usd::PrimSpec& prim) {
    const usd::MetadataEntry* entry = usd::findMetadata(prim.metadata, "fluence:instancePrototype");
    return entry ? entry->value.asString().value_or("") : "";
}

std::vector<std::string> pointInstancerPrototypes(const usd::PrimSpec& instancer) {
    std::vector<std::string> paths;
    for (const usd::RelationshipSpec& rel : instancer.relationships)
        if (rel.name == "prototypes" && !rel.blocked)
            for (const std::string& target : rel.targets) paths.push_back(resolveTargetPath(instancer.path, target));
    return paths;
}

PointInstances pointInstancesFromPrim(const PrimReader& prim, const std::function<void(const std::string&)>& warn,
                                      const SyncContext* motion) {
    PointInstances result;
    result.prototypes = pointInstancerPrototypes(prim.prim());
    std::vector<double> protoIndices = prim.numbers("protoIndices", 1).value_or(std::vector<double>{});
    const std::size_t count = protoIndices.size();
    if (count == 0) return result;
    std::optional<std::vector<double>> positions = perInstance(prim, "positions", 3, count, warn);
    if (!positions) {
        warn("'positions' must hold one point per protoIndices entry (" + std::to_string(count) +
             "); no instances placed");
        return result;
    }
    std::optional<std::vector<double>> orientations = prim.value("orientations")
                                                          ? perInstance(prim, "orientations", 4, count, warn)
                                                          : perInstance(prim, "orientationsf", 4, count, warn);
    std::optional<std::vector<double>> scales = perInstance(prim, "scales", 3, count, warn);
    std::optional<std::vector<double>> ids = perInstance(prim, "ids", 1, count, warn);

    const std::optional<InstanceVelocityMotion> moving =
        motion ? instanceVelocityMotion(motion->stage, prim.prim(), motion->time, motion->velocityFrame, count)
               : std::nullopt;

    std::set<long long> hidden = listOpIds(prim.prim().metadata, "inactiveIds");
    for (double id : prim.numbers("invisibleIds", 1).value_or(std::vector<double>{}))
        hidden.insert(static_cast<long long>(id));

    std::size_t outOfRange = 0;
    for (std::size_t i = 0; i < count; ++i) {
        long long id = ids ? static_cast<long long>((*ids)[i]) : static_cast<long long>(i);
        if (hidden.contains(id)) continue;
        double index = protoIndices[i];
        if (!(index >= 0.0 && index < static_cast<double>(result.prototypes.size()))) {
            ++outOfRange;
            continue;
        }
        Vec3d position((*positions)[3 * i], (*positions)[3 * i + 1], (*positions)[3 * i + 2]);
        if (moving && !moving->offsets.empty()) position = position + moving->offsets[i];
        Matrix4 m = Matrix4::translate(position);
        // As UsdGeomPointInstancer composes them: the angular motion turns the oriented instance.
        if (moving && !moving->rotations.empty()) m = m * moving->rotations[i];
        if (orientations) m = m * rotationOf(&(*orientations)[4 * i]);
        if (scales) m = m * Matrix4::scale({(*scales)[3 * i], (*scales)[3 * i + 1], (*scales)[3 * i + 2]});
        result.instances.push_back({static_cast<int>(index), m, id});
    }
    if (outOfRange > 0)
        warn(std::to_string(outOfRange) + " instances have a protoIndices entry outside the " +
             std::to_string(result.prototypes.size()) + " prototypes; skipped");
    return result;
}

namespace {

// Adds `prim`, met walking the prototype at `root`, to `contents` (`spaces`: the transforms of the
// prims met before it); returns whether the walk goes below it. Raises SceneError when it is
// malformed.
bool addToPrototype(const SyncContext& context, const usd::PrimSpec& prim, const std::string& root,
                    bool includeRootTransform, int nesting, std::map<std::string, Matrix4>& spaces,
                    PrototypeContents& contents) {
    const usd::Stage& stage = context.stage;
    const double time = context.time;
    std::vector<MeshPart>& parts = contents.parts;
    if (!isImaged(prim, time, context.purposes, [&](const SceneError& e) {
            contents.malformed.push_back(skipMalformed(context, prim.path, e, kReadAsNotAuthored));
        }))
        return false;
    Matrix4 space = Matrix4::identity();
    auto warnHere = [&](const std::string& message) { context.warn(prim.path, message); };
    if (prim.path != root || includeRootTransform) {
        LocalTransform local = localTransform(PrimReader(prim, time), warnHere);
        space = prim.path == root || local.resetsXformStack ? local.matrix
                                                            : spaces.at(parentPath(prim.path)) * local.matrix;
    }
    spaces[prim.path] = space;
    // A skinned mesh here poses alike in every instance (delegate/skinned_instances.h): posed once.
    const MeshSource source = meshSource(stage, prim, time, context.warn);
    contents.posedByAnimation = contents.posedByAnimation || (source.pose && source.pose->animated);
    const usd::PrimSpec& mesh = source.prim(prim);
    // A mesh light: each instance of the prototype is an emitter of its own (render/scene_description.h).
    const std::size_t firstPart = parts.size();
    if (std::optional<MeshLight> light =
            isGeometryType(prim.typeName) ? meshLightOf(PrimReader(prim, time), warnHere) : std::nullopt)
        contents.meshLights.emplace(prim.path, std::move(*light));
    if (mesh.typeName == "Mesh" && SubdivisionMesh::isSubdivided(mesh, time)) {
        contents.subdivided.push_back(
            {std::make_shared<const SubdivisionMesh>(stage, mesh, time, context.convertColor, warnHere), space});
    } else if (mesh.typeName == "Mesh") {
        for (MeshPart& part :
             meshPartsFromPrim(stage, mesh, time, space, context.convertColor, warnHere, context.velocityFrame))
            parts.push_back(std::move(part));
    } else if (isImplicitType(prim.typeName)) {
        const bool skinned = isSkelDeformed(stage, prim);  // posed in its own space, then placed
        render::MeshDesc surface = implicitMeshFromPrim(PrimReader(prim, time), skinned ? Matrix4::identity() : space,
                                                        context.convertColor, warnHere);
        if (const std::optional<bool> animated =
                skinned ? skinSurface(stage, prim, time, context.warn, surface) : std::nullopt) {
            surface = render::transformMesh(surface, space);
            contents.posedByAnimation = contents.posedByAnimation || *animated;
        }
        parts.push_back({std::move(surface), boundMaterialPath(stage, prim)});
    } else if (isCurvesType(prim.typeName)) {
        contents.curves.push_back(
            {transformCurves(objectSpaceCurves(context, prim), space), boundMaterialPath(stage, prim)});
    } else if (prim.typeName == "Points") {
        contents.points.push_back(
            {pointsToWorld(objectSpacePoints(context, prim), space), boundMaterialPath(stage, prim)});
    } else if (isLightType(prim.typeName)) {
        // (A native instance's own lights are instance proxies, which the render index holds
        // as lights of their own; only a point instancer places its prototypes' lights.)
        if (includeRootTransform)
            if (std::optional<render::LightDesc> light =
                    lightFromPrim(PrimReader(prim, time), space, stage.upAxis(), warnHere))
                contents.lights.push_back(std::move(*light));
    } else if (prim.typeName == "PointInstancer") {
        if (nesting + 1 >= kMaxPrototypeNesting) {
            warnHere("point instancers nest deeper than " + std::to_string(kMaxPrototypeNesting) + " levels; cut here");
            return false;
        }
        PointInstances nested = pointInstancesFromPrim(PrimReader(prim, time), warnHere, &context);
        std::vector<PrototypeContents> nestedContents;
        for (const std::string& path : nested.prototypes) {
            nestedContents.push_back(prototypeContents(context, path, true, nesting + 1));
            for (MalformedPrim& m : nestedContents.back().malformed) contents.malformed.push_back(std::move(m));
            contents.posedByAnimation = contents.posedByAnimation || nestedContents.back().posedByAnimation;
        }
        for (const PointInstances::Instance& instance : nested.instances) {
            const PrototypeContents& inner = nestedContents[instance.prototype];
            Matrix4 placement = space * instance.transform;
            for (const MeshPart& part : inner.parts) {
                parts.push_back({render::transformMesh(part.mesh, placement), part.materialPath});
                if (parts.back().mesh.light) parts.back().mesh.light->copy += contents.meshLightCopies;
            }
            contents.meshLightCopies += inner.meshLightCopies;
            for (const PrototypeContents::Subdivided& sub : inner.subdivided)
                contents.subdivided.push_back({sub.mesh, placement * sub.placement});
            for (const PrototypeCurves& c : inner.curves)
                contents.curves.push_back({transformCurves(c.curves, placement), c.materialPath});
            for (const PrototypePoints& p : inner.points)
                contents.points.push_back({pointsToWorld(p.points, placement), p.materialPath});
            for (render::LightDesc light : inner.lights) {
                light.transform = placement * light.transform;
                contents.lights.push_back(std::move(light));
            }
            contents.meshLights.insert(inner.meshLights.begin(), inner.meshLights.end());
        }
        return false;
    }
    if (contents.meshLights.contains(prim.path)) {
        for (std::size_t i = firstPart; i < parts.size(); ++i)
            parts[i].mesh.light =
                render::MeshLightDesc{.prim = prim.path, .lightToWorld = space, .copy = contents.meshLightCopies};
        contents.meshLightCopies += 1;
    }
    return true;
}

}  // namespace

PrototypeContents prototypeContents(const SyncContext& context, const std::string& root, bool includeRootTransform,
                                    int nesting) {
    PrototypeContents contents;
    const usd::PrimSpec* rootPrim = context.stage.prim(root);
    if (!rootPrim) {
        context.warn(root, "prototype prim does not exist");
        return contents;
    }
    std::map<std::string, Matrix4> spaces;  // prim path -> prim-to-prototype-root space
    usd::Stage::traverse(*rootPrim, [&](const usd::PrimSpec& prim) {
        try {
            return addToPrototype(context, prim, root, includeRootTransform, nesting, spaces, contents);
        } catch (const MissingAssetError&) {
            throw;
        } catch (const SceneError& e) {
            contents.malformed.push_back(skipMalformed(context, prim.path, e));
            return false;
        }
    });
    return contents;
}

}  // namespace fluence::delegate
