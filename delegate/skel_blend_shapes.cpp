#include "delegate/skel_blend_shapes.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fluence::delegate {

namespace {

std::vector<Vec3d> vectors(const std::optional<std::vector<double>>& numbers) {
    std::vector<Vec3d> out;
    if (!numbers) return out;
    out.reserve(numbers->size() / 3);
    for (std::size_t i = 0; i + 2 < numbers->size(); i += 3)
        out.push_back({(*numbers)[i], (*numbers)[i + 1], (*numbers)[i + 2]});
    return out;
}

constexpr const char* kInbetweens = "inbetweens:";
constexpr const char* kNormalOffsets = ":normalOffsets";
constexpr double kNoWeight = std::numeric_limits<double>::quiet_NaN();

}  // namespace

BlendShape readBlendShape(const PrimReader& prim, const std::function<void(const std::string&)>& warn) {
    BlendShape shape;
    shape.path = prim.path();
    for (double i : prim.numbers("pointIndices", 1).value_or(std::vector<double>{}))
        shape.pointIndices.push_back(static_cast<int>(i));
    BlendShape::Shape primary{1.0, vectors(prim.numbers("offsets", 3)), vectors(prim.numbers("normalOffsets", 3))};
    shape.shapes.push_back({0.0, {}, {}});
    for (const usd::AttributeSpec& a : prim.prim().attributes) {
        if (!a.name.starts_with(kInbetweens) || a.name.ends_with(kNormalOffsets)) continue;
        const usd::MetadataEntry* weight = usd::findMetadata(a.metadata, "weight");
        const double w = weight ? weight->value.asDouble().value_or(kNoWeight) : kNoWeight;
        BlendShape::Shape between{w, vectors(prim.numbers(a.name, 3)),
                                  vectors(prim.numbers(a.name + kNormalOffsets, 3))};
        std::string why;
        if (std::isnan(w))
            why = "has no weight";
        else if (w == 0.0 || w == 1.0)
            why = "has weight " + std::to_string(w) + ", which the shapes at 0 and 1 already hold";
        else if (std::ranges::any_of(shape.shapes, [&](const BlendShape::Shape& s) { return s.weight == w; }))
            why = "has the weight " + std::to_string(w) + " of another in-between";
        if (!why.empty()) {
            warn("in-between '" + a.name + "' " + why + "; ignored");
            continue;
        }
        shape.shapes.push_back(std::move(between));
    }
    shape.shapes.push_back(std::move(primary));
    std::ranges::stable_sort(shape.shapes, {}, &BlendShape::Shape::weight);
    return shape;
}

std::optional<std::string> BlendShape::problem(std::size_t pointCount) const {
    // Each shape's offsets (and normal offsets) apply on their own; unauthored ones add nothing.
    auto check = [&](const std::vector<Vec3d>& offsets, const std::string& what) -> std::optional<std::string> {
        if (offsets.empty()) return std::nullopt;
        if (pointIndices.empty() ? offsets.size() > pointCount : offsets.size() != pointIndices.size())
            return path + " has " + std::to_string(offsets.size()) + " " + what + " for " +
                   std::to_string(pointIndices.empty() ? pointCount : pointIndices.size()) +
                   (pointIndices.empty() ? " points" : " pointIndices");
        return std::nullopt;
    };
    for (const Shape& s : shapes)
        for (auto problem : {check(s.offsets, "offsets"), check(s.normalOffsets, "normalOffsets")})
            if (problem) return problem;
    for (std::size_t i = 0; i < pointIndices.size(); ++i)
        if (pointIndices[i] < 0 || static_cast<std::size_t>(pointIndices[i]) >= pointCount)
            return path + ": pointIndices[" + std::to_string(i) + "] = " + std::to_string(pointIndices[i]) +
                   " is out of range (" + std::to_string(pointCount) + " points)";
    return std::nullopt;
}

void BlendShape::apply(double weight, std::vector<Vec3d>& points, std::vector<Vec3d>* normals) const {
    if (weight == 0.0 || shapes.size() < 2) return;
    std::size_t lower = 0;
    while (lower + 2 < shapes.size() && shapes[lower + 1].weight <= weight) ++lower;
    const Shape &a = shapes[lower], &b = shapes[lower + 1];
    const double t = (weight - a.weight) / (b.weight - a.weight);
    auto add = [&](const std::vector<Vec3d>& from, double scale, std::vector<Vec3d>& to) {
        for (std::size_t i = 0; i < from.size(); ++i)
            to[pointIndices.empty() ? i : static_cast<std::size_t>(pointIndices[i])] += from[i] * scale;
    };
    add(a.offsets, 1.0 - t, points);
    add(b.offsets, t, points);
    if (!normals) return;
    add(a.normalOffsets, 1.0 - t, *normals);
    add(b.normalOffsets, t, *normals);
}

}  // namespace fluence::delegate
