// SubdivisionSurface (Bfr evaluation and tessellation) against OpenSubdiv's other, independent
// limit evaluation path: a Far::TopologyRefiner built here from the same arrays, adaptively
// refined, a Far::PatchTable (B-spline patches, Gregory end caps, infinitely sharp patches, to
// level 6 around sharp and 2 around smooth features: the options Bfr's own patch builder uses)
// located with Far::PatchMap and evaluated with PatchTable::EvaluateBasis, in double; and
// Far::PrimvarRefiner::Limit, the exact limit at the base points.
//
// Tolerances: SubdivisionSurface evaluates in double and rounds each result to float once, and
// reports (u, v) as floats. So a position may differ from the double reference by half an ulp of
// its magnitude plus the effect of rounding (u, v) (half an ulp of each, times |dP/du|, |dP/dv|);
// the checks allow twice that bound (the double arithmetic of both paths is a million times
// smaller). A unit normal's components are rounded by at most 2^-25 each (an error of length at
// most sqrt(3) 2^-25), and the (u, v) rounding tilts it by a similar amount divided by the sine of
// the angle between the derivatives: 2^-21 / sine leaves a margin of about 4.
#include "delegate/subdivision.h"
#include "tests/delegate/subdivision_test_cage.h"

#include <gtest/gtest.h>

#include <opensubdiv/bfr/parameterization.h>
#include <opensubdiv/far/patchMap.h>
#include <opensubdiv/far/patchTable.h>
#include <opensubdiv/far/patchTableFactory.h>
#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/ptexIndices.h>
#include <opensubdiv/far/topologyDescriptor.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace fluence::delegate {
namespace {

namespace Far = OpenSubdiv::Far;
namespace Sdc = OpenSubdiv::Sdc;
namespace Bfr = OpenSubdiv::Bfr;

// A point OpenSubdiv's primvar machinery can combine.
struct Point {
    double p[3] = {0.0, 0.0, 0.0};
    void Clear() { p[0] = p[1] = p[2] = 0.0; }
    void AddWithWeight(const Point& src, double w) {
        for (int k = 0; k < 3; ++k) p[k] += w * src.p[k];
    }
    Vec3d vec() const { return {p[0], p[1], p[2]}; }
};

struct Case {
    std::string name;
    SubdivisionTopology topology;
    std::vector<Vec3f> points;
};

Sdc::SchemeType scheme(SubdivisionTopology::Scheme s) {
    return s == SubdivisionTopology::Scheme::Loop ? Sdc::SCHEME_LOOP : Sdc::SCHEME_CATMARK;
}

// The Far refiner for a test case, built here from the arrays (USD crease chains expanded to
// Far's vertex pairs; the cases give one sharpness per crease).
std::unique_ptr<Far::TopologyRefiner> farRefiner(const Case& c) {
    const SubdivisionTopology& t = c.topology;
    std::vector<int> creasePairs;
    std::vector<float> creaseWeights;
    for (std::size_t i = 0, start = 0; i < t.creaseLengths.size(); start += std::size_t(t.creaseLengths[i]), ++i)
        for (int k = 0; k + 1 < t.creaseLengths[i]; ++k) {
            creasePairs.insert(creasePairs.end(), {t.creaseIndices[start + k], t.creaseIndices[start + k + 1]});
            creaseWeights.push_back(t.creaseSharpnesses[i]);
        }
    Far::TopologyDescriptor desc;
    desc.numVertices = t.pointCount;
    desc.numFaces = int(t.faceVertexCounts.size());
    desc.numVertsPerFace = t.faceVertexCounts.data();
    desc.vertIndicesPerFace = t.faceVertexIndices.data();
    desc.numCreases = int(creaseWeights.size());
    desc.creaseVertexIndexPairs = creasePairs.data();
    desc.creaseWeights = creaseWeights.data();
    desc.numCorners = int(t.cornerIndices.size());
    desc.cornerVertexIndices = t.cornerIndices.data();
    desc.cornerWeights = t.cornerSharpnesses.data();
    desc.numHoles = int(t.holeIndices.size());
    desc.holeIndices = t.holeIndices.data();
    Sdc::Options options;
    options.SetVtxBoundaryInterpolation(t.interpolateBoundary == "edgeOnly"
                                            ? Sdc::Options::VTX_BOUNDARY_EDGE_ONLY
                                            : Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER);
    options.SetTriangleSubdivision(t.triangleSubdivisionRule == "smooth" ? Sdc::Options::TRI_SUB_SMOOTH
                                                                         : Sdc::Options::TRI_SUB_CATMARK);
    using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
    return std::unique_ptr<Far::TopologyRefiner>(Factory::Create(desc, Factory::Options(scheme(t.scheme), options)));
}

// Far's limit surface: adaptive patches to level 6 for sharp and 2 for smooth features, as Bfr's
// defaults, evaluated in double.
class FarLimit {
public:
    explicit FarLimit(const Case& c) : scheme_(scheme(c.topology.scheme)), refiner_(farRefiner(c)) {
        Far::TopologyRefiner::AdaptiveOptions adaptive(6);
        adaptive.SetSecondaryLevel(2);
        adaptive.useInfSharpPatch = true;
        adaptive.useSingleCreasePatch = false;
        refiner_->RefineAdaptive(adaptive);

        Far::PatchTableFactory::Options options(6);
        options.SetEndCapType(Far::PatchTableFactory::Options::ENDCAP_GREGORY_BASIS);
        options.useInfSharpPatch = true;
        options.useSingleCreasePatch = false;
        options.generateLegacySharpCornerPatches = false;
        options.SetPatchPrecision<double>();
        table_.reset(Far::PatchTableFactory::Create(*refiner_, options));
        map_ = std::make_unique<Far::PatchMap>(*table_);
        ptex_ = std::make_unique<Far::PtexIndices>(*refiner_);

        points_.resize(std::size_t(refiner_->GetNumVerticesTotal() + table_->GetNumLocalPoints()));
        for (std::size_t i = 0; i < c.points.size(); ++i)
            points_[i].p[0] = c.points[i].x, points_[i].p[1] = c.points[i].y, points_[i].p[2] = c.points[i].z;
        Far::PrimvarRefinerReal<double> primvars(*refiner_);
        Point* src = points_.data();
        for (int level = 1; level < refiner_->GetNumLevels(); ++level) {
            Point* dst = src + refiner_->GetLevel(level - 1).GetNumVertices();
            primvars.Interpolate(level, src, dst);
            src = dst;
        }
        // (PatchTable::ComputeLocalPointValues is for float stencils only.)
        if (auto* stencils = table_->GetLocalPointStencilTable<double>())
            stencils->UpdateValues(points_.data(), points_.data() + refiner_->GetNumVerticesTotal());
    }

    // Position and first derivatives at (u, v) of `face` in Bfr's parameterization. Faces Bfr splits
    // into sub-faces are several Ptex faces in Far, with the sub-face's normalized coordinates.
    void evaluate(int face, double u, double v, Vec3d& P, Vec3d& dPds, Vec3d& dPdt) const {
        Bfr::Parameterization param(scheme_, refiner_->GetLevel(0).GetFaceVertices(face).size());
        double uv[2] = {u, v}, st[2] = {u, v};
        int ptexFace = ptex_->GetFaceId(face);
        if (param.HasSubFaces()) ptexFace += param.ConvertCoordToNormalizedSubFace(uv, st);
        const Far::PatchTable::PatchHandle* handle = map_->FindPatch(ptexFace, st[0], st[1]);
        ASSERT_NE(handle, nullptr);
        double w[20], ws[20], wt[20];
        table_->EvaluateBasis(*handle, st[0], st[1], w, ws, wt);
        Far::ConstIndexArray cvs = table_->GetPatchVertices(*handle);
        P = dPds = dPdt = Vec3d(0.0);
        for (int i = 0; i < cvs.size(); ++i) {
            Vec3d x = points_[std::size_t(cvs[i])].vec();
            P += w[i] * x;
            dPds += ws[i] * x;
            dPdt += wt[i] * x;
        }
    }

private:
    Sdc::SchemeType scheme_;
    std::unique_ptr<Far::TopologyRefiner> refiner_;
    std::unique_ptr<Far::PatchTable> table_;
    std::unique_ptr<Far::PatchMap> map_;
    std::unique_ptr<Far::PtexIndices> ptex_;
    std::vector<Point> points_;
};

// Exact limit positions of the base points: refined uniformly until every semi-sharp feature has
// decayed (sharpness 2.5 at most below) and every Catmull-Clark face is a quad, then Far's limit
// masks at that level, read at each base point's descendant.
std::vector<Vec3d> farVertexLimits(const Case& c) {
    constexpr int kLevels = 3;
    auto refiner = farRefiner(c);
    Far::TopologyRefiner::UniformOptions uniform(kLevels);
    uniform.fullTopologyInLastLevel = true;  // limit masks need it
    refiner->RefineUniform(uniform);
    std::vector<Point> points(std::size_t(refiner->GetNumVerticesTotal()));
    for (std::size_t i = 0; i < c.points.size(); ++i)
        points[i].p[0] = c.points[i].x, points[i].p[1] = c.points[i].y, points[i].p[2] = c.points[i].z;
    Far::PrimvarRefinerReal<double> primvars(*refiner);
    Point* src = points.data();
    for (int level = 1; level <= kLevels; ++level) {
        Point* dst = src + refiner->GetLevel(level - 1).GetNumVertices();
        primvars.Interpolate(level, src, dst);
        src = dst;
    }
    std::vector<Point> limits(std::size_t(refiner->GetLevel(kLevels).GetNumVertices()));
    primvars.Limit(src, limits);
    std::vector<Vec3d> out;
    for (int v = 0; v < c.topology.pointCount; ++v) {
        int child = v;
        for (int level = 0; level < kLevels; ++level) child = refiner->GetLevel(level).GetVertexChildVertex(child);
        out.push_back(limits[std::size_t(child)].vec());
    }
    return out;
}

double maxAbsCoordinate(const std::vector<Vec3f>& points) {
    double m = 0.0;
    for (const Vec3f& p : points) m = std::max(m, double(maxComponent(vmax(p, -p))));
    return m;
}

// A lumpy cube: 8 points, 6 quads, every point of valence 3 (extraordinary).
Case lumpyCube() {
    Case c{"lumpy cube", {}, {}};
    c.points = {{-1.0f, -1.0f, -1.0f}, {1.1f, -0.9f, -1.0f}, {1.0f, 1.2f, -0.8f}, {-0.9f, 1.0f, -1.1f},
                {-1.0f, -1.1f, 0.9f},  {0.8f, -1.0f, 1.0f},  {1.2f, 1.0f, 1.1f},  {-1.0f, 0.9f, 1.0f}};
    c.topology = testing::cubeTopology();
    return c;
}

// The lumpy cube with a semi-sharp crease, an infinitely sharp crease chain around its top face
// (a USD chain of 5 points) and a semi-sharp corner.
Case creasedCube() {
    Case c = lumpyCube();
    c.name = "creased cube";
    c.topology.creaseIndices = {0, 1, 4, 5, 6, 7, 4};
    c.topology.creaseLengths = {2, 5};
    c.topology.creaseSharpnesses = {2.5f, 10.0f};
    c.topology.cornerIndices = {3};
    c.topology.cornerSharpnesses = {1.5f};
    return c;
}

// The lumpy cube with one infinitely sharp edge whose ends are darts (a crease ending inside the
// surface).
Case dartCube() {
    Case c = lumpyCube();
    c.name = "dart cube";
    c.topology.creaseIndices = {6, 7};
    c.topology.creaseLengths = {2};
    c.topology.creaseSharpnesses = {10.0f};
    return c;
}

// A closed mesh of mixed faces: a pentagonal prism whose sides are quads except one split into two
// triangles; "smooth" triangle rule. Pentagons and triangles are Bfr sub-face parameterizations.
Case mixedPrism() {
    Case c{"mixed prism", {}, {}};
    for (int ring = 0; ring < 2; ++ring)
        for (int i = 0; i < 5; ++i) {
            double a = 2.0 * 3.14159265358979 * i / 5.0;
            c.points.emplace_back(float((1.0 + 0.1 * i) * std::cos(a)), float(std::sin(a)),
                                  ring == 0 ? -1.0f : 1.0f + 0.05f * float(i));
        }
    c.topology.pointCount = 10;
    c.topology.faceVertexCounts = {5, 5};
    c.topology.faceVertexIndices = {4, 3, 2, 1, 0, 5, 6, 7, 8, 9};
    for (int i = 0; i < 5; ++i) {
        int j = (i + 1) % 5;
        if (i == 2) {
            c.topology.faceVertexCounts.insert(c.topology.faceVertexCounts.end(), {3, 3});
            c.topology.faceVertexIndices.insert(c.topology.faceVertexIndices.end(), {i, j, j + 5, i, j + 5, i + 5});
        } else {
            c.topology.faceVertexCounts.push_back(4);
            c.topology.faceVertexIndices.insert(c.topology.faceVertexIndices.end(), {i, j, j + 5, i + 5});
        }
    }
    c.topology.triangleSubdivisionRule = "smooth";
    return c;
}

// An open, bumpy 5x5-point grid (boundary, regular interior, edgeOnly corners) with one hole.
Case holedGrid() {
    Case c{"holed grid", {}, {}};
    const int n = 5;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x)
            c.points.emplace_back(float(x), float(y), float(0.3 * std::sin(1.3 * x + 0.7 * y * y)));
    c.topology.pointCount = n * n;
    for (int y = 0; y + 1 < n; ++y)
        for (int x = 0; x + 1 < n; ++x) {
            c.topology.faceVertexCounts.push_back(4);
            c.topology.faceVertexIndices.insert(c.topology.faceVertexIndices.end(),
                                                {y * n + x, y * n + x + 1, (y + 1) * n + x + 1, (y + 1) * n + x});
        }
    c.topology.interpolateBoundary = "edgeOnly";
    c.topology.holeIndices = {9};
    return c;
}

// A perturbed icosahedron under Loop: every point of valence 5.
Case loopIcosahedron() {
    Case c{"loop icosahedron", {}, {}};
    const float g = 1.618034f;
    c.points = {{-1, g, 0},  {1, g, 0},  {-1, -g, 0}, {1, -g, 0}, {0, -1, g},  {0, 1, g},
                {0, -1, -g}, {0, 1, -g}, {g, 0, -1},  {g, 0, 1},  {-g, 0, -1}, {-g, 0, 1}};
    for (std::size_t i = 0; i < c.points.size(); ++i) c.points[i] *= 1.0f + 0.03f * float(i % 4);
    c.topology.scheme = SubdivisionTopology::Scheme::Loop;
    c.topology.pointCount = 12;
    c.topology.faceVertexIndices = {0, 11, 5,  0, 5,  1, 0, 1, 7, 0, 7,  10, 0, 10, 11, 1, 5, 9, 5, 11,
                                    4, 11, 10, 2, 10, 7, 6, 7, 1, 8, 3,  9,  4, 3,  4,  2, 3, 2, 6, 3,
                                    6, 8,  3,  8, 9,  4, 9, 5, 2, 4, 11, 6,  2, 10, 8,  6, 7, 9, 8, 1};
    c.topology.faceVertexCounts.assign(20, 3);
    c.topology.creaseIndices = {0, 11};
    c.topology.creaseLengths = {2};
    c.topology.creaseSharpnesses = {1.0f};
    return c;
}

std::vector<Case> cases() {
    return {lumpyCube(), creasedCube(), dartCube(), mixedPrism(), holedGrid(), loopIcosahedron()};
}

// Segment counts that differ from edge to edge (1 to 8).
std::vector<int> variedRates(std::size_t edges) {
    std::vector<int> rates(edges);
    for (std::size_t e = 0; e < edges; ++e) rates[e] = 1 + int((e * 7 + 3) % 8);
    return rates;
}

TEST(SubdivisionReference, TessellatedPointsMatchFarPatchTableEvaluation) {
    for (const Case& c : cases()) {
        SCOPED_TRACE(c.name);
        SubdivisionSurface surface(c.topology);
        auto result = surface.tessellate(c.points, variedRates(surface.edges().size()));
        FarLimit far(c);
        const double scale = maxAbsCoordinate(c.points);
        ASSERT_GT(result.positions.size(), std::size_t(c.topology.pointCount));
        // The worst error of each kind as a fraction of its tolerance, and where it happened.
        double worstPosition = 0.0, worstNormal = 0.0;
        std::string wherePosition, whereNormal;
        for (std::size_t i = 0; i < result.positions.size(); ++i) {
            const auto& sc = result.surfaceCoords[i];
            Vec3d P, dPds, dPdt;
            far.evaluate(int(sc.face), sc.u, sc.v, P, dPds, dPdt);
            const std::string where = "vertex " + std::to_string(i) + " of face " + std::to_string(sc.face) +
                                      " at (u, v) = (" + std::to_string(sc.u) + ", " + std::to_string(sc.v) + ")";
            Vec3d error = Vec3d(result.positions[i]) - P;
            double ratio = maxComponent(vmax(error, -error)) / (0x1p-23 * (scale + length(dPds) + length(dPdt)));
            if (ratio > worstPosition)
                worstPosition = ratio,
                wherePosition = where + ": " + to_string(result.positions[i]) + " vs Far " + to_string(P);
            // A normal is as uncertain as its derivatives divided by the sine of their angle: where
            // they are (nearly) parallel, e.g. at an edgeOnly corner, it is undefined.
            Vec3d n = cross(dPds, dPdt);
            double sine = length(n) / (length(dPds) * length(dPdt));
            double normalRatio = length(Vec3d(result.normals[i]) - normalize(n)) / (0x1p-21 / sine);
            if (normalRatio > worstNormal)
                worstNormal = normalRatio,
                whereNormal = where + ": " + to_string(result.normals[i]) + " vs Far " + to_string(normalize(n));
        }
        EXPECT_LE(worstPosition, 1.0) << wherePosition;
        EXPECT_LE(worstNormal, 1.0) << whereNormal;
    }
}

// The dart cube is left out: at an infinitely sharp dart, Bfr (and Far's patch tables with
// infinitely sharp patches, which Bfr always uses) represent the surface with a boundary patch that
// misses the limit of uniform refinement there by about 0.5% of the cube's size (measured with
// Far alone: uniform refinement to levels 3, 6, 8, 10 converges to a point 0.009 away from the
// patch tables' value). That is OpenSubdiv's representation, which the test above holds us to.
TEST(SubdivisionReference, BasePointsAreFarVertexLimits) {
    for (const Case& c : {lumpyCube(), creasedCube(), mixedPrism(), holedGrid(), loopIcosahedron()}) {
        SCOPED_TRACE(c.name);
        SubdivisionSurface surface(c.topology);
        auto result = surface.tessellateUniform(c.points, 1);
        auto limits = farVertexLimits(c);
        const double tolerance = 0x1p-23 * maxAbsCoordinate(c.points);
        // Every point of these cases is used by a face, so output vertex p is base point p (block 1
        // of the documented layout).
        for (int p = 0; p < c.topology.pointCount; ++p) {
            Vec3d error = Vec3d(result.positions[std::size_t(p)]) - limits[std::size_t(p)];
            EXPECT_LE(maxComponent(vmax(error, -error)), tolerance)
                << "point " << p << ": " << to_string(result.positions[std::size_t(p)]) << " vs Far "
                << to_string(limits[std::size_t(p)]);
        }
    }
}

}  // namespace
}  // namespace fluence::delegate
