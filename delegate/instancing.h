// Instancing: prototypes read once, and the transforms that place them.
//
// USD has two mechanisms, and the delegate maps both onto render::PrototypeDesc + InstanceDesc
// (one Embree scene per prototype, one Embree instance per placement):
//
//  - Native instancing. An `instanceable` prim with composition arcs is an instance; the stage
//    marks it with `fluence:instancePrototype`, a key equal for every instance that USD would
//    give one prototype. The prototype is the instance's descendants, read once (from the first
//    instance in path order) in the instance prim's space; each instance places it with its own
//    world transform. As in USD, prims inside an instance are instance proxies: read-only.
//
//  - UsdGeomPointInstancer. `prototypes` targets prototype root prims (ordered); instance i
//    places prototypes[protoIndices[i]], its geometry in the root's space with the root's own
//    transform included (USD's default IncludeProtoXform), by
//        instancer world * translate(positions[i]) * rotate(orientations[i]) * scale(scales[i]).
//    | attribute      | type     | notes                                                        |
//    |----------------|----------|--------------------------------------------------------------|
//    | protoIndices   | int[]    | required; an index outside `prototypes` skips the instance  |
//    | positions      | point3f[]| required, one per instance                                  |
//    | orientations   | quath[]  | optional (`orientationsf`, quatf[], when it is not authored),|
//    |                |          | real part first, normalised                                  |
//    | scales         | float3[] | optional                                                     |
//    | ids            | int64[]  | optional: the ids `invisibleIds` and `inactiveIds` name     |
//    | invisibleIds   | int64[]  | hidden instances (ids, or indices when `ids` is absent)      |
//    | inactiveIds    | metadata | int64 list op: deactivated instances, as invisibleIds        |
//    Arrays of the wrong length are warned about: without usable positions the instancer
//    places nothing; a bad orientations or scales array is ignored. Everything below a
//    PointInstancer is rendered only through it. `velocities`, `accelerations` and
//    `angularVelocities` move the instances at a motion step (delegate/motion_samples.h).
//
// A prototype holds meshes (subdivision surfaces among them), implicit surfaces, BasisCurves,
// NurbsCurves and Points, and lights (each instance places its own copy of each light). A PointInstancer nested inside a prototype is
// expanded into copies there (Embree is built with one instance level); nesting deeper than
// kMaxPrototypeNesting is cut with a warning. Read at a motion step (SyncContext::velocityFrame
// set), its points that are not time-sampled move by their velocities, as outside prototypes: a
// prototype deforms alike in all its instances (skinned, time-sampled or velocity-moved points,
// transforms or a point instancer inside it) and stays shared, its time steps gathered by
// delegate/motion_steps.h.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "delegate/geom_subset.h"
#include "delegate/imageable.h"
#include "delegate/material_adapter.h"
#include "delegate/mesh_light.h"
#include "delegate/prim_reader.h"
#include "delegate/subdivision_mesh.h"
#include "delegate/sync_context.h"
#include "render/curves_description.h"
#include "render/points_description.h"
#include "scene/stage.h"

namespace fluence::delegate {

inline constexpr int kMaxPrototypeNesting = 8;

// A prototype's curve set or point set, in the prototype root's space, and its bound material
// ("" for none).
struct PrototypeCurves {
    render::CurvesDesc curves;
    std::string materialPath;
};
struct PrototypePoints {
    render::PointsDesc points;
    std::string materialPath;
};

// The native-instancing prototype key of an instance prim, "" when the prim is not an instance.
std::string instancePrototypeKey(const usd::PrimSpec& prim);

// The prim paths a PointInstancer's `prototypes` relationship targets, in order.
std::vector<std::string> pointInstancerPrototypes(const usd::PrimSpec& instancer);

struct PointInstances {
    struct Instance {
        int prototype = 0;                        // index into `prototypes`
        Matrix4 transform = Matrix4::identity();  // prototype root space -> instancer space
        long long id = 0;                         // its `ids` entry, else its index
    };
    std::vector<std::string> prototypes;
    std::vector<Instance> instances;  // visible, active instances with a valid prototype, in order
};

// `motion`, when given, moves the instances by their velocities at a motion step (its velocityFrame,
// delegate/motion_samples.h).
PointInstances pointInstancesFromPrim(const PrimReader& instancer, const std::function<void(const std::string&)>& warn,
                                      const SyncContext* motion = nullptr);

// Every mesh, implicit surface (mesh lights among them), curve set, point set and UsdLux light at or below `root` (defined, active and imaged),
// in the root's space; with `includeRootTransform`, the root's own local transform applies too.
// Subdivision meshes are kept unTessellated, with their placement in the root's space: they are
// diced for the camera when the scene is described. Lights are placed once per instance (a
// light's LightDesc::transform is all that places it); a native prototype (`includeRootTransform`
// false) holds only those of the point instancers inside it, since the render index already holds
// its own lights as instance proxies. A malformed prim (render_index.h) is left out with its
// subtree, and the rest kept; with SyncContext::strict its SceneError is raised.
struct PrototypeContents {
    struct Subdivided {
        std::shared_ptr<const SubdivisionMesh> mesh;
        Matrix4 placement;  // mesh object space -> prototype root space
    };
    std::vector<MeshPart> parts;
    std::vector<Subdivided> subdivided;
    std::vector<PrototypeCurves> curves;
    std::vector<PrototypePoints> points;
    std::vector<render::LightDesc> lights;  // transform: light space -> prototype root space
    // The UsdLux mesh lights among them (delegate/mesh_light.h), by prim path: their parts carry a
    // MeshDesc::light naming the prim, with lightToWorld its space in the prototype, which
    // finishMeshLights completes once the parts' materials are known.
    std::map<std::string, MeshLight> meshLights;
    int meshLightCopies = 0;               // the MeshLightDesc::copy numbers its parts use: 0 to this, exclusive
    std::vector<MalformedPrim> malformed;  // left out, each with one warning (an error when strict)
    bool posedByAnimation = false;         // a skinned prim's pose changes over time (its animation may lie outside)
};
PrototypeContents prototypeContents(const SyncContext& context, const std::string& root, bool includeRootTransform,
                                    int nesting = 0);

}  // namespace fluence::delegate
