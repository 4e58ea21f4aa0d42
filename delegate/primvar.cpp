#include "delegate/primvar.h"

namespace fluence::delegate {

std::optional<Primvar> readPrimvar(const PrimReader& prim, const std::string& name,
                                   const std::string& defaultInterpolation, int components) {
    std::optional<std::vector<double>> values = prim.numbers(name, components);
    if (!values) return std::nullopt;
    Primvar pv;
    pv.name = name;
    pv.components = components;
    pv.values = std::move(*values);
    pv.interpolation = prim.attributeMetadata(name, "interpolation").value_or(defaultInterpolation);
    if (auto idx = prim.numbers(name + ":indices", 1)) {
        for (double d : *idx) {
            if (d < 0 || d >= static_cast<double>(pv.values.size() / components))
                prim.fail("'" + name + ":indices' holds " + std::to_string(static_cast<long long>(d)) +
                          ", outside the " + std::to_string(pv.values.size() / components) + " values of '" + name +
                          "'");
            pv.indices.push_back(static_cast<int>(d));
        }
    }
    return pv;
}

void checkPrimvarSize(const PrimReader& prim, const Primvar& pv, std::size_t faces, std::size_t faceVertices,
                      std::size_t points) {
    std::size_t need;
    if (pv.interpolation == "constant")
        need = 1;
    else if (pv.interpolation == "uniform")
        need = faces;
    else if (pv.interpolation == "faceVarying")
        need = faceVertices;
    else if (pv.interpolation == "vertex" || pv.interpolation == "varying")
        need = points;
    else
        prim.fail("'" + pv.name + "' has unknown interpolation '" + pv.interpolation + "'");
    if (pv.elementCount() < need)
        prim.fail("'" + pv.name + "' has " + std::to_string(pv.elementCount()) + " values but " + pv.interpolation +
                  " interpolation needs " + std::to_string(need));
}

std::vector<Primvar> readShadingPrimvars(const PrimReader& prim) {
    std::vector<Primvar> out;
    for (const usd::AttributeSpec& a : prim.prim().attributes) {
        if (!a.name.starts_with("primvars:") || a.name.ends_with(":indices") || a.name == "primvars:normals") continue;
        if (a.name.starts_with("primvars:skel:")) continue;  // UsdSkel's joint influences, not shading data
        std::optional<usd::Value> v = prim.value(a.name);
        if (!v || !v->isNumeric() || v->components < 1 || v->components > 3) continue;
        const std::string& type = v->typeName;
        if (!(type.starts_with("float") || type.starts_with("double") || type.starts_with("half") ||
              type.starts_with("texCoord") || type.starts_with("color") || type.starts_with("normal") ||
              type.starts_with("vector") || type.starts_with("point")))
            continue;
        if (std::optional<Primvar> pv = readPrimvar(prim, a.name, "constant", v->components)) {
            pv->name = a.name.substr(9);
            out.push_back(std::move(*pv));
        }
    }
    return out;
}

}  // namespace fluence::delegate
