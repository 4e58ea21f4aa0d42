// The thin lens of a camera with depth of field (UsdGeomCamera fStop and focusDistance; the
// aperture's blades and rotation are Fluence's own camera attributes, CameraDesc).
//
// Camera rays leave a point of the aperture, on the lens plane through the camera's origin
// (camera space, z = 0), and pass through the point the pinhole ray would reach on the plane of
// focus, at `focusDistance` along the view axis: what lies on that plane is sharp, and a point at
// depth z is blurred into the aperture's shape scaled by |z - focusDistance| / z (its circle of
// confusion, measured on the plane of focus). The aperture is a disk of `radius` or, with
// `blades` >= 3, the regular polygon inscribed in that disk with a vertex at `rotationDegrees`
// from the camera's +x axis (counter-clockwise seen from behind the camera). Both are sampled
// uniformly over their area, so the bokeh of a point is evenly lit.
#pragma once

#include "core/vec.h"

namespace fluence::render {

struct ThinLens {
    float radius = 0.0f;         // scene units; 0: a pinhole
    float focusDistance = 0.0f;  // scene units, along the view axis
    int blades = 0;              // 0: round; >= 3: a regular polygon
    float rotationDegrees = 0.0f;

    bool isPinhole() const { return !(radius > 0.0f); }
    // A point of the aperture on the lens plane (camera-space x, y) from a uniform u in [0, 1)^2;
    // uniform over the aperture's area.
    Vec2f sampleAperture(Vec2f u) const;
};

}  // namespace fluence::render
