// The material a curve set or point set binds, as the scene description records it.
#pragma once

#include <functional>
#include <string>

namespace fluence::delegate {

// `shape` (a render::CurvesDesc or PointsDesc) with the material bound at `materialPath` ("" for
// none): its index from `materialFor` (-1: the default material). A bound material replaces the
// shape's displayColor, which is dropped.
template <typename Shape>
Shape withBoundMaterial(Shape shape, const std::string& materialPath,
                        const std::function<int(const std::string&)>& materialFor) {
    if (!materialPath.empty()) shape.material = materialFor(materialPath);
    if (shape.material >= 0) shape.colors.clear();
    return shape;
}

}  // namespace fluence::delegate
