#include "delegate/subdivision_topology.h"

#include <opensubdiv/bfr/limits.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/sdc/crease.h>

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <limits>
#include <unordered_map>
#include <unordered_set>

namespace fluence::delegate::subdivision_detail {

namespace {

using OpenSubdiv::Sdc::Options;

[[noreturn]] void fail(const std::string& message) { throw std::invalid_argument("subdivision mesh: " + message); }

std::uint64_t edgeKey(int a, int b) {
    if (a > b) std::swap(a, b);
    return (std::uint64_t(std::uint32_t(a)) << 32) | std::uint32_t(b);
}

// OpenSubdiv's sharpness for a USD sharpness: 10 or more (and +infinity) is infinitely sharp.
float osdSharpness(float s, const char* attribute, std::size_t i) {
    if (std::isnan(s)) fail(std::string(attribute) + "[" + std::to_string(i) + "] is NaN");
    return s >= OpenSubdiv::Sdc::Crease::SHARPNESS_INFINITE ? OpenSubdiv::Sdc::Crease::SHARPNESS_INFINITE : s;
}

void checkPoint(int index, int pointCount, const char* attribute, std::size_t i) {
    if (index < 0 || index >= pointCount)
        fail(std::string(attribute) + "[" + std::to_string(i) + "] = " + std::to_string(index) +
             " is not a point (pointCount " + std::to_string(pointCount) + ")");
}

// USD primvar indices only compress values: one value index may serve corners at different points
// (Maya writes this where a UV edge is collapsed to one value, as in Pixar's Kitchen Set). OpenSubdiv's
// face-varying topology assumes each value belongs to one point (Bfr then reads patch points out of
// range), and so does the output layout here. The first point using a value keeps its index; every
// other point using it gets its own copy, appended. Corners at the same point still share, so seams and
// continuous edges are those of the data, and the values are the data's.
void splitValuesSharedByPoints(const SubdivisionTopology& t, FaceVaryingData& channel) {
    const std::size_t k = std::size_t(channel.components);
    const std::size_t count = channel.values.size() / k;
    std::vector<int> pointOf(count, -1);
    std::unordered_map<std::uint64_t, int> copies;  // (value, point) -> index of the value's copy
    for (std::size_t i = 0; i < channel.indices.size(); ++i) {
        const int value = channel.indices[i], point = t.faceVertexIndices[i];
        int& owner = pointOf[std::size_t(value)];
        if (owner < 0) owner = point;
        if (owner == point) continue;
        const std::uint64_t key = (std::uint64_t(std::uint32_t(value)) << 32) | std::uint32_t(point);
        auto [it, inserted] = copies.try_emplace(key, int(channel.values.size() / k));
        if (inserted) {
            if (channel.values.size() / k >= std::size_t(std::numeric_limits<int>::max()))
                fail("too many face-varying values after giving each point its own");
            for (std::size_t c = 0; c < k; ++c) {
                const float v = channel.values[std::size_t(value) * k + c];
                channel.values.push_back(v);
            }
        }
        channel.indices[i] = it->second;
    }
}

}  // namespace

OpenSubdiv::Sdc::SchemeType sdcScheme(SubdivisionTopology::Scheme scheme) {
    switch (scheme) {
        case SubdivisionTopology::Scheme::Loop: return OpenSubdiv::Sdc::SCHEME_LOOP;
        case SubdivisionTopology::Scheme::Bilinear: return OpenSubdiv::Sdc::SCHEME_BILINEAR;
        case SubdivisionTopology::Scheme::CatmullClark: break;
    }
    return OpenSubdiv::Sdc::SCHEME_CATMARK;
}

Options sdcOptions(const SubdivisionTopology& t) {
    Options options;
    const std::string& boundary = t.interpolateBoundary;
    if (boundary == "none")
        options.SetVtxBoundaryInterpolation(Options::VTX_BOUNDARY_NONE);
    else if (boundary == "edgeOnly")
        options.SetVtxBoundaryInterpolation(Options::VTX_BOUNDARY_EDGE_ONLY);
    else if (boundary == "edgeAndCorner")
        options.SetVtxBoundaryInterpolation(Options::VTX_BOUNDARY_EDGE_AND_CORNER);
    else
        fail("unknown interpolateBoundary \"" + boundary + "\" (none, edgeOnly or edgeAndCorner)");

    const std::string& fvar = t.faceVaryingLinearInterpolation;
    if (fvar == "none")
        options.SetFVarLinearInterpolation(Options::FVAR_LINEAR_NONE);
    else if (fvar == "cornersOnly")
        options.SetFVarLinearInterpolation(Options::FVAR_LINEAR_CORNERS_ONLY);
    else if (fvar == "cornersPlus1")
        options.SetFVarLinearInterpolation(Options::FVAR_LINEAR_CORNERS_PLUS1);
    else if (fvar == "cornersPlus2")
        options.SetFVarLinearInterpolation(Options::FVAR_LINEAR_CORNERS_PLUS2);
    else if (fvar == "boundaries")
        options.SetFVarLinearInterpolation(Options::FVAR_LINEAR_BOUNDARIES);
    else if (fvar == "all")
        options.SetFVarLinearInterpolation(Options::FVAR_LINEAR_ALL);
    else
        fail("unknown faceVaryingLinearInterpolation \"" + fvar +
             "\" (all, none, boundaries, cornersOnly, cornersPlus1 or cornersPlus2)");

    const std::string& triangles = t.triangleSubdivisionRule;
    if (triangles == "catmullClark")
        options.SetTriangleSubdivision(Options::TRI_SUB_CATMARK);
    else if (triangles == "smooth")
        options.SetTriangleSubdivision(Options::TRI_SUB_SMOOTH);
    else
        fail("unknown triangleSubdivisionRule \"" + triangles + "\" (catmullClark or smooth)");

    options.SetCreasingMethod(Options::CREASE_UNIFORM);
    return options;
}

void validateTopology(const SubdivisionTopology& t) {
    if (t.pointCount < 0) fail("pointCount is negative");
    const int maxFaceSize = OpenSubdiv::Bfr::Limits::MaxFaceSize();
    std::int64_t total = 0;
    for (std::size_t f = 0; f < t.faceVertexCounts.size(); ++f) {
        int n = t.faceVertexCounts[f];
        if (n < 3)
            fail("faceVertexCounts[" + std::to_string(f) + "] is " + std::to_string(n) +
                 ": a face needs 3 points or more");
        if (n > maxFaceSize)
            fail("faceVertexCounts[" + std::to_string(f) + "] is " + std::to_string(n) + ", more than OpenSubdiv's " +
                 std::to_string(maxFaceSize));
        if (t.scheme == SubdivisionTopology::Scheme::Loop && n != 3)
            fail("the loop scheme needs triangles, but face " + std::to_string(f) + " has " + std::to_string(n) +
                 " points");
        total += n;
    }
    if (total != std::int64_t(t.faceVertexIndices.size()))
        fail("faceVertexCounts add up to " + std::to_string(total) + " but faceVertexIndices has " +
             std::to_string(t.faceVertexIndices.size()) + " entries");

    std::unordered_set<std::uint64_t> meshEdges;
    std::size_t first = 0;
    for (std::size_t f = 0; f < t.faceVertexCounts.size(); ++f) {
        const int n = t.faceVertexCounts[f];
        for (int i = 0; i < n; ++i)
            checkPoint(t.faceVertexIndices[first + i], t.pointCount, "faceVertexIndices", first + i);
        for (int i = 0; i < n; ++i) {
            int a = t.faceVertexIndices[first + i], b = t.faceVertexIndices[first + (i + 1) % n];
            if (a == b)
                fail("face " + std::to_string(f) + " uses point " + std::to_string(a) +
                     " twice in a row (a degenerate edge)");
            meshEdges.insert(edgeKey(a, b));
        }
        first += std::size_t(n);
    }

    std::int64_t creasePoints = 0, creaseEdges = 0;
    for (std::size_t c = 0; c < t.creaseLengths.size(); ++c) {
        if (t.creaseLengths[c] < 2)
            fail("creaseLengths[" + std::to_string(c) + "] is " + std::to_string(t.creaseLengths[c]) +
                 ": a crease needs 2 points or more");
        creasePoints += t.creaseLengths[c];
        creaseEdges += t.creaseLengths[c] - 1;
    }
    if (creasePoints != std::int64_t(t.creaseIndices.size()))
        fail("creaseLengths add up to " + std::to_string(creasePoints) + " but creaseIndices has " +
             std::to_string(t.creaseIndices.size()) + " entries");
    const std::size_t sharpnesses = t.creaseSharpnesses.size();
    if (sharpnesses != t.creaseLengths.size() && std::int64_t(sharpnesses) != creaseEdges)
        fail("creaseSharpnesses has " + std::to_string(sharpnesses) + " entries: expected one per crease (" +
             std::to_string(t.creaseLengths.size()) + ") or one per crease edge (" + std::to_string(creaseEdges) + ")");
    for (std::size_t i = 0; i < t.creaseIndices.size(); ++i)
        checkPoint(t.creaseIndices[i], t.pointCount, "creaseIndices", i);
    for (std::size_t i = 0; i < sharpnesses; ++i) osdSharpness(t.creaseSharpnesses[i], "creaseSharpnesses", i);
    std::size_t start = 0;
    for (std::size_t c = 0; c < t.creaseLengths.size(); ++c) {
        for (int k = 0; k + 1 < t.creaseLengths[c]; ++k) {
            int a = t.creaseIndices[start + k], b = t.creaseIndices[start + k + 1];
            if (!meshEdges.contains(edgeKey(a, b)))
                fail("crease " + std::to_string(c) + " runs from point " + std::to_string(a) + " to point " +
                     std::to_string(b) + ", which is not an edge of the mesh");
        }
        start += std::size_t(t.creaseLengths[c]);
    }

    if (t.cornerIndices.size() != t.cornerSharpnesses.size())
        fail("cornerIndices has " + std::to_string(t.cornerIndices.size()) + " entries but cornerSharpnesses has " +
             std::to_string(t.cornerSharpnesses.size()));
    for (std::size_t i = 0; i < t.cornerIndices.size(); ++i) {
        checkPoint(t.cornerIndices[i], t.pointCount, "cornerIndices", i);
        osdSharpness(t.cornerSharpnesses[i], "cornerSharpnesses", i);
    }
    for (std::size_t i = 0; i < t.holeIndices.size(); ++i) {
        int h = t.holeIndices[i];
        if (h < 0 || h >= int(t.faceVertexCounts.size()))
            fail("holeIndices[" + std::to_string(i) + "] = " + std::to_string(h) + " is not a face (" +
                 std::to_string(t.faceVertexCounts.size()) + " faces)");
    }
}

void normalizeFaceVarying(const SubdivisionTopology& t, std::vector<FaceVaryingData>& channels) {
    const std::size_t faceVertices = t.faceVertexIndices.size();
    for (std::size_t c = 0; c < channels.size(); ++c) {
        FaceVaryingData& channel = channels[c];
        const std::string name = "face-varying channel " + std::to_string(c);
        if (channel.components < 1) fail(name + " has " + std::to_string(channel.components) + " components");
        if (channel.values.size() % std::size_t(channel.components) != 0)
            fail(name + " has " + std::to_string(channel.values.size()) + " floats, not a multiple of its " +
                 std::to_string(channel.components) + " components");
        const std::size_t count = channel.values.size() / std::size_t(channel.components);
        if (channel.indices.empty()) {
            if (count != faceVertices)
                fail(name + " has no indices and " + std::to_string(count) + " values, but the mesh has " +
                     std::to_string(faceVertices) + " face-vertices");
            channel.indices.resize(faceVertices);
            for (std::size_t i = 0; i < faceVertices; ++i) channel.indices[i] = int(i);
            continue;
        }
        if (channel.indices.size() != faceVertices)
            fail(name + " has " + std::to_string(channel.indices.size()) + " indices, but the mesh has " +
                 std::to_string(faceVertices) + " face-vertices");
        for (std::size_t i = 0; i < faceVertices; ++i)
            if (channel.indices[i] < 0 || std::size_t(channel.indices[i]) >= count)
                fail(name + ": indices[" + std::to_string(i) + "] = " + std::to_string(channel.indices[i]) +
                     " is not a value (" + std::to_string(count) + " values)");
        splitValuesSharedByPoints(t, channel);
    }
}

std::unique_ptr<OpenSubdiv::Far::TopologyRefiner> createRefiner(const SubdivisionTopology& t,
                                                                const std::vector<FaceVaryingData>& channels) {
    using OpenSubdiv::Far::TopologyDescriptor;

    // Crease chains become the vertex pairs of their edges, each with its sharpness.
    std::vector<int> creasePairs;
    std::vector<float> creaseWeights;
    const bool perCrease = t.creaseSharpnesses.size() == t.creaseLengths.size();
    std::size_t start = 0, edge = 0;
    for (std::size_t c = 0; c < t.creaseLengths.size(); ++c) {
        for (int k = 0; k + 1 < t.creaseLengths[c]; ++k, ++edge) {
            creasePairs.push_back(t.creaseIndices[start + k]);
            creasePairs.push_back(t.creaseIndices[start + k + 1]);
            std::size_t s = perCrease ? c : edge;
            creaseWeights.push_back(osdSharpness(t.creaseSharpnesses[s], "creaseSharpnesses", s));
        }
        start += std::size_t(t.creaseLengths[c]);
    }
    std::vector<float> cornerWeights;
    for (std::size_t i = 0; i < t.cornerSharpnesses.size(); ++i)
        cornerWeights.push_back(osdSharpness(t.cornerSharpnesses[i], "cornerSharpnesses", i));

    std::vector<TopologyDescriptor::FVarChannel> fvarChannels(channels.size());
    for (std::size_t c = 0; c < channels.size(); ++c) {
        fvarChannels[c].numValues = int(channels[c].values.size() / std::size_t(channels[c].components));
        fvarChannels[c].valueIndices = channels[c].indices.data();
    }

    TopologyDescriptor desc;
    desc.numVertices = t.pointCount;
    desc.numFaces = int(t.faceVertexCounts.size());
    desc.numVertsPerFace = t.faceVertexCounts.data();
    desc.vertIndicesPerFace = t.faceVertexIndices.data();
    desc.numCreases = int(creaseWeights.size());
    desc.creaseVertexIndexPairs = creasePairs.data();
    desc.creaseWeights = creaseWeights.data();
    desc.numCorners = int(cornerWeights.size());
    desc.cornerVertexIndices = t.cornerIndices.data();
    desc.cornerWeights = cornerWeights.data();
    desc.numHoles = int(t.holeIndices.size());
    desc.holeIndices = t.holeIndices.data();
    desc.isLeftHanded = false;
    desc.numFVarChannels = int(fvarChannels.size());
    desc.fvarChannels = fvarChannels.data();

    using Factory = OpenSubdiv::Far::TopologyRefinerFactory<TopologyDescriptor>;
    std::unique_ptr<OpenSubdiv::Far::TopologyRefiner> refiner(
        Factory::Create(desc, Factory::Options(sdcScheme(t.scheme), sdcOptions(t))));
    if (!refiner) fail("OpenSubdiv rejected the topology (OpenSubdiv printed the reason)");
    return refiner;
}

}  // namespace fluence::delegate::subdivision_detail
