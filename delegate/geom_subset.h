// UsdGeomSubset per-face materials: a Mesh -> one render::MeshDesc per bound material.
//
// The subsets read are the Mesh's direct children of type GeomSubset (defined and active) whose
// familyName is "materialBind", as UsdShade reads them. Attributes read:
// | attribute        | fallback | notes                                                        |
// |------------------|----------|---------------------------------------------------------------|
// | familyName       | ""       | other families carry no materials; a binding on one warns     |
// | elementType      | "face"   | other element types warn and the subset is ignored            |
// | indices          | []       | authored faces (into faceVertexCounts, holes included)        |
// | material:binding | —        | resolved as for any prim (boundMaterialPath), so a subset     |
// |                  |          | without one, or under a strongerThanDescendants binding, gets |
// |                  |          | its ancestors' material                                        |
// A face index outside the mesh raises SceneError naming the subset. A face listed in several
// materialBind subsets warns and keeps the first subset's material (authored order). Faces in no
// subset keep the mesh's own binding.
//
// The mesh is split into one MeshDesc per distinct material, sharing nothing: each part holds the
// points its triangles use and their per-corner normals and colours. The part holding the faces in
// no subset comes first and is named after the mesh; every other part is named after the first
// subset that contributes to it. Parts without triangles are dropped. A mesh without materialBind
// subsets is one part, exactly meshFromPrim's MeshDesc.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "core/matrix.h"
#include "render/scene_description.h"
#include "scene/stage.h"

namespace fluence::delegate {

struct MeshPart {
    render::MeshDesc mesh;
    std::string materialPath;  // the bound material, "" for none
};

// Which material each face of a mesh gets: the mesh's own binding and its materialBind subsets.
struct MaterialAssignment {
    struct Subset {
        std::string path;
        std::string materialPath;
        std::vector<std::size_t> faces;
    };
    static constexpr int kNoSubset = -1;
    std::string meshMaterial;
    std::vector<Subset> subsets;
    std::vector<int> subsetOfFace;  // per authored face, when there are subsets: a subset or kNoSubset
};

// Reads the assignment of a mesh with `faceCount` authored faces; warns about subsets that
// overlap (the earlier keeps the face) or carry no material.
MaterialAssignment readMaterialAssignment(const usd::Stage& stage, const usd::PrimSpec& mesh, double time,
                                          std::size_t faceCount, const std::function<void(const std::string&)>& warn);

// Splits a triangulated mesh into its parts by the assignment (see the top of this file).
struct TriangulatedMesh;
std::vector<MeshPart> splitByMaterial(TriangulatedMesh&& whole, const MaterialAssignment& assignment);

// `convertColor` maps an authored colour (with the attribute's colorSpace, "" if none) into the
// rendering space; `warn` reports a problem that does not stop the render. `velocityFrame`: see
// DelegateOptions::velocityFrame (delegate/motion_samples.h).
std::vector<MeshPart> meshPartsFromPrim(const usd::Stage& stage, const usd::PrimSpec& mesh, double time,
                                        const Matrix4& toWorld,
                                        const std::function<RGB(const RGB&, const std::string&)>& convertColor,
                                        const std::function<void(const std::string&)>& warn,
                                        double velocityFrame = usd::kDefaultTime);

}  // namespace fluence::delegate
