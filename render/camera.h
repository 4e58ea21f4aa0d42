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
#include "render/camera_motion.h"
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
    // A moving camera (CameraDesc::motionTransforms, motionLenses) generates it as the still camera
    // at(time) does; a still camera ignores `time`.
    Ray generateRay(float x, float y, Vec2f lens = {0.5f, 0.5f}, float time = 0.0f) const;
    // Whether the camera moves, zooms or refocuses during the shutter.
    bool moves() const { return motion_ != nullptr; }
    // The still camera where this one is at `time` in the shutter (render/camera_motion.h: its
    // transform, focal length, fStop and focus distance then); a still camera is its own.
    Camera at(float time) const;
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
    // Defined for a still perspective camera, pinhole or thin lens: hasImportance() is false for an
    // orthographic one (its rays are parallel, so a point reaches it along one direction only)
    // and for a moving one (ask the still camera at() the light path's time), and then
    // directionDensity() is 0 and rasterPosition() and connect() return nothing.
    // Conventions (Veach's thesis, ch. 10; pbrt-v4's PerspectiveCamera::We, PDF_We, SampleWi): a
    // camera ray leaves an aperture point (camera-space x, y on the lens plane z = 0; the pinhole
    // (0, 0) without depth of field) drawn uniformly over the aperture, along a direction w through
    // a uniformly chosen point of the image. Given its aperture point, w's solid-angle density is
    // We(w) cos(theta) (theta between w and the view axis), normalised over the image:
    //     integral over the image's directions of We(w) cos(theta) dw = 1.
    // The aperture point's own density is the same for every strategy (light tracing draws it as
    // camera rays do, ThinLens::sampleAperture), so it cancels in MIS and in the light a
    // connection carries (We / pdf of the lens point = the direction density / distance^2). From
    // aperture point a, the ray along camera-space direction (mx, my, -1) crosses the window at unit
    // distance at (mx, my) + a / focusDistance (through the point of the plane of focus it aims
    // at), and the map from the window to (mx, my) is a translation, so the density is the
    // pinhole's: |T m|^3 / (|det T| window area), exact for any affine camera transform T.
    bool hasImportance() const { return projection_ == Projection::Perspective && !moves(); }
    // We(w) cos(theta): the density, per unit solid angle, of camera rays from aperture point
    // `aperture` along w; 0 outside the image.
    float directionDensity(const Vec3f& w, Vec2f aperture = {0.0f, 0.0f}) const;
    // We(w) from aperture point `aperture`; 0 outside the image.
    float importance(const Vec3f& w, Vec2f aperture = {0.0f, 0.0f}) const;
    // Where a world point seen from aperture point `aperture` lands on the image, in pixels
    // (generateRay's (x, y)), or nothing when it is outside the image, behind the camera or outside
    // the clipping range (where camera rays cannot reach it).
    std::optional<Vec2f> rasterPosition(const Vec3f& worldPoint, Vec2f aperture = {0.0f, 0.0f}) const;
    // The aperture point (camera-space x, y) a camera ray starting at `origin` left from ((0, 0)
    // for a pinhole camera).
    Vec2f apertureOf(const Vec3f& origin) const;
    // A connection from a world point to aperture point `aperture` (light tracing).
    struct Connection {
        Vec2f raster;            // where the point lands on the image, in pixels
        Vec3f lensPoint;         // the aperture point, in world space (the pinhole: position())
        Vec3f direction;         // unit, from the point towards lensPoint
        float distance = 0;      // from the point to lensPoint
        float nearDistance = 0;  // from lensPoint to the near plane along the connection (camera rays start there)
        float density = 0;  // directionDensity(-direction, aperture): the camera's density of its ray towards the point
        float importance =
            0;  // We(-direction) cos(theta) / distance^2: importance reaching the point, per unit area facing it
    };
    std::optional<Connection> connect(const Vec3f& worldPoint, Vec2f aperture = {0.0f, 0.0f}) const;

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
    // The aperture conformed to the image and its offsets, in the camera's units (tenths of a scene
    // unit), which the focal length divides (setLens).
    float hAperture_, vAperture_, hOffset_, vOffset_;
    int apertureBlades_;
    float apertureRotation_;
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
    // CameraDesc::motionTransforms and motionLenses (null for a still camera), shared by the
    // copies of a moving camera.
    std::shared_ptr<const CameraMotion> motion_;

    // Places the camera by `toWorld` (what generating a ray reads of its transform).
    void place(const Matrix4& toWorld);
    // The window and the thin lens of focal length, fStop and focus distance `lens`.
    void setLens(const CameraLensStep& lens);
};

}  // namespace fluence::render
