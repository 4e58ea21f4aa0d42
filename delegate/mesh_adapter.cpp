#include "delegate/mesh_adapter.h"

#include <set>
#include <utility>

#include "delegate/primvar.h"

namespace fluence::delegate {

namespace {

// Which element of a primvar a triangle corner reads, by interpolation.
struct CornerKey {
    std::size_t face, faceVertex, point;
};

std::size_t elementFor(const Primvar& pv, const CornerKey& k) {
    if (pv.interpolation == "constant") return 0;
    if (pv.interpolation == "uniform") return k.face;
    if (pv.interpolation == "faceVarying") return k.faceVertex;
    return k.point;  // vertex, varying
}

}  // namespace

TriangulatedMesh triangulatedMeshFromPrim(const PrimReader& prim, const Matrix4& toWorld,
                                          const std::function<RGB(const RGB&, const std::string&)>& convertColor) {
    TriangulatedMesh result;
    render::MeshDesc& mesh = result.mesh;
    mesh.name = prim.path();
    std::vector<double> points = prim.numbers("points", 3).value_or(std::vector<double>{});
    std::vector<double> counts = prim.numbers("faceVertexCounts", 1).value_or(std::vector<double>{});
    std::vector<double> indices = prim.numbers("faceVertexIndices", 1).value_or(std::vector<double>{});
    const std::size_t pointCount = points.size() / 3;

    std::size_t total = 0;
    for (std::size_t f = 0; f < counts.size(); ++f) {
        if (counts[f] < 0) prim.fail("faceVertexCounts[" + std::to_string(f) + "] is negative");
        total += static_cast<std::size_t>(counts[f]);
    }
    if (total != indices.size())
        prim.fail("faceVertexCounts add up to " + std::to_string(total) + " but faceVertexIndices has " +
                  std::to_string(indices.size()) + " entries");
    for (std::size_t i = 0; i < indices.size(); ++i)
        if (indices[i] < 0 || indices[i] >= static_cast<double>(pointCount))
            prim.fail("faceVertexIndices[" + std::to_string(i) +
                      "] = " + std::to_string(static_cast<long long>(indices[i])) + " is out of range (" +
                      std::to_string(pointCount) + " points)");

    std::set<std::size_t> holes;
    for (double h : prim.numbers("holeIndices", 1).value_or(std::vector<double>{}))
        holes.insert(static_cast<std::size_t>(h));
    const bool leftHanded = prim.token({"orientation"}, "rightHanded") == "leftHanded";

    std::optional<Primvar> normals = readPrimvar(prim, "primvars:normals", "vertex");
    if (!normals) normals = readPrimvar(prim, "normals", "vertex");
    std::optional<Primvar> colors = readPrimvar(prim, "primvars:displayColor", "constant");
    if (normals) checkPrimvarSize(prim, *normals, counts.size(), indices.size(), pointCount);
    if (colors) checkPrimvarSize(prim, *colors, counts.size(), indices.size(), pointCount);
    std::string colorSpace = colors ? prim.attributeMetadata("primvars:displayColor", "colorSpace").value_or("") : "";
    std::vector<Primvar> shading = readShadingPrimvars(prim);
    for (const Primvar& pv : shading) {
        checkPrimvarSize(prim, pv, counts.size(), indices.size(), pointCount);
        mesh.primvars.push_back({pv.name, pv.components, {}});
    }

    mesh.positions.reserve(pointCount);
    for (std::size_t i = 0; i < pointCount; ++i)
        mesh.positions.emplace_back(toWorld.transformPoint({points[3 * i], points[3 * i + 1], points[3 * i + 2]}));

    auto addCorner = [&](const CornerKey& k) {
        mesh.indices.push_back(static_cast<std::uint32_t>(k.point));
        if (normals) {
            Vec3d n = toWorld.transformNormal(normals->at(elementFor(*normals, k)));
            double len = length(n);
            mesh.cornerNormals.emplace_back(len > 0.0 ? n / len : n);
        }
        if (colors) mesh.cornerColors.push_back(convertColor(RGB(colors->at(elementFor(*colors, k))), colorSpace));
        for (std::size_t i = 0; i < shading.size(); ++i) {
            const double* v = shading[i].element(elementFor(shading[i], k));
            for (int c = 0; c < shading[i].components; ++c) mesh.primvars[i].values.push_back(static_cast<float>(v[c]));
        }
    };

    std::size_t start = 0;
    for (std::size_t f = 0; f < counts.size(); ++f) {
        std::size_t n = static_cast<std::size_t>(counts[f]);
        if (n >= 3 && !holes.contains(f)) {
            auto key = [&](std::size_t corner) {
                return CornerKey{f, start + corner, static_cast<std::size_t>(indices[start + corner])};
            };
            for (std::size_t c = 1; c + 1 < n; ++c) {
                addCorner(key(0));
                addCorner(key(leftHanded ? c + 1 : c));
                addCorner(key(leftHanded ? c : c + 1));
                result.triangleFaces.push_back(f);
            }
        }
        start += n;
    }
    result.faceCount = counts.size();
    return result;
}

render::MeshDesc meshFromPrim(const PrimReader& prim, const Matrix4& toWorld,
                              const std::function<RGB(const RGB&, const std::string&)>& convertColor) {
    return std::move(triangulatedMeshFromPrim(prim, toWorld, convertColor).mesh);
}

}  // namespace fluence::delegate
