// A UsdGeomPoints prim as the render core takes it (part of render::SceneDescription): one sphere
// or disc per point, in world space, rendered with Embree's point primitives
// (render/point_geometry.h).
#pragma once

#include <string>
#include <vector>

#include "core/rgb.h"
#include "core/vec.h"

namespace fluence::render {

enum class PointStyle {
    Sphere,       // RTC_GEOMETRY_TYPE_SPHERE_POINT
    Disc,         // RTC_GEOMETRY_TYPE_DISC_POINT: a disc facing the ray
    OrientedDisc  // RTC_GEOMETRY_TYPE_ORIENTED_DISC_POINT: a disc facing its normal
};

// A primvar with one value of `components` (1 to 4) floats per point.
struct PointPrimvar {
    std::string name;
    int components = 1;
    std::vector<float> values;  // points * components
};

struct PointsDesc {
    std::string name;  // prim path, for messages
    PointStyle style = PointStyle::Sphere;
    std::vector<Vec3f> positions;  // world space
    std::vector<float> radii;      // one per point, world space (half the width)
    std::vector<Vec3f> normals;    // OrientedDisc: one per point (world space); otherwise empty
    std::vector<RGB> colors;       // empty, or one per point: diffuse colour (displayColor)
    // Motion blur (render/motion_geometry.h): the positions at evenly spaced times over the
    // shutter, the first at its opening and the last at its close (empty: the points do not move;
    // `positions` stays the frame's), and their radii at the same steps (empty: `radii` throughout).
    std::vector<std::vector<Vec3f>> motionPositions{};
    std::vector<std::vector<float>> motionRadii{};
    int material = -1;                   // index into SceneDescription::materials, -1 = default
    std::vector<PointPrimvar> primvars;  // those the material reads
    int linkGroup = 0;                   // its light and shadow links (render/light_links.h)
};

}  // namespace fluence::render
