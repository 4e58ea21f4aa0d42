#include "delegate/tet_mesh.h"

#include <algorithm>
#include <map>

#include "delegate/prim_copy.h"

namespace fluence::delegate {

std::vector<std::array<int, 3>> tetSurfaceFaces(const std::vector<std::array<int, 4>>& tets) {
    static constexpr int kFaces[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
    std::map<std::array<int, 3>, std::pair<int, std::array<int, 3>>> bySignature;  // sorted -> (count, face)
    for (const std::array<int, 4>& tet : tets)
        for (const auto& f : kFaces) {
            const std::array<int, 3> face{tet[f[0]], tet[f[1]], tet[f[2]]};
            std::array<int, 3> signature = face;
            std::sort(signature.begin(), signature.end());
            auto& [count, kept] = bySignature[signature];
            ++count;
            kept = face;
        }
    std::vector<std::array<int, 3>> surface;
    for (const auto& [signature, entry] : bySignature)
        if (entry.first == 1) surface.push_back(entry.second);
    std::sort(surface.begin(), surface.end());
    return surface;
}

namespace {

// The int arrays of `name` as groups of `N`, each index checked against `points`.
template <std::size_t N>
std::vector<std::array<int, N>> indexGroups(const PrimReader& prim, const std::string& name, std::size_t points) {
    const std::vector<double> numbers = prim.numbers(name, static_cast<int>(N)).value_or(std::vector<double>{});
    std::vector<std::array<int, N>> groups(numbers.size() / N);
    for (std::size_t i = 0; i < numbers.size(); ++i) {
        if (!(numbers[i] >= 0.0 && numbers[i] < static_cast<double>(points)))
            prim.fail(name + "[" + std::to_string(i / N) + "] names point " +
                      std::to_string(static_cast<long long>(numbers[i])) + " of " + std::to_string(points));
        groups[i / N][i % N] = static_cast<int>(numbers[i]);
    }
    return groups;
}

}  // namespace

std::unique_ptr<usd::PrimSpec> tetMeshSurface(const PrimReader& prim) {
    const std::size_t points = prim.numbers("points", 3).value_or(std::vector<double>{}).size() / 3;
    std::vector<std::array<int, 3>> faces = prim.value("surfaceFaceVertexIndices")
                                                ? indexGroups<3>(prim, "surfaceFaceVertexIndices", points)
                                                : tetSurfaceFaces(indexGroups<4>(prim, "tetVertexIndices", points));
    std::vector<double> indices;
    indices.reserve(3 * faces.size());
    for (const std::array<int, 3>& f : faces) indices.insert(indices.end(), {double(f[0]), double(f[1]), double(f[2])});
    std::unique_ptr<usd::PrimSpec> mesh = copyPrim(prim.prim());
    mesh->typeName = "Mesh";
    std::erase_if(mesh->attributes, [](const usd::AttributeSpec& a) {
        return a.name == "surfaceFaceVertexIndices" || a.name == "tetVertexIndices";
    });
    setArray(*mesh, "faceVertexCounts", "int[]", std::vector<double>(faces.size(), 3.0), 1);
    setArray(*mesh, "faceVertexIndices", "int[]", std::move(indices), 1);
    usd::AttributeSpec scheme;
    scheme.name = "subdivisionScheme";
    scheme.typeName = "token";
    scheme.uniform = true;
    scheme.hasDefault = true;
    scheme.defaultValue = usd::Value::string("token", usd::ValueKind::Token, {"none"}, false);
    std::erase_if(mesh->attributes, [](const usd::AttributeSpec& a) { return a.name == "subdivisionScheme"; });
    mesh->attributes.push_back(std::move(scheme));
    return mesh;
}

}  // namespace fluence::delegate
