// Limit-surface tessellation of subdivision meshes (UsdGeomMesh `subdivisionScheme` other than
// "none"), on OpenSubdiv 3.5.
//
// What it does. A SubdivisionSurface is built once from a mesh's topology in plain structs (no USD
// prims: the mesh adapter reads the attributes and hands them over). It maps the USD tokens to
// OpenSubdiv's Sdc options, builds a Far::TopologyRefiner with the creases, corners and holes,
// and a Bfr::RefinerSurfaceFactory over it. `tessellate` then evaluates every face's exact limit
// surface (Bfr::Surface: positions, first derivatives, normals; vertex, varying and face-varying
// primvars) on the points of a Bfr::Tessellation pattern whose segment count is given per base
// edge, so camera-driven dicing can pick a rate per edge and adjacent faces still agree. Nothing
// here writes a subdivision rule: OpenSubdiv does all of it. The interior rate of a face is the one
// Bfr::Tessellation infers from its edge rates. The limit surface is Bfr's default representation:
// regular faces are exact bicubic (Loop: quartic box-spline) patches; irregular faces are refined
// adaptively, 2 levels around smooth and 6 around sharp features, and end in Gregory patches, as in
// Far::PatchTable with Gregory end caps and infinitely sharp patches (the tests compare the two).
// One known consequence: at an infinitely sharp "dart" (a crease ending inside the surface) that
// representation differs slightly from the limit of uniform refinement (0.5% of a cube's size).
// A mesh without faces is valid and tessellates to nothing.
//
// USD token mapping (UsdGeomMesh attribute -> OpenSubdiv):
//
//   | USD attribute                    | token          | OpenSubdiv                               |
//   |----------------------------------|----------------|------------------------------------------|
//   | subdivisionScheme                | catmullClark   | Sdc::SCHEME_CATMARK (any face size)      |
//   |                                  | loop           | Sdc::SCHEME_LOOP (triangles only)        |
//   |                                  | bilinear       | Sdc::SCHEME_BILINEAR (any face size)     |
//   |                                  | none           | not subdivided: not this class's job     |
//   | interpolateBoundary              | none           | VTX_BOUNDARY_NONE: faces on a boundary   |
//   |                                  |                | have no limit surface (no triangles)     |
//   |                                  | edgeOnly       | VTX_BOUNDARY_EDGE_ONLY                   |
//   |                                  | edgeAndCorner  | VTX_BOUNDARY_EDGE_AND_CORNER (default)   |
//   | faceVaryingLinearInterpolation   | none           | FVAR_LINEAR_NONE                         |
//   |                                  | cornersOnly    | FVAR_LINEAR_CORNERS_ONLY                 |
//   |                                  | cornersPlus1   | FVAR_LINEAR_CORNERS_PLUS1 (default)      |
//   |                                  | cornersPlus2   | FVAR_LINEAR_CORNERS_PLUS2                |
//   |                                  | boundaries     | FVAR_LINEAR_BOUNDARIES                   |
//   |                                  | all            | FVAR_LINEAR_ALL                          |
//   | triangleSubdivisionRule          | catmullClark   | TRI_SUB_CATMARK (default)                |
//   |                                  | smooth         | TRI_SUB_SMOOTH                           |
//   | creaseIndices / creaseLengths /  |                | crease edges (vertex pairs of each       |
//   | creaseSharpnesses                |                | chain); one sharpness per crease or one  |
//   |                                  |                | per crease edge, as USD allows           |
//   | cornerIndices/cornerSharpnesses  |                | corner vertex sharpness                  |
//   | holeIndices                      |                | Far hole tags: no limit surface          |
//
// Sharpness 10 or more (including +infinity) is infinitely sharp, as in OpenSubdiv
// (Sdc::Crease::SHARPNESS_INFINITE); 0 or less is smooth; NaN is an error. Creasing is
// Sdc::CREASE_UNIFORM (UsdGeomMesh has no creaseMethod attribute). Unknown tokens and invalid
// topology (face sizes, out-of-range indices, a face using a point twice in a row, crease chains
// along pairs of points that are not mesh edges, Loop on non-triangles, mismatched array sizes)
// throw std::invalid_argument with a message naming the attribute and the element.
//
// Watertightness. Output vertices are shared by index, not merely by value, so Embree sees no
// crack between faces of different rates. The output vertex array is laid out in three blocks:
//   1. one vertex per base point used by a face with a limit surface (in point order);
//   2. per base edge (in edges() order), its `segments - 1` inner points, ordered from the edge's
//      lower-numbered point to its higher-numbered one (the key is (edge, segment position));
//   3. per face (in face order), the interior points of its tessellation pattern.
// Each shared point (blocks 1 and 2) is evaluated by one "owner" face, the lowest-numbered face
// with a limit surface that uses it; every other face refers to the same index. Both faces of an
// edge see the same segment count (it is the edge's), so their boundary points coincide.
// `normals`, `dPdu`, `dPdv` and `surfaceCoords` of a shared vertex are therefore the owner's.
// Where the limit surface is not smooth across an edge (infinitely sharp creases, where one face's
// normal is not the other's), use `cornerNormals`: each triangle corner gets the limit normal of
// the triangle's own face (OpenSubdiv issue #1347 is the same lesson). Shared indices make the mesh
// watertight; a ray tracer sees it so only with a watertight triangle test: Embree's is
// RTC_SCENE_FLAG_ROBUST. Its default test lets rays through exactly at shared edges and vertices
// (283 of 4000 rays aimed at a tessellated cube's seams; none in robust mode).
//
// Face-varying data (e.g. `st`). Face-varying values can be discontinuous at UV seams, so the
// output is indexed per triangle corner, like the input: Result::faceVarying[c] is a
// FaceVaryingData whose `indices` hold one value index per triangle corner (3 per triangle,
// parallel to `indices`) into its own `values`. Values are shared by index exactly where the
// face-varying topology is continuous: at a base point, corners sharing the input value index
// share one output value; along a base edge, faces whose input value indices at both edge ends
// match share the edge's points. So a seam stays a seam (different indices, different values) and
// a continuous edge is continuous bit for bit (the same index). A value shared by faces that are
// not contiguous around a point (rare) takes the lowest-numbered face's limit.
// One input value index used at different points (valid USD: indices only compress values; Maya
// writes it where a UV edge collapses) becomes one copy of the value per point before OpenSubdiv,
// whose face-varying topology assumes each value belongs to one point.
//
// Orientation. Bfr parameterizes a face with u along its first edge (point 0 to point 1) and v
// along its last (point 0 to the last point), so for a counter-clockwise face (USD's right-handed default) cross(dPdu, dPdv) and the output triangles'
// winding face the same way as the control face: front is counter-clockwise, as in the input. A
// caller with `orientation = "leftHanded"` reverses the faces' point order (or flips the results).
//
// Phase: used at sync time by the mesh adapter (topology is rebuilt only when the topology is
// dirty; `tessellate` runs whenever the points or rates change). `tessellate` is const and safe to
// call from several threads at once (the Bfr patch cache is guarded by a shared mutex).
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "core/vec.h"

namespace fluence::delegate {

struct SubdivisionTopology {
    enum class Scheme { CatmullClark, Loop, Bilinear };
    Scheme scheme = Scheme::CatmullClark;
    std::string interpolateBoundary = "edgeAndCorner";  // none, edgeOnly, edgeAndCorner
    std::string faceVaryingLinearInterpolation =
        "cornersPlus1";  // all, none, boundaries, cornersOnly, cornersPlus1, cornersPlus2
    std::string triangleSubdivisionRule = "catmullClark";  // catmullClark, smooth
    int pointCount = 0;
    std::vector<int> faceVertexCounts, faceVertexIndices;
    // USD semantics: creaseLengths[i] points of creaseIndices form crease i's chain; one sharpness
    // per crease, or one per crease edge (sum of (length - 1)).
    std::vector<int> creaseIndices, creaseLengths;
    std::vector<float> creaseSharpnesses;
    std::vector<int> cornerIndices;
    std::vector<float> cornerSharpnesses;
    std::vector<int> holeIndices;
};

// Per-face-vertex data (e.g. indexed `st` UVs): `values` holds `components` floats per element;
// `indices` one element per face-vertex (parallel to faceVertexIndices). Empty `indices` means
// one value per face-vertex (a non-indexed faceVarying primvar): every face then has its own
// values, so every edge is a seam.
struct FaceVaryingData {
    int components = 2;
    std::vector<float> values;
    std::vector<int> indices;
};

// Per-point data refined like the points: `vertex` primvars (smooth, like the positions) or, with
// `varying`, `varying` primvars (interpolated linearly over each face's parameterization).
struct VertexData {
    int components = 3;
    std::vector<float> values;  // components per point (pointCount points)
    bool varying = false;
};

class SubdivisionSurface {
public:
    // Builds the OpenSubdiv topology once. Throws std::invalid_argument on bad topology, bad
    // face-varying data or unknown tokens (see the top of this file).
    explicit SubdivisionSurface(SubdivisionTopology topology, std::vector<FaceVaryingData> faceVarying = {});
    ~SubdivisionSurface();
    SubdivisionSurface(SubdivisionSurface&&) noexcept;
    SubdivisionSurface& operator=(SubdivisionSurface&&) noexcept;
    SubdivisionSurface(const SubdivisionSurface&) = delete;
    SubdivisionSurface& operator=(const SubdivisionSurface&) = delete;

    const SubdivisionTopology& topology() const;

    // Every base edge as (point a, point b) with a < b, sorted (by a, then b). Per-edge segment
    // counts passed to tessellate() refer to this order.
    const std::vector<std::pair<int, int>>& edges() const;
    // The edges of face f in its own order (edge i runs from its point i to point i + 1), as
    // indices into edges().
    std::span<const int> faceEdges(int face) const;
    int faceCount() const;
    // False for holes and for faces without a limit surface (interpolateBoundary = none on a
    // boundary): such faces produce no triangles.
    bool faceHasLimitSurface(int face) const;

    // Where an output vertex was evaluated: its face and the (u, v) of the face's Bfr
    // parameterization (quads and Loop triangles: the unit square / triangle; other faces: Bfr's
    // quadrangulated sub-face layout).
    struct SurfaceCoord {
        std::uint32_t face = 0;
        float u = 0.0f, v = 0.0f;
    };

    struct Result {
        // Per output vertex (laid out as described above):
        std::vector<Vec3f> positions;  // limit positions
        // Unit limit normals, normalize(cross(dPdu, dPdv)) of the owner face. Where that is
        // undefined (parallel derivatives: coincident control points, a smooth valence-2 corner),
        // the area-weighted normal of the triangles around the vertex; never zero.
        std::vector<Vec3f> normals;
        std::vector<Vec3f> dPdu, dPdv;  // limit derivatives in the owner face's (u, v)
        std::vector<SurfaceCoord> surfaceCoords;
        std::vector<std::vector<float>> vertexData;  // per VertexData channel: components per vertex
        // Per triangle (3 indices each, wound as their faces; faces in order, holes give none):
        std::vector<std::uint32_t> indices;
        std::vector<std::uint32_t> triangleFaces;  // base face of each triangle
        // 3 per triangle: the limit normal of the triangle's own face at each corner (differs from
        // normals[] only where the surface is not smooth across a base edge or point).
        std::vector<Vec3f> cornerNormals;
        // Per input face-varying channel: its own values, indexed per triangle corner (indices
        // parallel to `indices`; see "Face-varying data" above).
        std::vector<FaceVaryingData> faceVarying;
    };

    // Tessellates every face with a limit surface with edgeSegments[i] segments on edges()[i]
    // (each in [1, kMaxEdgeSegments]). `points` holds the pointCount control points; each
    // vertexData channel holds components * pointCount values. Throws std::invalid_argument on
    // mismatched sizes or rates, std::length_error when the result would not fit 32-bit indices.
    Result tessellate(std::span<const Vec3f> points, std::span<const int> edgeSegments,
                      std::span<const VertexData> vertexData = {}) const;
    // 2^level segments on every edge (level in [0, 12]): an all-quad Catmull-Clark mesh gives
    // 2 * 4^level triangles per face, as `--subdiv-level N` expects.
    Result tessellateUniform(std::span<const Vec3f> points, int level,
                             std::span<const VertexData> vertexData = {}) const;

    static constexpr int kMaxEdgeSegments = 4096;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace fluence::delegate
