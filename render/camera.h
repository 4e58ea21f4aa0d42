// A camera that follows USD's camera model (UsdGeomCamera / GfCamera).
//
// The film back is the aperture window at distance focalLength in front of the lens (only the
// ratios matter for a perspective camera). The image's aspect ratio is width * pixelAspectRatio
// / height, and the aperture is conformed to it by UsdRenderSettingsBase's
// aspectRatioConformPolicy (ImageFraming): by default expandAperture, where the aperture grows in
// one direction until its aspect ratio matches the image's, so nothing it frames is cropped. Orthographic apertures are in
// tenths of a scene unit, as in USD. Camera rays start at the near clipping plane and end at
// the far one (planes perpendicular to the view axis, not spheres).
#pragma once

#include "core/matrix.h"
#include "render/ray.h"
#include "render/scene_description.h"

namespace fluence::render {

// UsdRenderSettingsBase aspectRatioConformPolicy: what gives when the aperture's aspect ratio
// differs from the image's.
enum class ApertureConform {
    ExpandAperture,         // grow the aperture in one direction (frames at least the aperture)
    CropAperture,           // shrink it in one direction (frames at most the aperture)
    AdjustApertureWidth,    // keep the aperture's height
    AdjustApertureHeight,   // keep the aperture's width
    AdjustPixelAspectRatio  // keep the aperture; the pixels stretch to fit
};

struct ImageFraming {
    float pixelAspectRatio = 1.0f;  // width / height of one pixel
    ApertureConform conform = ApertureConform::ExpandAperture;
};

class Camera {
public:
    Camera(const CameraDesc& desc, int imageWidth, int imageHeight, const ImageFraming& framing = {});

    // The pixel aspect ratio of the image (as asked, or as adjustPixelAspectRatio computed it).
    float pixelAspectRatio() const { return pixelAspectRatio_; }

    // A ray through film position (x, y) in pixels: (0,0) is the top-left corner of the image,
    // (width, height) the bottom-right.
    Ray generateRay(float x, float y) const;

    // Depth along the view axis of a world-space point (positive in front of the camera).
    float viewDepth(const Vec3f& worldPoint) const;

    // How many pixels one scene unit spans at `worldPoint`, seen face-on: for a perspective
    // camera, at its distance from the eye (clamped to the near plane, so points beside or behind
    // the camera count as close); for an orthographic one, everywhere the same.
    float pixelsPerUnitAt(const Vec3f& worldPoint) const;
    // Whether `worldPoint` projects into the image grown by `margin` (a fraction of its size on
    // every side), in front of the camera.
    bool sees(const Vec3f& worldPoint, float margin) const;

    float farClip() const { return far_; }
    const Vec3f& position() const { return position_; }

private:
    Projection projection_;
    Matrix4 toWorld_, toCamera_;
    Vec3f position_, forward_;
    int width_, height_;
    // Window half-extents and centre, on the plane at unit distance (perspective) or in scene
    // units (orthographic).
    float halfWidth_, halfHeight_, centreX_, centreY_;
    float near_, far_;
    float pixelAspectRatio_;
};

}  // namespace fluence::render
