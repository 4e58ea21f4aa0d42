// UsdGeomPrimvar reading shared by the mesh adapters: a 3-component primvar (normals,
// displayColor) with its interpolation and optional `:indices`, checked against the mesh.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/vec.h"
#include "delegate/prim_reader.h"

namespace fluence::delegate {

// A primvar flattened to 3-component values, with its interpolation and optional indices.
struct Primvar3 {
    std::vector<double> values;  // 3 per element
    std::vector<int> indices;    // empty when not indexed
    std::string interpolation;
    std::string name;

    std::size_t elementCount() const { return indices.empty() ? values.size() / 3 : indices.size(); }
    Vec3d at(std::size_t element) const {
        std::size_t i = indices.empty() ? element : static_cast<std::size_t>(indices[element]);
        return {values[3 * i], values[3 * i + 1], values[3 * i + 2]};
    }
};

// The primvar `name` (nullopt when not authored), with `defaultInterpolation` when the attribute
// has no interpolation metadata. Out-of-range indices raise SceneError.
std::optional<Primvar3> readPrimvar3(const PrimReader& prim, const std::string& name, const std::string& defaultInterpolation);

// Raises SceneError unless `pv` has the elements its interpolation needs on a mesh of `faces`
// faces, `faceVertices` face-vertices and `points` points.
void checkPrimvarSize(const PrimReader& prim, const Primvar3& pv, std::size_t faces, std::size_t faceVertices,
                      std::size_t points);

}  // namespace fluence::delegate
