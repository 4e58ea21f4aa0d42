#include "delegate/primvar.h"

namespace fluence::delegate {

std::optional<Primvar3> readPrimvar3(const PrimReader& prim, const std::string& name, const std::string& defaultInterpolation) {
    std::optional<std::vector<double>> values = prim.numbers(name, 3);
    if (!values) return std::nullopt;
    Primvar3 pv;
    pv.name = name;
    pv.values = std::move(*values);
    pv.interpolation = prim.attributeMetadata(name, "interpolation").value_or(defaultInterpolation);
    if (auto idx = prim.numbers(name + ":indices", 1)) {
        for (double d : *idx) {
            if (d < 0 || d >= static_cast<double>(pv.values.size() / 3))
                prim.fail("'" + name + ":indices' holds " + std::to_string(static_cast<long long>(d)) + ", outside the " +
                          std::to_string(pv.values.size() / 3) + " values of '" + name + "'");
            pv.indices.push_back(static_cast<int>(d));
        }
    }
    return pv;
}

void checkPrimvarSize(const PrimReader& prim, const Primvar3& pv, std::size_t faces, std::size_t faceVertices,
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

}  // namespace fluence::delegate
