#include "delegate/nurbs_patch.h"

#include <algorithm>
#include <cmath>

namespace fluence::delegate {

namespace {

// One parametric direction of the patch.
struct Direction {
    int count = 0, order = 0;
    std::vector<double> knots;
    double lo = 0.0, hi = 0.0;  // the range drawn

    // The `order` non-zero basis functions at t (Cox-de Boor) and the index of the first.
    int basis(double t, std::vector<double>& out) const {
        // The span [knots[s], knots[s+1]) holding t, clamped to the valid ones.
        int span = int(std::upper_bound(knots.begin() + order - 1, knots.begin() + count, t) - knots.begin()) - 1;
        span = std::clamp(span, order - 1, count - 1);
        const int p = order - 1;
        out.assign(static_cast<std::size_t>(order), 0.0);
        out[0] = 1.0;
        const std::size_t size = static_cast<std::size_t>(order);
        std::vector<double> left(size), right(size);
        for (int j = 1; j <= p; ++j) {
            left[std::size_t(j)] = t - knots[std::size_t(span + 1 - j)];
            right[std::size_t(j)] = knots[std::size_t(span + j)] - t;
            double saved = 0.0;
            for (int r = 0; r < j; ++r) {
                const double denominator = right[std::size_t(r + 1)] + left[std::size_t(j - r)];
                const double temp = denominator != 0.0 ? out[std::size_t(r)] / denominator : 0.0;
                out[std::size_t(r)] = saved + right[std::size_t(r + 1)] * temp;
                saved = left[std::size_t(j - r)] * temp;
            }
            out[std::size_t(j)] = saved;
        }
        return span - p;
    }

    // Parameter values of the grid: every distinct knot inside the range and `segments` steps
    // across each span.
    std::vector<double> samples() const {
        std::vector<double> breaks{lo};
        for (double k : knots)
            if (k > lo && k < hi && k != breaks.back()) breaks.push_back(k);
        breaks.push_back(hi);
        const int segments = order == 2 ? 1 : kNurbsSpanSegments;
        std::vector<double> out;
        for (std::size_t b = 0; b + 1 < breaks.size(); ++b)
            for (int s = 0; s < segments; ++s) out.push_back(breaks[b] + (breaks[b + 1] - breaks[b]) * s / segments);
        out.push_back(hi);
        return out;
    }
};

Direction readDirection(const PrimReader& prim, char name) {
    const std::string n(1, name);
    Direction d;
    d.count = static_cast<int>(prim.number({(n + "VertexCount").c_str()}, 0.0));
    d.order = static_cast<int>(prim.number({(n + "Order").c_str()}, 0.0));
    if (d.order < 2 || d.count < d.order)
        prim.fail(n + "Order must be at least 2 and at most " + n + "VertexCount (" + std::to_string(d.count) +
                  "), got " + std::to_string(d.order));
    std::optional<std::vector<double>> knots = prim.numbers(n + "Knots", 1);
    if (!knots || knots->size() != std::size_t(d.count + d.order))
        prim.fail(n + "Knots must hold " + n + "VertexCount + " + n + "Order = " + std::to_string(d.count + d.order) +
                  " values");
    if (!std::is_sorted(knots->begin(), knots->end())) prim.fail(n + "Knots must not decrease");
    d.knots = std::move(*knots);
    d.lo = d.knots[std::size_t(d.order - 1)];
    d.hi = d.knots[std::size_t(d.count)];
    if (std::optional<std::vector<double>> range = prim.numbers(n + "Range", 2); range && range->size() == 2) {
        d.lo = std::max(d.lo, (*range)[0]);
        d.hi = std::min(d.hi, (*range)[1]);
    }
    if (!(d.lo < d.hi)) prim.fail(n + "Range (or the knots) leaves no parameter interval to draw");
    return d;
}

}  // namespace

TessellatedSurface tessellateNurbsPatch(const PrimReader& prim, const std::function<void(const std::string&)>& warn) {
    const Direction u = readDirection(prim, 'u'), v = readDirection(prim, 'v');
    const std::size_t count = std::size_t(u.count) * std::size_t(v.count);
    std::optional<std::vector<double>> points = prim.numbers("points", 3);
    if (!points || points->size() != 3 * count)
        prim.fail("points must hold uVertexCount x vVertexCount = " + std::to_string(count) + " points");
    std::vector<double> weights(count, 1.0);
    if (std::optional<std::vector<double>> w = prim.numbers("pointWeights", 1); w && !w->empty()) {
        if (w->size() != count)
            prim.fail("pointWeights must hold one weight per point (" + std::to_string(count) + ")");
        if (std::any_of(w->begin(), w->end(), [](double x) { return !(x > 0.0); }))
            prim.fail("pointWeights must be positive");
        weights = std::move(*w);
    }
    if (prim.value("trimCurve:counts")) warn("trim curves are not applied yet; the whole NurbsPatch is rendered");

    std::vector<double> bu, bv;
    auto evaluate = [&](double s, double t) {
        const int iu = u.basis(s, bu), iv = v.basis(t, bv);
        Vec3d sum(0.0);
        double wsum = 0.0;
        for (int b = 0; b < v.order; ++b)
            for (int a = 0; a < u.order; ++a) {
                const std::size_t k = std::size_t(iv + b) * std::size_t(u.count) + std::size_t(iu + a);
                const double w = bu[std::size_t(a)] * bv[std::size_t(b)] * weights[k];
                sum += Vec3d((*points)[3 * k], (*points)[3 * k + 1], (*points)[3 * k + 2]) * w;
                wsum += w;
            }
        return sum / wsum;
    };
    const bool leftHanded = prim.token({"orientation"}, "rightHanded") == "leftHanded";
    const std::vector<double> su = u.samples(), sv = v.samples();
    const double hu = 1e-6 * (u.hi - u.lo), hv = 1e-6 * (v.hi - v.lo);
    TessellatedSurface out;
    for (double t : sv)
        for (double s : su) {
            out.points.push_back(evaluate(s, t));
            // Central differences, one-sided at the range's ends.
            const double s0 = std::max(u.lo, s - hu), s1 = std::min(u.hi, s + hu);
            const double t0 = std::max(v.lo, t - hv), t1 = std::min(v.hi, t + hv);
            Vec3d n = cross(evaluate(s1, t) - evaluate(s0, t), evaluate(s, t1) - evaluate(s, t0));
            if (leftHanded) n = -n;
            const double len = length(n);
            out.normals.push_back(len > 0.0 ? n / len : Vec3d(0.0));
        }
    const std::uint32_t row = static_cast<std::uint32_t>(su.size());
    for (std::uint32_t j = 0; j + 1 < sv.size(); ++j)
        for (std::uint32_t i = 0; i + 1 < row; ++i) {
            const std::uint32_t a = j * row + i, b = a + 1, c = a + row + 1, d = a + row;
            if (leftHanded)
                out.indices.insert(out.indices.end(), {a, c, b, a, d, c});
            else
                out.indices.insert(out.indices.end(), {a, b, c, a, c, d});
        }
    return out;
}

}  // namespace fluence::delegate
