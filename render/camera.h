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

#include <memory>
#include <optional>
#include <vector>

#include "core/matrix.h"
#include "render/ray.h"
#include "render/scene_description.h"
#include "render/thin_lens.h"

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
    // (width, height) the bottom-right. A perspective camera with depth of field starts it at the
    // aperture point `lens` (uniform in [0, 1)^2; the default is the lens's centre) picks
    // (render/thin_lens.h); a pinhole or orthographic camera ignores `lens`.
    // A moving camera (CameraDesc::motionTransforms) starts it from where the camera is at `time`
    // in the shutter (render/camera_motion.h); a still camera ignores `time`.
    Ray generateRay(float x, float y, Vec2f lens = {0.5f, 0.5f}, float time = 0.0f) const;
    bool moves() const { return motion_ != nullptr; }
    // The thin lens (a pinhole when CameraDesc's fStop or focusDistance is 0, or for an
    // orthographic camera): aperture radius focalLength / (2 fStop), the focal length converted from
    // tenths of a scene unit as UsdGeomCamera measures it.
    const ThinLens& lens() const { return lens_; }

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
    int imageWidth() const { return width_; }
    int imageHeight() const { return height_; }

    // ---- Importance, for light tracing (bdpt's t = 1 strategy), in render/camera_importance.cpp.
    // Defined for the perspective pinhole camera only: hasImportance() is false for an
    // orthographic one (its rays are parallel, so a point reaches it along one direction only)
    // and for one with depth of field (its importance would spread over the aperture's area; not
    // modelled yet), and then directionDensity() is 0 and rasterPosition() and connect() return
    // nothing.
    // Conventions (Veach's thesis, ch. 10; pbrt's PerspectiveCamera::We): the importance We(w) of
    // the ray leaving the pinhole along unit w is normalised over the whole image,
    //     integral over the image's directions of We(w) cos(theta) dw = 1,
    // theta between w and the view axis, so We(w) cos(theta) is the solid-angle density of the
    // direction of a camera ray through a uniformly chosen point of the image. The pinhole is a
    // delta in position: its positional density is 1 (the same for every strategy, so it cancels
    // in MIS). Exact for any affine camera transform (scaled or sheared), through the Jacobian
    // from the image to directions.
    // A moving camera has no importance either: light paths would have to meet it where it is at
    // their own time; bdpt leaves its t = 1 strategy out for it, as for a lens.
    bool hasImportance() const { return projection_ == Projection::Perspective && lens_.isPinhole() && !moves(); }
    // We(w) cos(theta): the density, per unit solid angle, of camera rays along w; 0 outside the image.
    float directionDensity(const Vec3f& w) const;
    // We(w); 0 outside the image.
    float importance(const Vec3f& w) const;
    // Where a world point lands on the image, in pixels (generateRay's (x, y)), or nothing when it
    // is outside the image, behind the camera or outside the clipping range (where camera rays
    // cannot reach it).
    std::optional<Vec2f> rasterPosition(const Vec3f& worldPoint) const;
    // A connection from a world point to the pinhole (light tracing).
    struct Connection {
        Vec2f raster;            // where the point lands on the image, in pixels
        Vec3f direction;         // unit, from the point towards the pinhole
        float distance = 0;      // from the point to the pinhole
        float nearDistance = 0;  // from the pinhole to the near plane along the connection (camera rays start there)
        float density = 0;       // directionDensity(-direction): the camera's density of its ray towards the point
        float importance =
            0;  // We(-direction) cos(theta) / distance^2: importance reaching the point, per unit area facing it
    };
    std::optional<Connection> connect(const Vec3f& worldPoint) const;

    // OpenEXR's standard camera attributes (ImfStandardAttributes.h), as column-vector matrices.
    // worldToCamera: world space -> the camera space of OpenEXR and RenderMan (left-handed: +x
    // right, +y up, +z the viewing direction, the eye at the origin).
    Matrix4 worldToCamera() const;
    // worldToNdc: world space -> projective NDC: divided by w, x and y are (0, 0) at the image's
    // top-left corner and (1, 1) at its bottom-right, and z runs from 0 at the near clipping plane
    // to 1 at the far one.
    Matrix4 worldToNdc() const;

private:
    Projection projection_;
    Matrix4 toWorld_, toCamera_;
    Vec3f position_, forward_;
    // toWorld_'s images of the camera-space axes x, y and z, in single precision: a perspective
    // ray's direction is their combination (generateRay, once per camera sample).
    Vec3f axisX_, axisY_, axisZ_;
    int width_, height_;
    // Window half-extents and centre, on the plane at unit distance (perspective) or in scene
    // units (orthographic).
    float halfWidth_, halfHeight_, centreX_, centreY_;
    float near_, far_;
    float pixelAspectRatio_;
    ThinLens lens_;
    // CameraDesc::motionTransforms (null for a still camera), shared by the still copies
    // generateRay makes of a moving camera.
    std::shared_ptr<const std::vector<Matrix4>> motion_;

    // Places the camera by `toWorld` (what generating a ray reads of its transform).
    void place(const Matrix4& toWorld);
};

}  // namespace fluence::render
