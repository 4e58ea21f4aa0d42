// UsdGeomPrimvar reading shared by the mesh adapters: a primvar (normals, displayColor, st, ...)
// with its interpolation and optional `:indices`, checked against the mesh; and the shading
// primvars a mesh hands the render core for its material's nodes.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/vec.h"
#include "delegate/prim_reader.h"

namespace fluence::delegate {

// A primvar flattened to `components` values per element, with its interpolation and optional indices.
struct Primvar {
    std::vector<double> values;  // components per element
    std::vector<int> indices;    // empty when not indexed
    std::string interpolation;
    std::string name;
    int components = 3;

    std::size_t elementCount() const { return indices.empty() ? values.size() / components : indices.size(); }
    // The first value of an element (components values follow it).
    const double* element(std::size_t e) const {
        std::size_t i = indices.empty() ? e : static_cast<std::size_t>(indices[e]);
        return &values[i * static_cast<std::size_t>(components)];
    }
    Vec3d at(std::size_t e) const {  // a 3-component element
        const double* v = element(e);
        return {v[0], v[1], v[2]};
    }
};

// The primvar `name` of `components` components (nullopt when not authored), with
// `defaultInterpolation` when the attribute has no interpolation metadata. Values of another
// shape and out-of-range indices raise SceneError.
std::optional<Primvar> readPrimvar(const PrimReader& prim, const std::string& name,
                                   const std::string& defaultInterpolation, int components = 3);

// The primvars a material's nodes may read (UsdPrimvarReader varnames): every authored
// "primvars:NAME" of 1 to 3 floating-point components (st, float, float3, colours...), except
// normals and UsdSkel's primvars:skel:*, with "constant" as the default interpolation. Names are
// without "primvars:".
std::vector<Primvar> readShadingPrimvars(const PrimReader& prim);

// Raises SceneError unless `pv` has the elements its interpolation needs on a mesh of `faces`
// faces, `faceVertices` face-vertices and `points` points.
void checkPrimvarSize(const PrimReader& prim, const Primvar& pv, std::size_t faces, std::size_t faceVertices,
                      std::size_t points);

}  // namespace fluence::delegate
