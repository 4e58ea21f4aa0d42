// UsdGeomMesh subdivision surfaces: read once, tessellated for the camera.
//
// A Mesh is a subdivision surface unless `subdivisionScheme` is "none" (USD's fallback is
// catmullClark). Reading it (at sync time) builds the OpenSubdiv topology (delegate/subdivision.h)
// from these attributes, and keeps the control points, displayColor and material assignment:
// | attribute                        | fallback        | notes                                    |
// |----------------------------------|-----------------|------------------------------------------|
// | subdivisionScheme                | catmullClark    | catmullClark, loop, bilinear, none       |
// | interpolateBoundary              | edgeAndCorner   |                                          |
// | faceVaryingLinearInterpolation   | cornersPlus1    |                                          |
// | triangleSubdivisionRule          | catmullClark    |                                          |
// | creaseIndices/Lengths/Sharpnesses| none            |                                          |
// | cornerIndices/Sharpnesses        | none            |                                          |
// | holeIndices                      | none            | faces with no surface                    |
// | orientation                      | rightHanded     | leftHanded faces are reversed            |
// | primvars:displayColor            | none            | any interpolation, indexed or not        |
// | normals, primvars:normals        | —               | ignored, as USD says for subdivision     |
// |                                  |                 | surfaces: the limit normals shade        |
// | other primvars (st, ...)         | none            | every interpolation; face-varying ones   |
// |                                  |                 | refined by SubdivisionSurface            |
//
// Tessellating (whenever the scene is described) dices every base edge for the camera
// (delegate/dicing.h) as the mesh's placements put it in the world, takes the largest count over
// the placements (a prototype has one per instance; the 16 nearest the camera are used), and
// evaluates the limit surface: positions, shading normals (the limit normal of each triangle's
// own face) and displayColor. A material's UsdPreviewSurface `displacement` (a constant or a
// texture) moves each limit point along its limit normal by that many object units, and the
// shading normals become the displaced surface's (delegate/displacement.h). The result is split by
// material like any mesh.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/matrix.h"
#include "delegate/dicing.h"
#include "delegate/geom_subset.h"
#include "delegate/material_adapter.h"
#include "delegate/primvar.h"
#include "delegate/subdivision.h"

namespace fluence::delegate {

class SubdivisionMesh {
public:
    // Whether the mesh is subdivided (its subdivisionScheme is not "none").
    static bool isSubdivided(const usd::PrimSpec& mesh, double time);
    // Reads a subdivided mesh. Raises SceneError naming the prim on bad topology or primvars.
    SubdivisionMesh(const usd::Stage& stage, const usd::PrimSpec& mesh, double time, const ColorConverter& convertColor,
                    const std::function<void(const std::string&)>& warn);

    // The same mesh with new control points (an edit of `points` alone): the OpenSubdiv topology
    // is shared, not rebuilt. Raises SceneError when the point count changed.
    std::shared_ptr<const SubdivisionMesh> withPoints(const usd::PrimSpec& mesh, double time) const;
    const SubdivisionSurface& surface() const { return *surface_; }

    const std::string& path() const { return path_; }
    // The materials its faces bind ("" for none).
    std::vector<std::string> materialPaths() const;
    // The object-space parts, diced for the camera as `placements` (object to world) put the mesh.
    std::vector<MeshPart> tessellate(const std::vector<Matrix4>& placements, const DicingContext& context) const;

private:
    std::vector<int> segmentsFor(const std::vector<Matrix4>& placements, const DicingContext& context,
                                 float scale) const;
    render::MeshDesc meshFrom(const SubdivisionSurface::Result& result, const DicingContext& context) const;
    // Moves the tessellation's points by their materials' displacement (delegate/displacement.h).
    void displace(render::MeshDesc& mesh, const SubdivisionSurface::Result& result, const DicingContext& context) const;

    std::string path_;
    std::shared_ptr<const SubdivisionSurface> surface_;
    std::vector<Vec3f> points_;  // object space
    float dicingRate_ = 0.0f;    // primvars:fluence:dicingRate, 0 when not authored
    // A primvar carried through refinement (displayColor, st, ...), by its interpolation.
    struct RefinedPrimvar {
        std::string name;
        int components = 3;
        enum class Source { Constant, Uniform, FaceVarying, Vertex } source = Source::Constant;
        int channel = 0;            // FaceVarying: the surface's faceVarying channel; Vertex: into vertexData_
        std::vector<float> values;  // Constant: one element; Uniform: one per face
    };
    void addPrimvar(const Primvar& pv, std::vector<float> values, const SubdivisionTopology& topology, bool leftHanded,
                    std::vector<FaceVaryingData>& faceVarying);
    // The values of `pv` at triangle corner c of a tessellation.
    const float* cornerValues(const RefinedPrimvar& pv, const SubdivisionSurface::Result& result,
                              const render::MeshDesc& mesh, std::size_t c) const;
    std::vector<RefinedPrimvar> primvars_;
    std::vector<VertexData> vertexData_;
    int displayColor_ = -1;  // into primvars_: displayColor, already in the rendering space
    MaterialAssignment materials_;
};

}  // namespace fluence::delegate
