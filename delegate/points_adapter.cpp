#include "delegate/points_adapter.h"

#include <cmath>
#include <optional>

#include "delegate/primvar.h"
#include "render/mesh_transform.h"

namespace fluence::delegate {

namespace {

// The element of `pv` for point `i` of `count`: a single value applies to every point, else the
// primvar must hold one per point.
std::size_t elementFor(const PrimReader& prim, const Primvar& pv, std::size_t count, std::size_t i) {
    const std::size_t n = pv.elementCount();
    if (n == 1 || pv.interpolation == "constant" || pv.interpolation == "uniform") return 0;
    if (n != count)
        prim.fail("'" + pv.name + "' has " + std::to_string(n) + " values for " + std::to_string(count) + " points");
    return i;
}

// Whether a colour or shading primvar has a value for each of `count` points (or one for them all);
// if not, it is ignored with a warning, and what reads it falls back to its constant value.
bool perPointOrDropped(const Primvar& pv, std::size_t count, const std::function<void(const std::string&)>& warn) {
    const std::size_t n = pv.elementCount();
    if (n == 1 || pv.interpolation == "constant" || pv.interpolation == "uniform" || n == count) return n > 0;
    warn("'" + pv.name + "' has " + std::to_string(n) + " values for " + std::to_string(count) +
         " points; it is ignored");
    return false;
}

std::optional<Primvar> widthsOf(const PrimReader& prim) {
    if (std::optional<Primvar> pv = readPrimvar(prim, "primvars:widths", "vertex", 1)) return pv;
    return readPrimvar(prim, "widths", "vertex", 1);
}

std::optional<Primvar> normalsOf(const PrimReader& prim) {
    if (std::optional<Primvar> pv = readPrimvar(prim, "primvars:normals", "vertex")) return pv;
    return readPrimvar(prim, "normals", "vertex");
}

render::PointStyle styleOf(const PrimReader& prim, bool hasNormals) {
    const std::string style = prim.token({"primvars:fluence:pointStyle"}, "sphere");
    if (style == "sphere") return render::PointStyle::Sphere;
    if (style == "disc") return render::PointStyle::Disc;
    if (style == "orientedDisc") return hasNormals ? render::PointStyle::OrientedDisc : render::PointStyle::Disc;
    prim.fail("primvars:fluence:pointStyle must be \"sphere\", \"disc\" or \"orientedDisc\", got \"" + style + "\"");
}

}  // namespace

render::PointsDesc pointsFromPrim(const PrimReader& prim,
                                  const std::function<RGB(const RGB&, const std::string&)>& convertColor,
                                  const std::function<void(const std::string&)>& warn) {
    render::PointsDesc p;
    p.name = prim.path();
    if (std::optional<std::vector<double>> points = prim.numbers("points", 3))
        for (std::size_t i = 0; i + 2 < points->size(); i += 3)
            p.positions.emplace_back(Vec3d((*points)[i], (*points)[i + 1], (*points)[i + 2]));
    const std::size_t n = p.positions.size();

    const std::optional<Primvar> widths = widthsOf(prim);
    p.radii.assign(n, 0.5f);
    if (widths && widths->elementCount() > 0)
        for (std::size_t i = 0; i < n; ++i) {
            const double w = widths->element(elementFor(prim, *widths, n, i))[0];
            if (!(w >= 0.0) || !std::isfinite(w))
                prim.fail("widths must be finite and not negative, got " + std::to_string(w));
            p.radii[i] = static_cast<float>(0.5 * w);
        }

    const std::optional<Primvar> normals = normalsOf(prim);
    p.style = styleOf(prim, normals && normals->elementCount() > 0);
    if (p.style == render::PointStyle::OrientedDisc)
        for (std::size_t i = 0; i < n; ++i) p.normals.emplace_back(normals->at(elementFor(prim, *normals, n, i)));

    if (std::optional<Primvar> color = readPrimvar(prim, "primvars:displayColor", "constant");
        color && perPointOrDropped(*color, n, warn)) {
        const std::string space = prim.attributeMetadata("primvars:displayColor", "colorSpace").value_or("");
        for (std::size_t i = 0; i < n; ++i)
            p.colors.push_back(convertColor(RGB(color->at(elementFor(prim, *color, n, i))), space));
    }
    for (const Primvar& pv : readShadingPrimvars(prim)) {
        if (!perPointOrDropped(pv, n, warn)) continue;
        render::PointPrimvar& out = p.primvars.emplace_back(render::PointPrimvar{pv.name, pv.components, {}});
        for (std::size_t i = 0; i < n; ++i) {
            const double* v = pv.element(elementFor(prim, pv, n, i));
            for (int c = 0; c < pv.components; ++c) out.values.push_back(static_cast<float>(v[c]));
        }
    }
    return p;
}

render::PointsDesc pointsToWorld(render::PointsDesc p, const Matrix4& toWorld) {
    render::transformPrimitives(p.positions, p.radii, p.normals, toWorld);
    return p;
}

}  // namespace fluence::delegate
