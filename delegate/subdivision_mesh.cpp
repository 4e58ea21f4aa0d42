#include "delegate/subdivision_mesh.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>

#include "delegate/displacement.h"
#include "delegate/mesh_adapter.h"
#include "delegate/primvar.h"
#include "render/mesh_transform.h"

namespace fluence::delegate {

namespace {

std::vector<int> integers(const PrimReader& prim, const std::string& name) {
    std::vector<int> out;
    for (double d : prim.numbers(name, 1).value_or(std::vector<double>{})) out.push_back(static_cast<int>(d));
    return out;
}

std::vector<float> floats(const PrimReader& prim, const std::string& name) {
    std::vector<float> out;
    for (double d : prim.numbers(name, 1).value_or(std::vector<double>{})) out.push_back(static_cast<float>(d));
    return out;
}

SubdivisionTopology::Scheme schemeOf(const PrimReader& prim, const std::string& token) {
    if (token == "catmullClark") return SubdivisionTopology::Scheme::CatmullClark;
    if (token == "loop") return SubdivisionTopology::Scheme::Loop;
    if (token == "bilinear") return SubdivisionTopology::Scheme::Bilinear;
    prim.fail("subdivisionScheme '" + token + "' is not one of catmullClark, loop, bilinear, none");
}

// Reverses each face's winding (keeping its first point), for leftHanded meshes.
void reverseFaces(const std::vector<int>& counts, std::vector<int>& perFaceVertex) {
    std::size_t start = 0;
    for (int n : counts) {
        if (n > 2 && start + static_cast<std::size_t>(n) <= perFaceVertex.size())
            std::reverse(perFaceVertex.begin() + static_cast<std::ptrdiff_t>(start) + 1,
                         perFaceVertex.begin() + static_cast<std::ptrdiff_t>(start + static_cast<std::size_t>(n)));
        start += static_cast<std::size_t>(std::max(n, 0));
    }
}

}  // namespace

bool SubdivisionMesh::isSubdivided(const usd::PrimSpec& mesh, double time) {
    return PrimReader(mesh, time).token({"subdivisionScheme"}, "catmullClark") != "none";
}

SubdivisionMesh::SubdivisionMesh(const usd::Stage& stage, const usd::PrimSpec& mesh, double time,
                                 const ColorConverter& convertColor,
                                 const std::function<void(const std::string&)>& warn)
    : path_(mesh.path) {
    PrimReader prim(mesh, time);
    SubdivisionTopology topology;
    topology.scheme = schemeOf(prim, prim.token({"subdivisionScheme"}, "catmullClark"));
    topology.interpolateBoundary = prim.token({"interpolateBoundary"}, "edgeAndCorner");
    topology.faceVaryingLinearInterpolation = prim.token({"faceVaryingLinearInterpolation"}, "cornersPlus1");
    topology.triangleSubdivisionRule = prim.token({"triangleSubdivisionRule"}, "catmullClark");
    std::vector<double> points = prim.numbers("points", 3).value_or(std::vector<double>{});
    topology.pointCount = static_cast<int>(points.size() / 3);
    for (std::size_t i = 0; i + 2 < points.size(); i += 3)
        points_.emplace_back(points[i], points[i + 1], points[i + 2]);
    topology.faceVertexCounts = integers(prim, "faceVertexCounts");
    topology.faceVertexIndices = integers(prim, "faceVertexIndices");
    topology.creaseIndices = integers(prim, "creaseIndices");
    topology.creaseLengths = integers(prim, "creaseLengths");
    topology.creaseSharpnesses = floats(prim, "creaseSharpnesses");
    topology.cornerIndices = integers(prim, "cornerIndices");
    topology.cornerSharpnesses = floats(prim, "cornerSharpnesses");
    topology.holeIndices = integers(prim, "holeIndices");
    const bool leftHanded = prim.token({"orientation"}, "rightHanded") == "leftHanded";
    if (leftHanded) reverseFaces(topology.faceVertexCounts, topology.faceVertexIndices);
    dicingRate_ = static_cast<float>(prim.number({"primvars:fluence:dicingRate"}, 0.0));
    if (dicingRate_ < 0.0f || !std::isfinite(dicingRate_)) prim.fail("primvars:fluence:dicingRate must be > 0 pixels");

    std::vector<FaceVaryingData> faceVarying;
    auto checked = [&](const Primvar& pv) {
        checkPrimvarSize(prim, pv, topology.faceVertexCounts.size(), topology.faceVertexIndices.size(), points_.size());
    };
    if (std::optional<Primvar> colors = readPrimvar(prim, "primvars:displayColor", "constant")) {
        checked(*colors);
        std::string space = prim.attributeMetadata("primvars:displayColor", "colorSpace").value_or("");
        std::vector<float> values;  // converted, indexed like the authored values
        for (std::size_t i = 0; i < colors->values.size() / 3; ++i) {
            RGB c = convertColor(
                RGB(Vec3d(colors->values[3 * i], colors->values[3 * i + 1], colors->values[3 * i + 2])), space);
            values.insert(values.end(), {c.x, c.y, c.z});
        }
        displayColor_ = static_cast<int>(primvars_.size());
        addPrimvar(*colors, std::move(values), topology, leftHanded, faceVarying);
    }
    for (const Primvar& pv : readShadingPrimvars(prim)) {
        checked(pv);
        addPrimvar(pv, std::vector<float>(pv.values.begin(), pv.values.end()), topology, leftHanded, faceVarying);
        primvars_.back().name = pv.name;
    }
    std::size_t faceCount = topology.faceVertexCounts.size();
    try {
        surface_ = std::make_shared<const SubdivisionSurface>(std::move(topology), std::move(faceVarying));
    } catch (const std::invalid_argument& e) {
        prim.fail(e.what());
    }
    materials_ = readMaterialAssignment(stage, mesh, time, faceCount, warn);
}

void SubdivisionMesh::addPrimvar(const Primvar& pv, std::vector<float> values, const SubdivisionTopology& topology,
                                 bool leftHanded, std::vector<FaceVaryingData>& faceVarying) {
    RefinedPrimvar out;
    out.name = pv.name;
    out.components = pv.components;
    const std::size_t k = static_cast<std::size_t>(pv.components);
    auto element = [&](std::size_t e) {
        std::size_t i = pv.indices.empty() ? e : static_cast<std::size_t>(pv.indices[e]);
        return values.begin() + static_cast<std::ptrdiff_t>(i * k);
    };
    if (pv.interpolation == "constant" || pv.interpolation == "uniform") {
        out.source =
            pv.interpolation == "constant" ? RefinedPrimvar::Source::Constant : RefinedPrimvar::Source::Uniform;
        std::size_t n = pv.interpolation == "constant" ? 1 : topology.faceVertexCounts.size();
        for (std::size_t e = 0; e < n; ++e)
            out.values.insert(out.values.end(), element(e), element(e) + static_cast<std::ptrdiff_t>(k));
    } else if (pv.interpolation == "faceVarying") {
        out.source = RefinedPrimvar::Source::FaceVarying;
        out.channel = static_cast<int>(faceVarying.size());
        FaceVaryingData data{pv.components, std::move(values), pv.indices};
        if (leftHanded) {  // values follow their face-vertices
            std::vector<int> order(pv.elementCount());
            for (std::size_t i = 0; i < order.size(); ++i)
                order[i] = pv.indices.empty() ? static_cast<int>(i) : pv.indices[i];
            reverseFaces(topology.faceVertexCounts, order);
            data.indices = order;
        }
        faceVarying.push_back(std::move(data));
    } else {  // vertex, varying
        out.source = RefinedPrimvar::Source::Vertex;
        out.channel = static_cast<int>(vertexData_.size());
        VertexData data{pv.components, {}, pv.interpolation == "varying"};
        for (std::size_t p = 0; p < points_.size(); ++p)
            data.values.insert(data.values.end(), element(p), element(p) + static_cast<std::ptrdiff_t>(k));
        vertexData_.push_back(std::move(data));
    }
    primvars_.push_back(std::move(out));
}

const float* SubdivisionMesh::cornerValues(const RefinedPrimvar& pv, const SubdivisionSurface::Result& result,
                                           const render::MeshDesc& mesh, std::size_t c) const {
    const std::size_t k = static_cast<std::size_t>(pv.components);
    switch (pv.source) {
        case RefinedPrimvar::Source::Constant: return pv.values.data();
        case RefinedPrimvar::Source::Uniform: return &pv.values[result.triangleFaces[c / 3] * k];
        case RefinedPrimvar::Source::Vertex:
            return &result.vertexData.at(static_cast<std::size_t>(pv.channel))[mesh.indices[c] * k];
        case RefinedPrimvar::Source::FaceVarying: {
            const FaceVaryingData& fv = result.faceVarying.at(static_cast<std::size_t>(pv.channel));
            return &fv.values[static_cast<std::size_t>(fv.indices[c]) * k];
        }
    }
    return pv.values.data();
}

std::shared_ptr<const SubdivisionMesh> SubdivisionMesh::withPoints(const usd::PrimSpec& mesh, double time) const {
    PrimReader prim(mesh, time);
    std::vector<double> points = prim.numbers("points", 3).value_or(std::vector<double>{});
    if (points.size() != 3 * points_.size())
        prim.fail("points has " + std::to_string(points.size() / 3) + " points, but the topology uses " +
                  std::to_string(points_.size()));
    auto copy = std::make_shared<SubdivisionMesh>(*this);
    for (std::size_t i = 0; i < points_.size(); ++i)
        copy->points_[i] = Vec3f(points[3 * i], points[3 * i + 1], points[3 * i + 2]);
    return copy;
}

std::vector<std::string> SubdivisionMesh::materialPaths() const {
    std::vector<std::string> paths = {materials_.meshMaterial};
    for (const MaterialAssignment::Subset& s : materials_.subsets) paths.push_back(s.materialPath);
    return paths;
}

std::vector<int> SubdivisionMesh::segmentsFor(const std::vector<Matrix4>& placements, const DicingContext& context,
                                              float scale) const {
    const float rate = dicingRate_ > 0.0f ? dicingRate_ : context.settings.rate;
    return placedEdgeSegments(context.camera, context.settings, rate, points_, surface_->edges(), placements, scale);
}

std::vector<MeshPart> SubdivisionMesh::tessellate(const std::vector<Matrix4>& placements,
                                                  const DicingContext& context) const {
    const DicingSettings& settings = context.settings;
    auto dice = [&](float scale, int level) {
        try {
            return level >= 0 ? surface_->tessellateUniform(points_, level, vertexData_)
                              : surface_->tessellate(points_, segmentsFor(placements, context, scale), vertexData_);
        } catch (const std::logic_error& e) {  // too many vertices, or OpenSubdiv's data out of range: name the prim
            throw SceneError(path_ + ": " + e.what());
        }
    };
    int level = settings.uniformLevel;
    float scale = context.scale;
    SubdivisionSurface::Result result = dice(scale, level);
    // Over the per-mesh budget: coarser rates (a lower level) until it fits.
    std::size_t wanted = result.indices.size() / 3;
    for (int attempt = 0; result.indices.size() / 3 > settings.meshTriangleBudget && attempt < 8; ++attempt) {
        if (level > 0)
            --level;
        else if (level < 0)
            scale *= 0.9f * std::sqrt(static_cast<float>(settings.meshTriangleBudget) /
                                      static_cast<float>(result.indices.size() / 3));
        else
            break;
        result = dice(scale, level);
    }
    if (result.indices.size() / 3 < wanted)
        context.warn(path_, "tessellation of " + std::to_string(wanted) + " triangles exceeds the per-mesh budget of " +
                                std::to_string(settings.meshTriangleBudget) + "; diced coarser, to " +
                                std::to_string(result.indices.size() / 3) + " triangles");

    TriangulatedMesh whole;
    whole.mesh = meshFrom(result, context);
    whole.triangleFaces.assign(result.triangleFaces.begin(), result.triangleFaces.end());
    whole.faceCount = static_cast<std::size_t>(surface_->faceCount());
    return splitByMaterial(std::move(whole), materials_);
}

render::MeshDesc SubdivisionMesh::meshFrom(const SubdivisionSurface::Result& result,
                                           const DicingContext& context) const {
    render::MeshDesc mesh;
    mesh.name = path_;
    mesh.positions = result.positions;
    mesh.indices = result.indices;
    mesh.cornerNormals = result.cornerNormals;
    const std::size_t corners = mesh.indices.size();
    for (std::size_t i = 0; i < primvars_.size(); ++i) {
        const RefinedPrimvar& pv = primvars_[i];
        const auto k = static_cast<std::ptrdiff_t>(pv.components);
        if (static_cast<int>(i) == displayColor_) {
            for (std::size_t c = 0; c < corners; ++c) {
                const float* v = cornerValues(pv, result, mesh, c);
                mesh.cornerColors.emplace_back(v[0], v[1], v[2]);
            }
            continue;
        }
        render::CornerPrimvar& out = mesh.primvars.emplace_back(render::CornerPrimvar{pv.name, pv.components, {}});
        out.values.reserve(corners * static_cast<std::size_t>(k));
        for (std::size_t c = 0; c < corners; ++c) {
            const float* v = cornerValues(pv, result, mesh, c);
            out.values.insert(out.values.end(), v, v + k);
        }
    }
    displace(mesh, result, context);
    return mesh;
}

void SubdivisionMesh::displace(render::MeshDesc& mesh, const SubdivisionSurface::Result& result,
                               const DicingContext& context) const {
    // Along the limit normal, by the material of the face that evaluated the point.
    auto materialOf = [&](std::uint32_t face) -> const std::string& {
        if (materials_.subsetOfFace.empty()) return materials_.meshMaterial;
        int subset = materials_.subsetOfFace[face];
        return subset == MaterialAssignment::kNoSubset
                   ? materials_.meshMaterial
                   : materials_.subsets[static_cast<std::size_t>(subset)].materialPath;
    };
    std::vector<float> amounts(mesh.positions.size(), 0.0f);
    bool displaced = false;
    const std::vector<std::string> paths = materialPaths();
    for (const std::string& material : std::set<std::string>(paths.begin(), paths.end())) {
        const MaterialDisplacement* displacement = material.empty() ? nullptr : context.displacement(material);
        if (!displacement) continue;
        displaced = true;
        displacement->atVertices(
            mesh, [&](std::size_t v) { return materialOf(result.surfaceCoords[v].face) == material; }, amounts);
    }
    if (displaced) displaceAlongNormals(mesh, result.normals, amounts);
}

}  // namespace fluence::delegate
