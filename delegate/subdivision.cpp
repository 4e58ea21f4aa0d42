#include "delegate/subdivision.h"

#include <opensubdiv/bfr/refinerSurfaceFactory.h>
#include <opensubdiv/bfr/surface.h>
#include <opensubdiv/bfr/surfaceFactoryCache.h>
#include <opensubdiv/bfr/tessellation.h>

#include <algorithm>
#include <cfloat>
#include <climits>
#include <cmath>
#include <limits>
#include <mutex>
#include <shared_mutex>
#include <stdexcept>
#include <string>

#include "delegate/subdivision_topology.h"

namespace fluence::delegate {

namespace Bfr = OpenSubdiv::Bfr;
namespace Far = OpenSubdiv::Far;

namespace {

// A factory whose patch cache may be shared by threads calling tessellate() at once.
using ThreadSafeCache = Bfr::SurfaceFactoryCacheThreaded<std::shared_mutex, std::shared_lock<std::shared_mutex>,
                                                         std::unique_lock<std::shared_mutex>>;
using SurfaceFactory = Bfr::RefinerSurfaceFactory<ThreadSafeCache>;
using Surface = Bfr::Surface<double>;

constexpr std::uint64_t kMaxIndex = std::numeric_limits<std::uint32_t>::max();

// The unit normal cross(du, dv), or false where du and dv are (numerically) parallel: a cross
// product below a few hundred times its own rounding error has no reliable direction.
bool unitNormal(const double du[3], const double dv[3], Vec3f& n) {
    Vec3d a(du[0], du[1], du[2]), b(dv[0], dv[1], dv[2]);
    Vec3d c = cross(a, b);
    double len = length(c);
    if (!std::isfinite(len) || !(len > 1024.0 * DBL_EPSILON * length(a) * length(b))) return false;
    n = Vec3f(c / len);
    return true;
}

std::vector<double> toDouble(std::span<const float> values) { return {values.begin(), values.end()}; }

}  // namespace

// Face-varying layout of one channel (see "Face-varying data" in subdivision.h): which output value
// a face's corner or edge point uses, and which face evaluates it.
struct FaceVaryingLayout {
    std::vector<int> valueSlot;   // per input value: output value, or -1 when no face uses it
    std::vector<int> valueOwner;  // per input value: the face that evaluates it
    int usedValues = 0;
    // A span is one side of a base edge in face-varying terms: (edge, input value at its lower point,
    // input value at its higher point). Faces with the same span share the edge's points.
    std::vector<int> faceEdgeSpan;  // per face-vertex (face edge i of face f at faceStart[f] + i)
    std::vector<int> spanEdge, spanOwner;
};

struct SubdivisionSurface::Impl {
    SubdivisionTopology topology;
    std::vector<FaceVaryingData> faceVarying;  // indices filled in
    std::unique_ptr<Far::TopologyRefiner> refiner;
    std::unique_ptr<SurfaceFactory> factory;

    std::vector<std::pair<int, int>> edges;  // sorted, a < b
    std::vector<int> faceStart;              // per face + 1: first entry in faceVertexIndices
    std::vector<int> faceEdgeIndices;        // per face-vertex: the edge from it to the next point
    std::vector<char> hasLimit;              // per face
    // Shared output vertices: base points (block 1) and edges (block 2), owned by the first face
    // with a limit surface that uses them.
    std::vector<int> vertexOwner, vertexSlot;
    int usedVertices = 0;
    std::vector<int> edgeOwner;
    std::vector<FaceVaryingLayout> fvar;

    int faceSize(int f) const { return faceStart[f + 1] - faceStart[f]; }
    std::span<const int> facePoints(int f) const {
        return std::span<const int>(topology.faceVertexIndices)
            .subspan(std::size_t(faceStart[f]), std::size_t(faceSize(f)));
    }
    // True when face edge i of face f runs from the edge's lower point to its higher point.
    bool edgeForward(int f, int i) const {
        auto points = facePoints(f);
        return points[std::size_t(i)] == edges[std::size_t(faceEdgeIndices[std::size_t(faceStart[f] + i)])].first;
    }

    void buildEdges();
    void buildOwnership();
    void buildFaceVaryingLayout(int channel);

    // One tessellate() call: where everything goes is decided first, without evaluating anything
    // (pass 1, `layout`); then each face evaluates its points (pass 2, `evaluateFace`).
    struct Layout {
        std::vector<std::uint64_t> edgeBase;      // per edge: output vertex of its first inner point
        std::vector<std::uint64_t> interiorBase;  // per face: output vertex of its first interior point
        std::vector<std::uint64_t> triangleBase;  // per face + 1: its first triangle
        std::uint64_t interiorStart = 0, vertexCount = 0, triangleCount = 0;
        struct Channel {                          // the same for one face-varying channel's values
            std::vector<std::uint64_t> spanBase;  // per span: value of its first inner point
            std::uint64_t interiorStart = 0, count = 0;
        };
        std::vector<Channel> faceVarying;
    };
    // The call's mesh data in double: Bfr evaluates in double, each result is rounded to float once.
    struct MeshData {
        std::vector<double> points;
        std::vector<std::vector<double>> vertexData, faceVarying;
        std::span<const VertexData> vertexChannels;
        bool anyVarying = false;
    };
    // Working storage for one face, reused from face to face.
    struct FaceWork {
        Surface surface, varyingSurface, faceVaryingSurface;
        std::vector<int> rates, facets;            // facets: 3 face coordinates per triangle
        std::vector<double> coords, patch, value;  // coords: (u, v) per face coordinate
        std::vector<int> controlPoints;            // a face-varying surface's value indices
        int boundaryCount = 0;                     // face coordinates on the face's boundary
        std::vector<std::uint32_t> output;         // face coordinate -> output vertex (or value)
        std::vector<char> owned;                   // face coordinate -> this face evaluates it
        std::vector<Vec3f> normal;                 // face coordinate -> this face's limit normal
        std::vector<char> normalValid;
    };

    void faceRates(int f, std::span<const int> edgeSegments, std::vector<int>& rates) const;
    Layout layout(std::span<const int> edgeSegments) const;
    // Calls corner(b, i) for face point i and edgePoint(b, i, fromLower) for each inner point of
    // face edge i (fromLower: its segment position from the edge's lower-numbered point), where b
    // is the point's index among the boundary coordinates of the face's Bfr::Tessellation: point 0,
    // edge 0's inner points from point 0 towards point 1, point 1, and so on. Returns the count.
    template <typename Corner, typename EdgePoint>
    int walkBoundary(int f, const std::vector<int>& rates, Corner&& corner, EdgePoint&& edgePoint) const;
    void evaluateFace(int f, const Layout& layout, const MeshData& mesh, FaceWork& work, Result& result,
                      std::vector<char>& degenerate) const;
    void evaluateFaceVarying(int f, int channel, const Layout& layout, const MeshData& mesh, FaceWork& work,
                             Result& result) const;
};

void SubdivisionSurface::Impl::buildEdges() {
    const std::vector<int>& fvi = topology.faceVertexIndices;
    const int faces = int(topology.faceVertexCounts.size());
    faceStart.assign(std::size_t(faces) + 1, 0);
    for (int f = 0; f < faces; ++f) faceStart[f + 1] = faceStart[f] + topology.faceVertexCounts[f];
    for (int f = 0; f < faces; ++f)
        for (int i = 0, n = faceSize(f); i < n; ++i) {
            int a = fvi[faceStart[f] + i], b = fvi[faceStart[f] + (i + 1) % n];
            edges.emplace_back(std::min(a, b), std::max(a, b));
        }
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    faceEdgeIndices.resize(fvi.size());
    for (int f = 0; f < faces; ++f)
        for (int i = 0, n = faceSize(f); i < n; ++i) {
            int a = fvi[faceStart[f] + i], b = fvi[faceStart[f] + (i + 1) % n];
            auto it = std::lower_bound(edges.begin(), edges.end(), std::pair(std::min(a, b), std::max(a, b)));
            faceEdgeIndices[faceStart[f] + i] = int(it - edges.begin());
        }
}

void SubdivisionSurface::Impl::buildOwnership() {
    const int faces = int(topology.faceVertexCounts.size());
    hasLimit.assign(std::size_t(faces), 0);
    for (int f = 0; f < faces; ++f) hasLimit[f] = factory->FaceHasLimitSurface(f) ? 1 : 0;
    vertexOwner.assign(std::size_t(topology.pointCount), -1);
    edgeOwner.assign(edges.size(), -1);
    for (int f = 0; f < faces; ++f) {
        if (!hasLimit[f]) continue;
        for (int i = 0, n = faceSize(f); i < n; ++i) {
            int& vertex = vertexOwner[topology.faceVertexIndices[faceStart[f] + i]];
            if (vertex < 0) vertex = f;
            int& edge = edgeOwner[faceEdgeIndices[faceStart[f] + i]];
            if (edge < 0) edge = f;
        }
    }
    vertexSlot.assign(std::size_t(topology.pointCount), -1);
    for (int v = 0; v < topology.pointCount; ++v)
        if (vertexOwner[v] >= 0) vertexSlot[v] = usedVertices++;
}

void SubdivisionSurface::Impl::buildFaceVaryingLayout(int channel) {
    const FaceVaryingData& data = faceVarying[channel];
    FaceVaryingLayout& layout = fvar[channel];
    const std::size_t values = data.values.size() / std::size_t(data.components);
    layout.valueOwner.assign(values, -1);
    layout.valueSlot.assign(values, -1);
    layout.faceEdgeSpan.assign(data.indices.size(), -1);
    std::vector<std::vector<int>> edgeSpans(edges.size());  // spans of each edge
    std::vector<std::pair<int, int>> spanValues;            // per span: values at (lower, higher) point
    const int faces = int(topology.faceVertexCounts.size());
    for (int f = 0; f < faces; ++f) {
        if (!hasLimit[f]) continue;
        const int n = faceSize(f);
        for (int i = 0; i < n; ++i) {
            const int corner = faceStart[f] + i, next = faceStart[f] + (i + 1) % n;
            if (layout.valueOwner[data.indices[corner]] < 0) layout.valueOwner[data.indices[corner]] = f;
            const int e = faceEdgeIndices[corner];
            std::pair<int, int> ends = edgeForward(f, i) ? std::pair(data.indices[corner], data.indices[next])
                                                         : std::pair(data.indices[next], data.indices[corner]);
            int span = -1;
            for (int s : edgeSpans[e])
                if (spanValues[s] == ends) span = s;
            if (span < 0) {
                span = int(spanValues.size());
                spanValues.push_back(ends);
                edgeSpans[e].push_back(span);
                layout.spanEdge.push_back(e);
                layout.spanOwner.push_back(f);
            }
            layout.faceEdgeSpan[corner] = span;
        }
    }
    for (std::size_t v = 0; v < values; ++v)
        if (layout.valueOwner[v] >= 0) layout.valueSlot[v] = layout.usedValues++;
}

SubdivisionSurface::SubdivisionSurface(SubdivisionTopology topology, std::vector<FaceVaryingData> faceVarying)
    : impl_(std::make_unique<Impl>()) {
    Impl& m = *impl_;
    m.topology = std::move(topology);
    m.faceVarying = std::move(faceVarying);
    subdivision_detail::sdcOptions(m.topology);  // unknown tokens first: the clearest message
    subdivision_detail::validateTopology(m.topology);
    subdivision_detail::normalizeFaceVarying(m.topology, m.faceVarying);
    // A mesh without faces (valid in USD) has no surface; OpenSubdiv would reject it.
    if (!m.topology.faceVertexCounts.empty()) {
        m.refiner = subdivision_detail::createRefiner(m.topology, m.faceVarying);
        m.factory = std::make_unique<SurfaceFactory>(*m.refiner, SurfaceFactory::Options());
    }
    m.buildEdges();
    m.buildOwnership();
    m.fvar.resize(m.faceVarying.size());
    for (int c = 0; c < int(m.faceVarying.size()); ++c) m.buildFaceVaryingLayout(c);
}

SubdivisionSurface::~SubdivisionSurface() = default;
SubdivisionSurface::SubdivisionSurface(SubdivisionSurface&&) noexcept = default;
SubdivisionSurface& SubdivisionSurface::operator=(SubdivisionSurface&&) noexcept = default;

const SubdivisionTopology& SubdivisionSurface::topology() const { return impl_->topology; }
const std::vector<std::pair<int, int>>& SubdivisionSurface::edges() const { return impl_->edges; }
int SubdivisionSurface::faceCount() const { return int(impl_->topology.faceVertexCounts.size()); }
bool SubdivisionSurface::faceHasLimitSurface(int face) const { return impl_->hasLimit.at(std::size_t(face)) != 0; }
std::span<const int> SubdivisionSurface::faceEdges(int face) const {
    const Impl& m = *impl_;
    if (face < 0 || face >= faceCount()) throw std::out_of_range("subdivision mesh: no face " + std::to_string(face));
    return std::span<const int>(m.faceEdgeIndices)
        .subspan(std::size_t(m.faceStart[face]), std::size_t(m.faceSize(face)));
}

SubdivisionSurface::Result SubdivisionSurface::tessellateUniform(std::span<const Vec3f> points, int level,
                                                                 std::span<const VertexData> vertexData) const {
    if (level < 0 || (1 << std::min(level, 30)) > kMaxEdgeSegments)
        throw std::invalid_argument("subdivision mesh: uniform level " + std::to_string(level) + " is not in [0, 12]");
    std::vector<int> rates(impl_->edges.size(), 1 << level);
    return tessellate(points, rates, vertexData);
}

void SubdivisionSurface::Impl::faceRates(int f, std::span<const int> edgeSegments, std::vector<int>& rates) const {
    rates.resize(std::size_t(faceSize(f)));
    for (int i = 0; i < faceSize(f); ++i)
        rates[std::size_t(i)] = edgeSegments[std::size_t(faceEdgeIndices[std::size_t(faceStart[f] + i)])];
}

template <typename Corner, typename EdgePoint>
int SubdivisionSurface::Impl::walkBoundary(int f, const std::vector<int>& rates, Corner&& corner,
                                           EdgePoint&& edgePoint) const {
    int b = 0;
    for (int i = 0, n = faceSize(f); i < n; ++i) {
        corner(b++, i);
        const int rate = rates[std::size_t(i)];
        const bool forward = edgeForward(f, i);
        for (int k = 1; k < rate; ++k) edgePoint(b++, i, forward ? k : rate - k);
    }
    return b;
}

SubdivisionSurface::Impl::Layout SubdivisionSurface::Impl::layout(std::span<const int> edgeSegments) const {
    const int faces = int(topology.faceVertexCounts.size());
    Layout l;
    l.edgeBase.assign(edges.size(), 0);
    l.interiorBase.assign(std::size_t(faces), 0);
    l.triangleBase.assign(std::size_t(faces) + 1, 0);
    std::uint64_t next = std::uint64_t(usedVertices);
    for (std::size_t e = 0; e < edges.size(); ++e)
        if (edgeOwner[e] >= 0) {
            l.edgeBase[e] = next;
            next += std::uint64_t(edgeSegments[e] - 1);
        }
    l.interiorStart = next;
    const Bfr::Tessellation::Options triangles;
    std::vector<int> rates;
    for (int f = 0; f < faces; ++f) {
        l.triangleBase[std::size_t(f) + 1] = l.triangleBase[std::size_t(f)];
        if (!hasLimit[std::size_t(f)]) continue;
        faceRates(f, edgeSegments, rates);
        // Bfr counts a face's points in int: keep n (rate + 1)^2, a bound on them, below INT_MAX.
        const std::int64_t maxRate = *std::max_element(rates.begin(), rates.end());
        if (std::int64_t(faceSize(f)) * (maxRate + 1) * (maxRate + 1) > INT_MAX)
            throw std::length_error("subdivision mesh: face " + std::to_string(f) +
                                    " would have too many points at these rates");
        Bfr::Tessellation tess(factory->GetFaceParameterization(f), int(rates.size()), rates.data(), triangles);
        l.interiorBase[std::size_t(f)] = next;
        next += std::uint64_t(tess.GetNumInteriorCoords());
        l.triangleBase[std::size_t(f) + 1] += std::uint64_t(tess.GetNumFacets());
    }
    l.vertexCount = next;
    l.triangleCount = l.triangleBase.back();
    if (l.vertexCount > kMaxIndex || 3 * l.triangleCount > kMaxIndex)
        throw std::length_error("subdivision mesh: " + std::to_string(l.vertexCount) + " vertices and " +
                                std::to_string(l.triangleCount) + " triangles do not fit 32-bit indices");

    // Face-varying values: those of base points, then the spans' inner points, then the faces'
    // interiors (as many as the interior vertices).
    l.faceVarying.resize(fvar.size());
    for (std::size_t c = 0; c < fvar.size(); ++c) {
        Layout::Channel& channel = l.faceVarying[c];
        std::uint64_t value = std::uint64_t(fvar[c].usedValues);
        channel.spanBase.resize(fvar[c].spanEdge.size());
        for (std::size_t s = 0; s < channel.spanBase.size(); ++s) {
            channel.spanBase[s] = value;
            value += std::uint64_t(edgeSegments[std::size_t(fvar[c].spanEdge[s])] - 1);
        }
        channel.interiorStart = value;
        channel.count = value + (l.vertexCount - l.interiorStart);
        if (channel.count > kMaxIndex)
            throw std::length_error("subdivision mesh: too many face-varying values for 32-bit indices");
    }
    return l;
}

void SubdivisionSurface::Impl::evaluateFace(int f, const Layout& l, const MeshData& mesh, FaceWork& w, Result& r,
                                            std::vector<char>& degenerate) const {
    if (!factory->InitVertexSurface(f, &w.surface))
        throw std::logic_error("subdivision mesh: OpenSubdiv has no limit surface for face " + std::to_string(f));
    if (mesh.anyVarying && !factory->InitVaryingSurface(f, &w.varyingSurface))
        throw std::logic_error("subdivision mesh: OpenSubdiv has no varying surface for face " + std::to_string(f));
    Bfr::Tessellation tess(w.surface.GetParameterization(), int(w.rates.size()), w.rates.data(),
                           Bfr::Tessellation::Options());
    const int coordCount = tess.GetNumCoords();
    w.boundaryCount = tess.GetNumBoundaryCoords();
    w.coords.resize(2 * std::size_t(coordCount));
    tess.GetCoords(w.coords.data());
    w.facets.resize(3 * std::size_t(tess.GetNumFacets()));
    tess.GetFacets(w.facets.data());

    // The output vertex of each face coordinate, and whether this face owns (evaluates) it.
    w.output.assign(std::size_t(coordCount), 0);
    w.owned.assign(std::size_t(coordCount), 1);
    const auto points = facePoints(f);
    const int walked = walkBoundary(
        f, w.rates,
        [&](int b, int i) {
            const int point = points[std::size_t(i)];
            w.output[std::size_t(b)] = std::uint32_t(vertexSlot[std::size_t(point)]);
            w.owned[std::size_t(b)] = vertexOwner[std::size_t(point)] == f;
        },
        [&](int b, int i, int fromLower) {
            const std::size_t e = std::size_t(faceEdgeIndices[std::size_t(faceStart[f] + i)]);
            w.output[std::size_t(b)] = std::uint32_t(l.edgeBase[e] + std::uint64_t(fromLower - 1));
            w.owned[std::size_t(b)] = edgeOwner[e] == f;
        });
    if (walked != w.boundaryCount) throw std::logic_error("subdivision mesh: unexpected Bfr boundary layout");
    for (int j = w.boundaryCount; j < coordCount; ++j)
        w.output[std::size_t(j)] = std::uint32_t(l.interiorBase[std::size_t(f)] + std::uint64_t(j - w.boundaryCount));

    // Positions, derivatives and normals: at every coordinate, as corner normals need this face's own.
    w.patch.resize(3 * std::size_t(w.surface.GetNumPatchPoints()));
    w.surface.PreparePatchPoints(mesh.points.data(), 3, w.patch.data(), 3);
    w.normal.resize(std::size_t(coordCount));
    w.normalValid.resize(std::size_t(coordCount));
    for (std::size_t j = 0; j < std::size_t(coordCount); ++j) {
        double p[3], du[3], dv[3];
        w.surface.Evaluate(&w.coords[2 * j], w.patch.data(), 3, p, du, dv);
        w.normalValid[j] = unitNormal(du, dv, w.normal[j]);
        if (!w.owned[j]) continue;
        const std::uint32_t out = w.output[j];
        r.positions[out] = Vec3f(float(p[0]), float(p[1]), float(p[2]));
        r.dPdu[out] = Vec3f(float(du[0]), float(du[1]), float(du[2]));
        r.dPdv[out] = Vec3f(float(dv[0]), float(dv[1]), float(dv[2]));
        r.normals[out] = w.normal[j];
        degenerate[out] = !w.normalValid[j];
        r.surfaceCoords[out] = {std::uint32_t(f), float(w.coords[2 * j]), float(w.coords[2 * j + 1])};
    }

    // Vertex and varying primvars, at the points this face owns.
    for (std::size_t c = 0; c < mesh.vertexChannels.size(); ++c) {
        const Surface& s = mesh.vertexChannels[c].varying ? w.varyingSurface : w.surface;
        const int components = mesh.vertexChannels[c].components;
        w.patch.resize(std::size_t(components) * std::size_t(s.GetNumPatchPoints()));
        s.PreparePatchPoints(mesh.vertexData[c].data(), components, w.patch.data(), components);
        w.value.resize(std::size_t(components));
        for (std::size_t j = 0; j < std::size_t(coordCount); ++j) {
            if (!w.owned[j]) continue;
            s.Evaluate(&w.coords[2 * j], w.patch.data(), components, w.value.data());
            float* out = &r.vertexData[c][std::size_t(w.output[j]) * std::size_t(components)];
            for (int k = 0; k < components; ++k) out[k] = float(w.value[std::size_t(k)]);
        }
    }

    // Triangles (a corner whose normal is undefined is filled in afterwards, see repairNormals).
    const std::size_t first = l.triangleBase[std::size_t(f)];
    for (std::size_t t = 0; t < w.facets.size() / 3; ++t) {
        r.triangleFaces[first + t] = std::uint32_t(f);
        for (std::size_t k = 0; k < 3; ++k) {
            const std::size_t j = std::size_t(w.facets[3 * t + k]);
            r.indices[3 * (first + t) + k] = w.output[j];
            r.cornerNormals[3 * (first + t) + k] = w.normalValid[j] ? w.normal[j] : Vec3f(0.0f);
        }
    }

    for (int c = 0; c < int(fvar.size()); ++c) evaluateFaceVarying(f, c, l, mesh, w, r);
}

void SubdivisionSurface::Impl::evaluateFaceVarying(int f, int c, const Layout& l, const MeshData& mesh, FaceWork& w,
                                                   Result& r) const {
    const FaceVaryingLayout& layout = fvar[std::size_t(c)];
    const Layout::Channel& bases = l.faceVarying[std::size_t(c)];
    const FaceVaryingData& input = faceVarying[std::size_t(c)];
    Surface& s = w.faceVaryingSurface;
    if (!factory->InitFaceVaryingSurface(f, &s, Bfr::SurfaceFactory::FVarID(c)))
        throw std::logic_error("subdivision mesh: OpenSubdiv has no face-varying surface for face " +
                               std::to_string(f));
    // Bfr reads the channel's values through these indices without bounds checks: where OpenSubdiv's
    // face-varying topology went wrong (it once did, on values shared by several points), fail, not read out of range.
    w.controlPoints.resize(std::size_t(s.GetNumControlPoints()));
    s.GetControlPointIndices(w.controlPoints.data());
    const std::size_t valueCount = input.values.size() / std::size_t(input.components);
    for (int index : w.controlPoints)
        if (index < 0 || std::size_t(index) >= valueCount)
            throw std::logic_error("subdivision mesh: face " + std::to_string(f) + " of face-varying channel " +
                                   std::to_string(c) + " refers to value " + std::to_string(index) + " of " +
                                   std::to_string(valueCount));

    // The output value of each face coordinate: corners by input value, edge points by span.
    const std::size_t coordCount = w.coords.size() / 2;
    w.output.assign(coordCount, 0);
    w.owned.assign(coordCount, 1);
    walkBoundary(
        f, w.rates,
        [&](int b, int i) {
            const std::size_t value = std::size_t(input.indices[std::size_t(faceStart[f] + i)]);
            w.output[std::size_t(b)] = std::uint32_t(layout.valueSlot[value]);
            w.owned[std::size_t(b)] = layout.valueOwner[value] == f;
        },
        [&](int b, int i, int fromLower) {
            const std::size_t span = std::size_t(layout.faceEdgeSpan[std::size_t(faceStart[f] + i)]);
            w.output[std::size_t(b)] = std::uint32_t(bases.spanBase[span] + std::uint64_t(fromLower - 1));
            w.owned[std::size_t(b)] = layout.spanOwner[span] == f;
        });
    const std::uint64_t interior = bases.interiorStart + (l.interiorBase[std::size_t(f)] - l.interiorStart);
    for (std::size_t j = std::size_t(w.boundaryCount); j < coordCount; ++j)
        w.output[j] = std::uint32_t(interior + (j - std::size_t(w.boundaryCount)));

    const int components = input.components;
    w.patch.resize(std::size_t(components) * std::size_t(s.GetNumPatchPoints()));
    s.PreparePatchPoints(mesh.faceVarying[std::size_t(c)].data(), components, w.patch.data(), components);
    w.value.resize(std::size_t(components));
    FaceVaryingData& out = r.faceVarying[std::size_t(c)];
    for (std::size_t j = 0; j < coordCount; ++j) {
        if (!w.owned[j]) continue;
        s.Evaluate(&w.coords[2 * j], w.patch.data(), components, w.value.data());
        for (int k = 0; k < components; ++k)
            out.values[std::size_t(w.output[j]) * std::size_t(components) + std::size_t(k)] =
                float(w.value[std::size_t(k)]);
    }
    const std::size_t first = 3 * l.triangleBase[std::size_t(f)];
    for (std::size_t k = 0; k < w.facets.size(); ++k) out.indices[first + k] = w.output[std::size_t(w.facets[k])];
}

namespace {

// Where the limit normal is undefined (parallel derivatives: coincident control points, a smooth
// valence-2 corner), the area-weighted normal of the triangles around the vertex stands in; a
// triangle corner whose own normal is undefined takes its vertex's.
void repairNormals(SubdivisionSurface::Result& r, const std::vector<char>& degenerate) {
    if (std::find(degenerate.begin(), degenerate.end(), 1) != degenerate.end()) {
        std::vector<Vec3d> sum(r.positions.size());
        for (std::size_t t = 0; t < r.indices.size(); t += 3) {
            const std::uint32_t* tri = &r.indices[t];
            if (!degenerate[tri[0]] && !degenerate[tri[1]] && !degenerate[tri[2]]) continue;
            Vec3d a(r.positions[tri[0]]), b(r.positions[tri[1]]), c(r.positions[tri[2]]);
            const Vec3d area = cross(b - a, c - a);
            for (int k = 0; k < 3; ++k) sum[tri[k]] += area;
        }
        for (std::size_t v = 0; v < sum.size(); ++v)
            if (degenerate[v]) r.normals[v] = length(sum[v]) > 0.0 ? Vec3f(normalize(sum[v])) : Vec3f(0.0f, 0.0f, 1.0f);
    }
    for (std::size_t i = 0; i < r.cornerNormals.size(); ++i)
        if (r.cornerNormals[i] == Vec3f(0.0f)) r.cornerNormals[i] = r.normals[r.indices[i]];
}

}  // namespace

SubdivisionSurface::Result SubdivisionSurface::tessellate(std::span<const Vec3f> points,
                                                          std::span<const int> edgeSegments,
                                                          std::span<const VertexData> vertexData) const {
    const Impl& m = *impl_;
    auto fail = [](const std::string& message) { throw std::invalid_argument("subdivision mesh: " + message); };
    if (points.size() != std::size_t(m.topology.pointCount))
        fail(std::to_string(points.size()) + " points given for " + std::to_string(m.topology.pointCount) +
             " control points");
    if (edgeSegments.size() != m.edges.size())
        fail(std::to_string(edgeSegments.size()) + " edge segment counts given for " + std::to_string(m.edges.size()) +
             " edges");
    for (std::size_t e = 0; e < edgeSegments.size(); ++e)
        if (edgeSegments[e] < 1 || edgeSegments[e] > kMaxEdgeSegments)
            fail("edge " + std::to_string(e) + " has " + std::to_string(edgeSegments[e]) + " segments (1 to " +
                 std::to_string(kMaxEdgeSegments) + " allowed)");
    for (std::size_t c = 0; c < vertexData.size(); ++c) {
        if (vertexData[c].components < 1) fail("vertex data channel " + std::to_string(c) + " has no components");
        if (vertexData[c].values.size() != std::size_t(vertexData[c].components) * points.size())
            fail("vertex data channel " + std::to_string(c) + " has " + std::to_string(vertexData[c].values.size()) +
                 " floats, expected " + std::to_string(vertexData[c].components) + " per point");
    }

    const Impl::Layout layout = m.layout(edgeSegments);
    Result r;
    r.positions.resize(layout.vertexCount);
    r.normals.resize(layout.vertexCount);
    r.dPdu.resize(layout.vertexCount);
    r.dPdv.resize(layout.vertexCount);
    r.surfaceCoords.resize(layout.vertexCount);
    r.vertexData.resize(vertexData.size());
    for (std::size_t c = 0; c < vertexData.size(); ++c)
        r.vertexData[c].resize(layout.vertexCount * std::size_t(vertexData[c].components));
    r.indices.resize(3 * layout.triangleCount);
    r.triangleFaces.resize(layout.triangleCount);
    r.cornerNormals.resize(3 * layout.triangleCount);
    r.faceVarying.resize(m.fvar.size());
    for (std::size_t c = 0; c < m.fvar.size(); ++c) {
        r.faceVarying[c].components = m.faceVarying[c].components;
        r.faceVarying[c].values.resize(layout.faceVarying[c].count * std::size_t(m.faceVarying[c].components));
        r.faceVarying[c].indices.resize(3 * layout.triangleCount);
    }

    Impl::MeshData mesh;
    mesh.points.resize(3 * points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
        mesh.points[3 * i] = points[i].x;
        mesh.points[3 * i + 1] = points[i].y;
        mesh.points[3 * i + 2] = points[i].z;
    }
    for (const VertexData& data : vertexData) mesh.vertexData.push_back(toDouble(data.values));
    for (const FaceVaryingData& data : m.faceVarying) mesh.faceVarying.push_back(toDouble(data.values));
    mesh.vertexChannels = vertexData;
    mesh.anyVarying = std::any_of(vertexData.begin(), vertexData.end(), [](const VertexData& d) { return d.varying; });

    // Each face writes only its interior points and the shared points it owns, and reads nothing
    // another face writes: faces could be evaluated in any order, or in parallel, with the same result.
    Impl::FaceWork work;
    std::vector<char> degenerate(layout.vertexCount, 0);  // output vertices whose limit normal is undefined
    for (int f = 0; f < faceCount(); ++f) {
        if (!m.hasLimit[std::size_t(f)]) continue;
        m.faceRates(f, edgeSegments, work.rates);
        m.evaluateFace(f, layout, mesh, work, r, degenerate);
    }
    repairNormals(r, degenerate);
    return r;
}

}  // namespace fluence::delegate
