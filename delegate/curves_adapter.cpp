#include "delegate/curves_adapter.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "delegate/primvar.h"
#include "render/mesh_transform.h"

namespace fluence::delegate {

namespace {

using render::CurveBasis;

enum class Wrap { Nonperiodic, Periodic, Pinned };

// A curve batch's type, basis and wrap, and what UsdGeom's tables derive from them.
struct Topology {
    CurveBasis basis = CurveBasis::Linear;
    Wrap wrap = Wrap::Nonperiodic;

    std::size_t vstep() const { return basis == CurveBasis::Bezier ? 3 : 1; }
    bool periodic() const { return wrap == Wrap::Periodic; }
    bool phantoms() const {
        return wrap == Wrap::Pinned && (basis == CurveBasis::BSpline || basis == CurveBasis::CatmullRom);
    }
    // The segments of a curve of n vertices; 0 when n is not a valid count.
    std::size_t segments(std::size_t n) const {
        if (basis == CurveBasis::Linear) return periodic() ? (n >= 3 ? n : 0) : (n >= 2 ? n - 1 : 0);
        if (periodic()) return n >= 3 && n % vstep() == 0 ? n / vstep() : 0;
        if (phantoms()) return n >= 2 ? n - 1 : 0;
        return n >= 4 && (n - 4) % vstep() == 0 ? (n - 4) / vstep() + 1 : 0;
    }
    std::size_t varying(std::size_t n) const { return periodic() ? segments(n) : segments(n) + 1; }
    // Where vertex j of a curve of n vertices sits in the curve's varying values (fractional
    // between two segment ends).
    double varyingPosition(std::size_t j, std::size_t n) const {
        const double jd = static_cast<double>(j);
        if (basis == CurveBasis::Linear || phantoms()) return jd;
        if (basis == CurveBasis::Bezier) return jd / 3.0;
        if (periodic()) return static_cast<double>((j + n - 1) % n);
        return std::clamp(jd - 1.0, 0.0, static_cast<double>(n - 3));
    }
};

Topology topologyOf(const PrimReader& prim) {
    Topology t;
    const std::string type = prim.token({"type"}, "cubic"), basis = prim.token({"basis"}, "bezier"),
                      wrap = prim.token({"wrap"}, "nonperiodic");
    if (type == "linear")
        t.basis = CurveBasis::Linear;
    else if (type != "cubic")
        prim.fail("type '" + type + "' is not linear or cubic");
    else if (basis == "bezier")
        t.basis = CurveBasis::Bezier;
    else if (basis == "bspline")
        t.basis = CurveBasis::BSpline;
    else if (basis == "catmullRom")
        t.basis = CurveBasis::CatmullRom;
    else
        prim.fail("basis '" + basis + "' is not bezier, bspline or catmullRom");
    if (wrap == "periodic")
        t.wrap = Wrap::Periodic;
    else if (wrap == "pinned")
        t.wrap = Wrap::Pinned;
    else if (wrap != "nonperiodic")
        prim.fail("wrap '" + wrap + "' is not nonperiodic, periodic or pinned");
    return t;
}

// The curves of a batch: each one's first vertex and vertex count.
struct Curve {
    std::size_t first = 0, count = 0;
};

std::vector<Curve> curvesOf(const PrimReader& prim, std::size_t points) {
    std::vector<Curve> curves;
    std::size_t first = 0;
    for (double c : prim.numbers("curveVertexCounts", 1).value_or(std::vector<double>{})) {
        if (c < 0) prim.fail("curveVertexCounts holds a negative count");
        curves.push_back({first, static_cast<std::size_t>(c)});
        first += static_cast<std::size_t>(c);
    }
    if (first != points)
        prim.fail("curveVertexCounts add up to " + std::to_string(first) + " but there are " + std::to_string(points) +
                  " points");
    return curves;
}

// A primvar's values along a curve: `k` components per vertex of the curve (or per sample, for
// an evaluated NURBS curve).
using Values = std::vector<double>;

// The element of a non-vertex primvar at `position` along curve `c`'s varying values (m of them,
// from `firstVarying`), interpolated linearly; constant and uniform ones are the same all along.
void appendAlong(const Primvar& pv, std::size_t c, std::size_t firstVarying, std::size_t m, double position,
                 bool periodic, Values& out) {
    const auto k = static_cast<std::size_t>(pv.components);
    if (pv.interpolation != "varying") {
        const double* v = pv.element(pv.interpolation == "uniform" ? c : 0);
        out.insert(out.end(), v, v + k);
        return;
    }
    const std::size_t lo = std::min(static_cast<std::size_t>(position), m - 1);
    const std::size_t hi = periodic ? (lo + 1) % m : std::min(lo + 1, m - 1);
    const double w = position - static_cast<double>(lo);
    const double *a = pv.element(firstVarying + lo), *b = pv.element(firstVarying + hi);
    for (std::size_t i = 0; i < k; ++i) out.push_back(a[i] * (1.0 - w) + b[i] * w);
}

// What keeps `pv` from having the values its interpolation needs ("" when nothing does).
std::string countProblem(Primvar& pv, std::size_t curves, std::size_t varying, std::size_t vertices) {
    if (pv.elementCount() == 1)
        pv.interpolation = "constant";  // one value can only mean the whole prim (as Hydra reads it)
    std::size_t need = 0;
    if (pv.interpolation == "constant")
        need = 1;
    else if (pv.interpolation == "uniform")
        need = curves;
    else if (pv.interpolation == "varying")
        need = varying;
    else if (pv.interpolation == "vertex")
        need = vertices;
    else
        return "'" + pv.name + "' has interpolation '" + pv.interpolation + "', which curves do not take";
    if (pv.elementCount() < need)
        return "'" + pv.name + "' has " + std::to_string(pv.elementCount()) + " values but " + pv.interpolation +
               " interpolation needs " + std::to_string(need);
    return "";
}

// Raises SceneError unless `pv` has the values its interpolation needs.
void checkCount(const PrimReader& prim, Primvar& pv, std::size_t curves, std::size_t varying, std::size_t vertices) {
    if (const std::string problem = countProblem(pv, curves, varying, vertices); !problem.empty()) prim.fail(problem);
}

// The primvars a curve batch carries, read and checked: its geometry's, displayColor, and the
// shading primvars a material may read (delegate/primvar.h).
struct CurvePrimvars {
    std::optional<Primvar> widths, normals, colors;
    std::string colorSpace;
    std::vector<Primvar> shading;
};

CurvePrimvars readCurvePrimvars(const PrimReader& prim) {
    CurvePrimvars p;
    p.widths = readPrimvar(prim, "primvars:widths", "vertex", 1);
    if (!p.widths) p.widths = readPrimvar(prim, "widths", "vertex", 1);
    p.normals = readPrimvar(prim, "primvars:normals", "vertex");
    if (!p.normals) p.normals = readPrimvar(prim, "normals", "vertex");
    p.colors = readPrimvar(prim, "primvars:displayColor", "constant");
    if (p.colors) p.colorSpace = prim.attributeMetadata("primvars:displayColor", "colorSpace").value_or("");
    for (Primvar& pv : readShadingPrimvars(prim))
        if (pv.name != "widths" && pv.elementCount() > 0) p.shading.push_back(std::move(pv));
    return p;
}

// Widths and normals of the wrong length make the prim malformed (SceneError); a colour or shading
// primvar of the wrong length is dropped with a warning, and what reads it falls back to its
// constant value (the material's colour, a primvar reader's fallback).
void checkCounts(const PrimReader& prim, CurvePrimvars& p, std::size_t curves, std::size_t varying,
                 std::size_t vertices, const std::function<void(const std::string&)>& warn) {
    for (std::optional<Primvar>* pv : {&p.widths, &p.normals})
        if (*pv) checkCount(prim, **pv, curves, varying, vertices);
    auto keeps = [&](Primvar& pv, bool quiet) {
        const std::string problem = countProblem(pv, curves, varying, vertices);
        if (!problem.empty() && !quiet) warn(problem + "; it is ignored");
        return problem.empty();
    };
    if (p.colors && !keeps(*p.colors, false)) p.colors.reset();
    // displayColor is a shading primvar too: its warning is said once.
    std::erase_if(p.shading, [&](Primvar& pv) { return !keeps(pv, pv.name == "displayColor"); });
}

// A shading primvar carried per vertex (or per evaluated sample), as `Values` are.
struct PerVertexPrimvar {
    std::string name;
    int components = 1;
    Values values;
};

// Per-vertex values of every primvar, the way a batch of BasisCurves lays them out: points,
// widths, normals and colours, one entry per authored vertex (or per evaluated sample).
struct VertexData {
    Values points, widths, normals, colors;
    std::vector<PerVertexPrimvar> shading;
};

render::CurveStyle styleOf(const PrimReader& prim, bool hasNormals) {
    const std::string style = prim.token({"primvars:fluence:curveStyle"}, "");
    if (style == "flat") return render::CurveStyle::Flat;
    if (style == "round") return render::CurveStyle::Round;
    if (style == "ribbon" && !hasNormals)
        prim.fail("primvars:fluence:curveStyle is 'ribbon' but no normals are authored");
    if (!style.empty() && style != "ribbon")
        prim.fail("primvars:fluence:curveStyle '" + style + "' is not round, flat or ribbon");
    return hasNormals ? render::CurveStyle::Oriented : render::CurveStyle::Round;
}

// Unrolls per-vertex data into Embree's control points (periodic curves repeat their first
// vertices, pinned ones gain phantom points) and segments.
render::CurvesDesc unrolled(const PrimReader& prim, const Topology& topo, const std::vector<Curve>& curves,
                            const VertexData& data, const CurvePrimvars& primvars, const ColorConverter& convertColor) {
    render::CurvesDesc desc;
    desc.name = prim.path();
    desc.basis = topo.basis;
    desc.style = styleOf(prim, !data.normals.empty());
    auto vec3 = [](const Values& v, std::size_t i) { return Vec3f(Vec3d(v[3 * i], v[3 * i + 1], v[3 * i + 2])); };
    for (const PerVertexPrimvar& pv : data.shading) desc.primvars.push_back({pv.name, pv.components, false, {}});
    // Control point from vertex `a`, or the phantom 2 a - b.
    auto push = [&](std::size_t a, std::optional<std::size_t> b) {
        auto extrapolated = [&](auto value) { return b ? value(a) * 2.0f - value(*b) : value(a); };
        desc.points.push_back(extrapolated([&](std::size_t i) { return vec3(data.points, i); }));
        desc.radii.push_back(std::max(0.0f, 0.5f * extrapolated([&](std::size_t i) {
                                                return data.widths.empty() ? 1.0f : static_cast<float>(data.widths[i]);
                                            })));
        if (!data.normals.empty())
            desc.normals.push_back(extrapolated([&](std::size_t i) { return vec3(data.normals, i); }));
        if (!data.colors.empty())
            desc.colors.push_back(convertColor(RGB(extrapolated([&](std::size_t i) { return vec3(data.colors, i); })),
                                               primvars.colorSpace));
        for (std::size_t v = 0; v < data.shading.size(); ++v) {
            const auto k = static_cast<std::size_t>(data.shading[v].components);
            for (std::size_t c = 0; c < k; ++c)
                desc.primvars[v].values.push_back(
                    static_cast<float>(extrapolated([&](std::size_t i) { return data.shading[v].values[i * k + c]; })));
        }
    };
    for (const Curve& c : curves) {
        const auto base = static_cast<std::uint32_t>(desc.points.size());
        const std::size_t last = c.first + c.count - 1;
        if (topo.phantoms()) push(c.first, c.first + 1);
        for (std::size_t j = c.first; j <= last; ++j) push(j, std::nullopt);
        if (topo.periodic())
            for (std::size_t j = 0; j < (topo.basis == CurveBasis::Linear ? 1 : 4 - topo.vstep()); ++j)
                push(c.first + j, std::nullopt);
        if (topo.phantoms()) push(last, last - 1);
        for (std::size_t s = 0; s < topo.segments(c.count); ++s)
            desc.segments.push_back(base + static_cast<std::uint32_t>(s * topo.vstep()));
    }
    return desc;
}

// A varying, uniform or constant primvar of a BasisCurves batch at the two ends of each segment of
// its valid curves, in the order of their segments: varying values linear between segment ends, as
// UsdGeomBasisCurves defines them, whatever the basis.
render::CurvePrimvar atSegmentEnds(const Primvar& pv, const Topology& topo, const std::vector<Curve>& curves) {
    render::CurvePrimvar out{pv.name, pv.components, true, {}};
    std::size_t firstVarying = 0;
    for (std::size_t i = 0; i < curves.size(); ++i) {
        const std::size_t segments = topo.segments(curves[i].count);
        if (segments == 0) continue;  // a curve left out (its varying values count none)
        const std::size_t m = topo.varying(curves[i].count);
        for (std::size_t s = 0; s < segments; ++s)
            for (std::size_t end : {s, topo.periodic() ? (s + 1) % m : s + 1}) {
                const std::size_t e = pv.interpolation == "varying"   ? firstVarying + end
                                      : pv.interpolation == "uniform" ? i
                                                                      : 0;
                const double* v = pv.element(e);
                for (int c = 0; c < pv.components; ++c) out.values.push_back(static_cast<float>(v[c]));
            }
        firstVarying += m;
    }
    return out;
}

render::CurvesDesc basisCurvesFromPrim(const PrimReader& prim, const ColorConverter& convertColor,
                                       const std::function<void(const std::string&)>& warn) {
    const Topology topo = topologyOf(prim);
    VertexData data;
    data.points = prim.numbers("points", 3).value_or(Values{});
    const std::vector<Curve> curves = curvesOf(prim, data.points.size() / 3);
    // A curve whose count fits no segment is left out alone (its varying values count none), as
    // Hydra leaves it; the others render.
    std::vector<Curve> valid;
    std::size_t varying = 0, invalid = 0;
    for (std::size_t i = 0; i < curves.size(); ++i) {
        if (topo.segments(curves[i].count) == 0) {
            if (invalid++ == 0)
                warn("curve " + std::to_string(i) + " has " + std::to_string(curves[i].count) +
                     " vertices, not a valid count for its type, basis and wrap; such curves are left out");
            continue;
        }
        valid.push_back(curves[i]);
        varying += topo.varying(curves[i].count);
    }
    if (invalid > 1)
        warn(std::to_string(invalid) + " of its " + std::to_string(curves.size()) +
             " curves are left out for their vertex counts");
    CurvePrimvars primvars = readCurvePrimvars(prim);
    checkCounts(prim, primvars, curves.size(), varying, data.points.size() / 3, warn);
    auto expand = [&](const Primvar& pv, Values& out) {
        std::size_t firstVarying = 0;
        for (std::size_t i = 0; i < curves.size(); ++i) {
            const Curve& c = curves[i];
            const std::size_t m = topo.segments(c.count) == 0 ? 0 : topo.varying(c.count);
            for (std::size_t j = 0; j < c.count; ++j) {
                if (pv.interpolation == "vertex") {
                    const double* v = pv.element(c.first + j);
                    out.insert(out.end(), v, v + pv.components);
                } else if (pv.interpolation == "varying" && m == 0) {
                    out.insert(out.end(), static_cast<std::size_t>(pv.components), 0.0);  // a curve left out
                } else {
                    appendAlong(pv, i, firstVarying, m, topo.varyingPosition(j, c.count), topo.periodic(), out);
                }
            }
            firstVarying += m;
        }
    };
    if (primvars.widths) expand(*primvars.widths, data.widths);
    if (primvars.normals) expand(*primvars.normals, data.normals);
    if (primvars.colors) expand(*primvars.colors, data.colors);
    for (const Primvar& pv : primvars.shading)
        if (pv.interpolation == "vertex") expand(pv, data.shading.emplace_back(pv.name, pv.components).values);
    render::CurvesDesc desc = unrolled(prim, topo, valid, data, primvars, convertColor);
    for (const Primvar& pv : primvars.shading)
        if (pv.interpolation != "vertex") desc.primvars.push_back(atSegmentEnds(pv, topo, curves));
    return desc;
}

// The B-spline basis functions of degree p that are non-zero at t in knot span `span`
// (The NURBS Book, algorithm A2.2).
std::vector<double> basisFunctions(const double* knots, std::size_t span, int p, double t) {
    std::vector<double> n(static_cast<std::size_t>(p) + 1, 0.0), left(n.size()), right(n.size());
    n[0] = 1.0;
    for (int j = 1; j <= p; ++j) {
        left[j] = t - knots[span + 1 - j];
        right[j] = knots[span + j] - t;
        double saved = 0.0;
        for (int r = 0; r < j; ++r) {
            const double denominator = right[r + 1] + left[j - r];
            const double temp = denominator != 0.0 ? n[r] / denominator : 0.0;
            n[r] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        n[j] = saved;
    }
    return n;
}

// Samples per knot span of an evaluated NURBS curve.
constexpr std::size_t kSamplesPerSpan = 8;

render::CurvesDesc nurbsCurvesFromPrim(const PrimReader& prim, const ColorConverter& convertColor,
                                       const std::function<void(const std::string&)>& warn) {
    const Values points = prim.numbers("points", 3).value_or(Values{});
    const std::vector<Curve> curves = curvesOf(prim, points.size() / 3);
    const Values orders = prim.numbers("order", 1).value_or(Values(curves.size(), 4.0));
    const Values knots = prim.numbers("knots", 1).value_or(Values{});
    const Values weights = prim.numbers("pointWeights", 1).value_or(Values(points.size() / 3, 1.0));
    const Values ranges = prim.numbers("ranges", 2).value_or(Values{});
    if (orders.size() != curves.size())
        prim.fail("order has " + std::to_string(orders.size()) + " values for " + std::to_string(curves.size()) +
                  " curves");
    if (weights.size() != points.size() / 3)
        prim.fail("pointWeights has " + std::to_string(weights.size()) + " values for " +
                  std::to_string(points.size() / 3) + " points");
    if (!ranges.empty() && ranges.size() != 2 * curves.size())
        prim.fail("ranges has " + std::to_string(ranges.size() / 2) + " values for " + std::to_string(curves.size()) +
                  " curves");
    std::size_t knotCount = 0, varying = 0;
    for (std::size_t i = 0; i < curves.size(); ++i) {
        const auto order = static_cast<std::size_t>(orders[i]);
        if (orders[i] < 2 || curves[i].count < order)
            prim.fail("curve " + std::to_string(i) + " has order " + std::to_string(static_cast<long long>(orders[i])) +
                      " and " + std::to_string(curves[i].count) +
                      " vertices (order must be 2 or more and at most the vertex count)");
        knotCount += curves[i].count + order;
        varying += curves[i].count - order + 2;
    }
    if (knots.size() != knotCount)
        prim.fail("knots has " + std::to_string(knots.size()) + " values; the curves' vertex counts and orders need " +
                  std::to_string(knotCount));
    for (std::size_t i = 1; i < knots.size(); ++i)
        if (knots[i] < knots[i - 1]) prim.fail("knots decrease at index " + std::to_string(i));
    CurvePrimvars primvars = readCurvePrimvars(prim);
    checkCounts(prim, primvars, curves.size(), varying, points.size() / 3, warn);

    // Each curve sampled, as the vertices of a pinned Catmull-Rom batch; its primvars per sample.
    VertexData data;
    for (const Primvar& pv : primvars.shading) data.shading.emplace_back(pv.name, pv.components);
    std::vector<Curve> sampled;
    std::size_t firstKnot = 0, firstVarying = 0;
    for (std::size_t i = 0; i < curves.size(); ++i) {
        const Curve& c = curves[i];
        const int p = static_cast<int>(orders[i]) - 1;
        const double* k = knots.data() + firstKnot;
        const double t0 = ranges.empty() ? k[p] : ranges[2 * i], t1 = ranges.empty() ? k[c.count] : ranges[2 * i + 1];
        const std::size_t samples = kSamplesPerSpan * (c.count - static_cast<std::size_t>(p)) + 1;
        const std::size_t m = c.count - static_cast<std::size_t>(p) + 1;
        sampled.push_back({data.points.size() / 3, samples});
        for (std::size_t s = 0; s < samples; ++s) {
            const double fraction = static_cast<double>(s) / static_cast<double>(samples - 1);
            const double t = t0 + (t1 - t0) * fraction;
            std::size_t span = static_cast<std::size_t>(p);
            while (span + 1 < c.count && k[span + 1] <= t) ++span;
            const std::vector<double> n = basisFunctions(k, span, p, t);
            // A rational combination of vertex values (k components each) around the span.
            auto evaluate = [&](const Values& perVertex, std::size_t components, Values& out) {
                double w = 0.0;
                std::vector<double> sum(components, 0.0);
                for (int j = 0; j <= p; ++j) {
                    const std::size_t vertex =
                        c.first + span - static_cast<std::size_t>(p) + static_cast<std::size_t>(j);
                    const double nw = n[static_cast<std::size_t>(j)] * weights[vertex];
                    w += nw;
                    for (std::size_t a = 0; a < components; ++a) sum[a] += nw * perVertex[vertex * components + a];
                }
                for (double v : sum) out.push_back(w != 0.0 ? v / w : v);
            };
            evaluate(points, 3, data.points);
            auto along = [&](const Primvar& pv, Values& out) {
                if (pv.interpolation == "vertex") {
                    Values flat;
                    for (std::size_t e = 0; e < points.size() / 3; ++e)
                        flat.insert(flat.end(), pv.element(e), pv.element(e) + pv.components);
                    evaluate(flat, static_cast<std::size_t>(pv.components), out);
                } else {
                    appendAlong(pv, i, firstVarying, m, fraction * static_cast<double>(m - 1), false, out);
                }
            };
            if (primvars.widths) along(*primvars.widths, data.widths);
            if (primvars.normals) along(*primvars.normals, data.normals);
            if (primvars.colors) along(*primvars.colors, data.colors);
            for (std::size_t v = 0; v < primvars.shading.size(); ++v)
                along(primvars.shading[v], data.shading[v].values);
        }
        firstKnot += c.count + static_cast<std::size_t>(p) + 1;
        firstVarying += m;
    }
    return unrolled(prim, Topology{CurveBasis::CatmullRom, Wrap::Pinned}, sampled, data, primvars, convertColor);
}

render::CurvesDesc hermiteCurvesFromPrim(const PrimReader& prim, const ColorConverter& convertColor,
                                         const std::function<void(const std::string&)>& warn) {
    const Values points = prim.numbers("points", 3).value_or(Values{});
    const Values tangents = prim.numbers("tangents", 3).value_or(Values{});
    const std::size_t n = points.size() / 3;
    if (tangents.size() != points.size())
        prim.fail("tangents has " + std::to_string(tangents.size() / 3) + " values for " + std::to_string(n) +
                  " points");
    const std::vector<Curve> curves = curvesOf(prim, n);
    CurvePrimvars primvars = readCurvePrimvars(prim);
    checkCounts(prim, primvars, curves.size(), n, n, warn);  // varying: one value per vertex, as vertex
    for (std::optional<Primvar>* pv : {&primvars.widths, &primvars.normals, &primvars.colors})
        if (*pv && (*pv)->interpolation == "vertex") (*pv)->interpolation = "varying";
    for (Primvar& pv : primvars.shading)
        if (pv.interpolation == "vertex") pv.interpolation = "varying";

    // Each curve as the Bezier control points of its segments, primvars linear along each segment.
    VertexData data;
    for (const Primvar& pv : primvars.shading) data.shading.emplace_back(pv.name, pv.components);
    std::vector<Curve> bezier;
    std::size_t tooShort = 0;
    for (std::size_t i = 0; i < curves.size(); ++i) {
        const Curve& c = curves[i];
        if (c.count < 2) {
            ++tooShort;
            continue;
        }
        bezier.push_back({data.points.size() / 3, 3 * (c.count - 1) + 1});
        for (std::size_t b = 0; b < bezier.back().count; ++b) {
            const std::size_t j = c.first + (b + 1) / 3;  // the Hermite vertex it starts from
            const double side = b % 3 == 1 ? 1.0 / 3.0 : b % 3 == 2 ? -1.0 / 3.0 : 0.0;  // along T_j
            for (std::size_t a = 0; a < 3; ++a) data.points.push_back(points[3 * j + a] + side * tangents[3 * j + a]);
            const double position = static_cast<double>(b) / 3.0;
            if (primvars.widths) appendAlong(*primvars.widths, i, c.first, c.count, position, false, data.widths);
            if (primvars.normals) appendAlong(*primvars.normals, i, c.first, c.count, position, false, data.normals);
            if (primvars.colors) appendAlong(*primvars.colors, i, c.first, c.count, position, false, data.colors);
            for (std::size_t v = 0; v < primvars.shading.size(); ++v)
                appendAlong(primvars.shading[v], i, c.first, c.count, position, false, data.shading[v].values);
        }
    }
    if (tooShort > 0)
        warn(std::to_string(tooShort) + " of its " + std::to_string(curves.size()) +
             " curves have fewer than 2 vertices; left out");
    return unrolled(prim, Topology{CurveBasis::Bezier, Wrap::Nonperiodic}, bezier, data, primvars, convertColor);
}

}  // namespace

bool isCurvesType(const std::string& typeName) {
    return typeName == "BasisCurves" || typeName == "NurbsCurves" || typeName == "HermiteCurves";
}

render::CurvesDesc curvesFromPrim(const PrimReader& prim, const ColorConverter& convertColor,
                                  const std::function<void(const std::string&)>& warn) {
    if (prim.prim().typeName == "NurbsCurves") return nurbsCurvesFromPrim(prim, convertColor, warn);
    if (prim.prim().typeName == "HermiteCurves") return hermiteCurvesFromPrim(prim, convertColor, warn);
    return basisCurvesFromPrim(prim, convertColor, warn);
}

render::CurvesDesc transformCurves(render::CurvesDesc curves, const Matrix4& toWorld) {
    render::transformPrimitives(curves.points, curves.radii, curves.normals, toWorld);
    return curves;
}

}  // namespace fluence::delegate
