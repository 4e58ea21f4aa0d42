#include "delegate/skel_binding.h"

#include <algorithm>
#include <map>

#include "delegate/prim_copy.h"
#include "delegate/primvar.h"
#include "delegate/render_index.h"
#include "delegate/skel_blend_shapes.h"
#include "delegate/skel_skeleton.h"
#include "delegate/skel_skinning.h"

namespace fluence::delegate {

namespace {

constexpr const char* kJointIndices = "primvars:skel:jointIndices";
constexpr const char* kJointWeights = "primvars:skel:jointWeights";

bool hasTimeSamples(const usd::PrimSpec& prim) {
    for (const usd::AttributeSpec& a : prim.attributes)
        if (a.timeSamples.size() > 1) return true;
    return false;
}

bool hasTargets(const usd::PrimSpec& prim, const std::string& name) {
    const usd::RelationshipSpec* r = prim.relationship(name);
    return r && !r->blocked && !r->targets.empty();
}

// The path of the nearest SkelRoot above `path`, or "" when there is none.
std::string skelRootAbove(const usd::Stage& stage, const std::string& path) {
    for (std::string p = parentPath(path); p != "/"; p = parentPath(p))
        if (const usd::PrimSpec* prim = stage.prim(p); prim && prim->typeName == "SkelRoot") return p;
    return "";
}

// The nearest prim from `path` up to `root` (both included) for which `authors` holds.
template <typename Authors>
const usd::PrimSpec* nearest(const usd::Stage& stage, const std::string& path, const std::string& root,
                             Authors&& authors) {
    for (std::string p = path;; p = parentPath(p)) {
        if (const usd::PrimSpec* prim = stage.prim(p); prim && authors(*prim)) return prim;
        if (p == root || p == "/") return nullptr;
    }
}

// The first target of relationship `name` on `owner`, resolved to the prim it names; raises
// SceneError naming `owner` unless it is of type `type`.
const usd::PrimSpec& target(const usd::Stage& stage, const usd::PrimSpec& owner, const std::string& name,
                            const std::string& type) {
    const std::string path = resolveTargetPath(owner.path, owner.relationship(name)->targets.front());
    const usd::PrimSpec* prim = stage.prim(path);
    if (!prim) throw SceneError(owner.path + ": " + name + " targets " + path + ", which does not exist");
    if (prim->typeName != type)
        throw SceneError(owner.path + ": " + name + " targets " + path + ", a " +
                         (prim->typeName.empty() ? "typeless prim" : prim->typeName) + ", not a " + type);
    return *prim;
}

JointInfluences readInfluences(const usd::PrimSpec& indicesOwner, const usd::PrimSpec* weightsOwner, double time) {
    const PrimReader indices(indicesOwner, time);
    if (!weightsOwner) indices.fail(std::string(kJointIndices) + " is authored but " + kJointWeights + " is not");
    JointInfluences influences;
    for (double i : indices.numbers(kJointIndices, 1).value_or(std::vector<double>{}))
        influences.indices.push_back(static_cast<int>(i));
    influences.weights = PrimReader(*weightsOwner, time).numbers(kJointWeights, 1).value_or(std::vector<double>{});
    const usd::MetadataEntry* size = usd::findMetadata(indicesOwner.attribute(kJointIndices)->metadata, "elementSize");
    influences.perPoint = size ? static_cast<int>(size->value.asDouble().value_or(1.0)) : 1;
    const std::string interpolation = indices.attributeMetadata(kJointIndices, "interpolation").value_or("constant");
    if (interpolation != "constant" && interpolation != "vertex")
        indices.fail(std::string(kJointIndices) + " has " + interpolation +
                     " interpolation; UsdSkel takes constant or vertex");
    influences.constant = interpolation == "constant";
    return influences;
}

// Which point each authored normal follows, or nullopt when the normals cannot be skinned.
std::optional<std::vector<std::size_t>> normalPoints(const Primvar& normals, const PrimReader& mesh,
                                                     std::size_t pointCount) {
    if (!normals.indices.empty()) return std::nullopt;
    const std::size_t count = normals.values.size() / 3;
    std::vector<std::size_t> pointOf;
    if (normals.interpolation == "vertex" || normals.interpolation == "varying") {
        if (count != pointCount) return std::nullopt;
        for (std::size_t i = 0; i < count; ++i) pointOf.push_back(i);
        return pointOf;
    }
    if (normals.interpolation != "faceVarying") return std::nullopt;
    const std::vector<double> faceVertices = mesh.numbers("faceVertexIndices", 1).value_or(std::vector<double>{});
    if (faceVertices.size() != count) return std::nullopt;
    for (double p : faceVertices) {
        if (p < 0 || p >= static_cast<double>(pointCount)) return std::nullopt;
        pointOf.push_back(static_cast<std::size_t>(p));
    }
    return pointOf;
}

std::vector<Vec3d> vectors(const std::vector<double>& n) {
    std::vector<Vec3d> out;
    for (std::size_t i = 0; i + 2 < n.size(); i += 3) out.push_back({n[i], n[i + 1], n[i + 2]});
    return out;
}

std::vector<double> numbers(const std::vector<Vec3d>& v) {
    std::vector<double> out;
    out.reserve(3 * v.size());
    for (const Vec3d& x : v) out.insert(out.end(), {x.x, x.y, x.z});
    return out;
}

// The mesh's blend shapes applied at the pose's weights.
bool applyBlendShapes(const usd::Stage& stage, const usd::PrimSpec& mesh, double time, const SkeletonPose& pose,
                      const Warn& warn, std::vector<Vec3d>& points, std::vector<Vec3d>* normals) {
    if (!hasTargets(mesh, "skel:blendShapeTargets")) return false;
    const PrimReader reader(mesh, time);
    const std::vector<std::string> names = reader.strings("skel:blendShapes").value_or(std::vector<std::string>{});
    const std::vector<std::string>& targets = mesh.relationship("skel:blendShapeTargets")->targets;
    if (names.size() != targets.size())
        reader.fail("has " + std::to_string(names.size()) + " skel:blendShapes but " + std::to_string(targets.size()) +
                    " skel:blendShapeTargets");
    std::map<std::string, double> weights;
    for (std::size_t i = 0; i < pose.blendShapes.size(); ++i)
        weights.emplace(pose.blendShapes[i], pose.blendShapeWeights[i]);
    bool animated = false;
    for (std::size_t i = 0; i < names.size(); ++i) {
        const std::string path = resolveTargetPath(mesh.path, targets[i]);
        const usd::PrimSpec* prim = stage.prim(path);
        if (!prim || prim->typeName != "BlendShape")
            reader.fail("skel:blendShapeTargets[" + std::to_string(i) + "] " + path + " is not a BlendShape");
        animated = animated || hasTimeSamples(*prim);
        const BlendShape shape = readBlendShape(PrimReader(*prim, time), [&](const std::string& m) { warn(path, m); });
        if (std::optional<std::string> problem = shape.problem(points.size())) reader.fail(*problem);
        auto it = weights.find(names[i]);
        if (it != weights.end()) shape.apply(it->second, points, normals);
    }
    return animated;
}

// What skinning moves: points, and normals that follow point normalPoint[i] (per point when
// `perPointNormals`, so blend shapes' normal offsets apply to them).
struct Deformable {
    std::vector<Vec3d> points;
    std::vector<Vec3d> normals;
    std::vector<std::size_t> normalPoint;
    bool perPointNormals = false;
};

// The nearest prim from `path` up to `root` authoring attribute `name`.
const usd::PrimSpec* nearestAuthoring(const usd::Stage& stage, const std::string& path, const std::string& root,
                                      const char* name) {
    return nearest(stage, path, root, [name](const usd::PrimSpec& p) { return p.attribute(name) != nullptr; });
}

// The prims a prim's UsdSkel binding below its SkelRoot reads: each binding attribute's nearest
// owner, the skeleton and its animation (nullptr where there is none).
struct BindingSources {
    const usd::PrimSpec* indices = nullptr;  // primvars:skel:jointIndices
    const usd::PrimSpec* weights = nullptr;  // primvars:skel:jointWeights
    const usd::PrimSpec* joints = nullptr;   // skel:joints
    const usd::PrimSpec* geomBind = nullptr;
    const usd::PrimSpec* method = nullptr;  // primvars:skel:skinningMethod
    const usd::PrimSpec* skeletonOwner = nullptr;
    const usd::PrimSpec* skeleton = nullptr;
    const usd::PrimSpec* animationOwner = nullptr;
    const usd::PrimSpec* animation = nullptr;
};

// `prim`'s binding below `root`, or nullopt when nothing of UsdSkel deforms it; raises SceneError
// when its skeleton or animation cannot be found.
std::optional<BindingSources> bindingSources(const usd::Stage& stage, const usd::PrimSpec& prim,
                                             const std::string& root) {
    BindingSources s;
    s.indices = nearestAuthoring(stage, prim.path, root, kJointIndices);
    if (!s.indices && !hasTargets(prim, "skel:blendShapeTargets")) return std::nullopt;
    s.skeletonOwner =
        nearest(stage, prim.path, root, [](const usd::PrimSpec& p) { return hasTargets(p, "skel:skeleton"); });
    if (!s.skeletonOwner)
        PrimReader(prim, 0.0).fail(
            "has joint influences or blend shapes but no skel:skeleton is bound to it or above it in " + root);
    s.skeleton = &target(stage, *s.skeletonOwner, "skel:skeleton", "Skeleton");
    s.animationOwner = nearest(stage, s.skeleton->path, "/",
                               [](const usd::PrimSpec& p) { return hasTargets(p, "skel:animationSource"); });
    if (s.animationOwner) s.animation = &target(stage, *s.animationOwner, "skel:animationSource", "SkelAnimation");
    s.weights = nearestAuthoring(stage, prim.path, root, kJointWeights);
    s.joints = nearestAuthoring(stage, prim.path, root, "skel:joints");
    s.geomBind = nearestAuthoring(stage, prim.path, root, "primvars:skel:geomBindTransform");
    s.method = nearestAuthoring(stage, prim.path, root, "primvars:skel:skinningMethod");
    return s;
}

// Poses `shape`, the geometry of `prim`, by the prim's UsdSkel binding below `root`, into the
// prim's own space. False when nothing of UsdSkel deforms the prim; raises SceneError when its
// binding cannot apply. `animated`: whether the pose changes with time.
bool deform(const usd::Stage& stage, const usd::PrimSpec& prim, const std::string& root, double time, const Warn& warn,
            Deformable& shape, bool& animated) {
    const std::optional<BindingSources> sources = bindingSources(stage, prim, root);
    if (!sources) return false;  // nothing of UsdSkel deforms it
    const usd::PrimSpec& skeletonPrim = *sources->skeleton;
    const usd::PrimSpec* animation = sources->animation;
    auto warnAt = [&](const std::string& path) { return [&warn, path](const std::string& m) { warn(path, m); }; };
    const Skeleton skeleton = readSkeleton(PrimReader(skeletonPrim, time), warnAt(skeletonPrim.path));
    const std::optional<PrimReader> animationReader =
        animation ? std::optional<PrimReader>(std::in_place, *animation, time) : std::nullopt;
    const SkeletonPose skeletonPose =
        poseSkeleton(skeleton, animationReader ? &*animationReader : nullptr, warnAt(skeletonPrim.path));

    animated = hasTimeSamples(skeletonPrim) || (animation && hasTimeSamples(*animation));
    animated = applyBlendShapes(stage, prim, time, skeletonPose, warn, shape.points,
                                shape.perPointNormals ? &shape.normals : nullptr) ||
               animated;
    if (!sources->indices) return true;  // blend shapes alone: the prim's own space

    const JointInfluences influences = readInfluences(*sources->indices, sources->weights, time);
    std::vector<Matrix4> skinning = skeletonPose.skinning;
    if (const usd::PrimSpec* jointsOwner = sources->joints) {
        std::map<std::string, std::size_t> index;
        for (std::size_t j = 0; j < skeleton.joints.size(); ++j) index.emplace(skeleton.joints[j], j);
        skinning.clear();
        for (const std::string& name :
             PrimReader(*jointsOwner, time).strings("skel:joints").value_or(std::vector<std::string>{})) {
            auto it = index.find(name);
            skinning.push_back(it == index.end() ? Matrix4::identity() : skeletonPose.skinning[it->second]);
        }
    }
    if (std::optional<std::string> problem = influences.problem(shape.points.size(), skinning.size()))
        PrimReader(*sources->indices, time).fail(*problem);
    Matrix4 geomBind = Matrix4::identity();
    if (const usd::PrimSpec* owner = sources->geomBind)
        if (auto m = PrimReader(*owner, time).numbers("primvars:skel:geomBindTransform", 16); m && m->size() == 16)
            geomBind = Matrix4::fromUsdRowMajor(m->data());
    SkinningMethod method = SkinningMethod::ClassicLinear;
    if (const usd::PrimSpec* owner = sources->method) {
        const std::string name = PrimReader(*owner, time).token({"primvars:skel:skinningMethod"}, "classicLinear");
        if (name == "dualQuaternion")
            method = SkinningMethod::DualQuaternion;
        else if (name != "classicLinear")
            warn(owner->path, "primvars:skel:skinningMethod '" + name +
                                  "' is not classicLinear or dualQuaternion; classicLinear used");
    }
    skinPoints(method, geomBind, skinning, influences, shape.points);
    skinNormals(method, geomBind, skinning, influences, shape.normalPoint, shape.normals);
    const std::optional<Matrix4> fromWorld = worldTransformOf(stage, prim.path, time, warn).matrix.inverse();
    if (!fromWorld)
        PrimReader(prim, time).fail("its transform is not invertible, so its skinned points cannot be placed");
    const Matrix4 toPrim =
        *fromWorld * worldTransformOf(stage, skeletonPrim.path, time, warn).matrix;  // skeleton space -> the prim's
    for (Vec3d& p : shape.points) p = toPrim.transformPoint(p);
    for (Vec3d& n : shape.normals) n = toPrim.transformNormal(n);
    return true;
}

std::optional<SkinnedPose> meshPose(const usd::Stage& stage, const usd::PrimSpec& mesh, const std::string& root,
                                    double time, const Warn& warn) {
    const PrimReader reader(mesh, time);
    Deformable shape;
    shape.points = vectors(reader.numbers("points", 3).value_or(std::vector<double>{}));
    const char* normalsName = reader.value("primvars:normals") ? "primvars:normals" : "normals";
    std::optional<Primvar> normalsPrimvar = readPrimvar(reader, normalsName, "vertex");
    std::optional<std::vector<std::size_t>> pointOf =
        normalsPrimvar ? normalPoints(*normalsPrimvar, reader, shape.points.size()) : std::nullopt;
    if (pointOf) {
        shape.normals = vectors(normalsPrimvar->values);
        shape.normalPoint = std::move(*pointOf);
        shape.perPointNormals = normalsPrimvar->interpolation != "faceVarying";
    }
    SkinnedPose result;
    if (!deform(stage, mesh, root, time, warn, shape, result.animated)) return std::nullopt;
    result.points = numbers(shape.points);
    if (pointOf) result.normals = numbers(shape.normals);
    result.normalsName = normalsName;
    return result;
}

// Runs `pose`, turning a binding that cannot apply into a warning naming the prim (nullopt).
template <typename Pose>
auto warnedPose(const usd::PrimSpec& prim, const Warn& warn, Pose&& pose) -> decltype(pose()) {
    try {
        return pose();
    } catch (const MissingAssetError&) {
        throw;
    } catch (const SceneError& e) {
        warn(prim.path, std::string("UsdSkel binding not applied, the ") + (prim.typeName == "Mesh" ? "mesh" : "prim") +
                            " renders in its rest pose: " + e.what());
        return {};
    }
}

}  // namespace

std::optional<SkinnedPose> skinnedPose(const usd::Stage& stage, const usd::PrimSpec& mesh, double time,
                                       const Warn& warn) {
    // Bindings outside a SkelRoot mean nothing; an unbound mesh's points are not read here.
    if (!isSkelDeformed(stage, mesh)) return std::nullopt;
    const std::string root = skelRootAbove(stage, mesh.path);
    return warnedPose(mesh, warn, [&] { return meshPose(stage, mesh, root, time, warn); });
}

std::optional<bool> skinSurface(const usd::Stage& stage, const usd::PrimSpec& prim, double time, const Warn& warn,
                                render::MeshDesc& surface) {
    const std::string root = skelRootAbove(stage, prim.path);
    if (root.empty()) return std::nullopt;
    return warnedPose(prim, warn, [&]() -> std::optional<bool> {
        Deformable shape;
        for (const Vec3f& p : surface.positions) shape.points.push_back(Vec3d(p));
        for (std::size_t c = 0; c < surface.cornerNormals.size(); ++c) {
            shape.normals.push_back(Vec3d(surface.cornerNormals[c]));
            shape.normalPoint.push_back(surface.indices[c]);
        }
        bool animated = false;
        if (!deform(stage, prim, root, time, warn, shape, animated)) return std::nullopt;
        for (std::size_t i = 0; i < shape.points.size(); ++i) surface.positions[i] = Vec3f(shape.points[i]);
        for (std::size_t c = 0; c < shape.normals.size(); ++c)
            surface.cornerNormals[c] = Vec3f(normalize(shape.normals[c]));
        return animated;
    });
}

bool isSkelDeformed(const usd::Stage& stage, const usd::PrimSpec& prim) {
    const std::string root = skelRootAbove(stage, prim.path);
    return !root.empty() &&
           (hasTargets(prim, "skel:blendShapeTargets") || nearestAuthoring(stage, prim.path, root, kJointIndices));
}

std::vector<std::string> skelInputsOutside(const usd::Stage& stage, const usd::PrimSpec& prim,
                                           const std::string& subtree) {
    const std::string root = skelRootAbove(stage, prim.path);
    if (root.empty()) return {};
    std::optional<BindingSources> sources;
    try {
        sources = bindingSources(stage, prim, root);
    } catch (const SceneError&) {
        return {};  // the binding cannot apply: the prim renders in its rest pose wherever it is
    }
    if (!sources) return {};
    std::vector<std::string> read;
    for (const usd::PrimSpec* p :
         {sources->indices, sources->weights, sources->joints, sources->geomBind, sources->method,
          sources->skeletonOwner, sources->skeleton, sources->animationOwner, sources->animation})
        if (p) read.push_back(p->path);
    if (const usd::RelationshipSpec* shapes = prim.relationship("skel:blendShapeTargets"))
        for (const std::string& t : shapes->targets) read.push_back(resolveTargetPath(prim.path, t));
    std::erase_if(read, [&](const std::string& path) { return isAtOrBelow(path, subtree); });
    std::sort(read.begin(), read.end());
    read.erase(std::unique(read.begin(), read.end()), read.end());
    return read;
}

std::unique_ptr<usd::PrimSpec> posedMeshSpec(const usd::PrimSpec& mesh, const SkinnedPose& pose) {
    std::unique_ptr<usd::PrimSpec> posed = copyPrim(mesh);
    std::erase_if(posed->attributes, [&](const usd::AttributeSpec& a) {
        if (a.name.starts_with("primvars:skel:")) return true;
        const bool normals = a.name == "normals" || a.name.starts_with("primvars:normals");
        return normals && (!pose.normals || a.name != pose.normalsName);
    });
    setArray(*posed, "points", "point3f[]", pose.points, 3);
    if (pose.normals) setArray(*posed, pose.normalsName, "normal3f[]", *pose.normals, 3);
    return posed;
}

}  // namespace fluence::delegate
