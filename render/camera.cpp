#include "render/camera.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace fluence::render {

namespace {
constexpr float kOrthographicApertureUnit = 0.1f;  // GfCamera::APERTURE_UNIT
constexpr float kLensUnit = 0.1f;                  // GfCamera::FOCAL_LENGTH_UNIT: tenths of a scene unit
}  // namespace

Camera::Camera(const CameraDesc& d, int imageWidth, int imageHeight, const ImageFraming& framing)
    : projection_(d.projection),
      toWorld_(d.transform),
      hOffset_(d.horizontalApertureOffset),
      vOffset_(d.verticalApertureOffset),
      apertureBlades_(d.apertureBlades),
      apertureRotation_(d.apertureRotation),
      width_(imageWidth),
      height_(imageHeight),
      near_(d.nearClip),
      far_(d.farClip),
      pixelAspectRatio_(framing.pixelAspectRatio) {
    if (imageWidth <= 0 || imageHeight <= 0) throw std::invalid_argument("image resolution must be positive");
    if (!(d.horizontalAperture > 0.0f) || !(d.verticalAperture > 0.0f))
        throw std::invalid_argument("camera " + d.name + ": apertures must be positive");
    if (!(framing.pixelAspectRatio > 0.0f) || !std::isfinite(framing.pixelAspectRatio))
        throw std::invalid_argument("pixelAspectRatio must be positive");
    if (d.apertureBlades < 0) throw std::invalid_argument("camera " + d.name + ": apertureBlades must not be negative");
    const CameraLensStep frameLens{d.focalLength, d.fStop, d.focusDistance};
    for (const CameraLensStep& lens :
         d.motionLenses.empty() ? std::vector<CameraLensStep>{frameLens} : d.motionLenses) {
        if (projection_ == Projection::Perspective && !(lens.focalLength > 0.0f))
            throw std::invalid_argument("camera " + d.name + ": focalLength must be positive");
        if (!(lens.fStop >= 0.0f) || !(lens.focusDistance >= 0.0f))
            throw std::invalid_argument("camera " + d.name + ": fStop and focusDistance must not be negative");
    }

    float hAperture = d.horizontalAperture, vAperture = d.verticalAperture;
    const float apertureAspect = hAperture / vAperture;
    const float pixels = static_cast<float>(imageWidth) / static_cast<float>(imageHeight);
    const float imageAspect = pixels * framing.pixelAspectRatio;
    switch (framing.conform) {
        case ApertureConform::ExpandAperture:
        case ApertureConform::CropAperture:
            // Expanding widens a too-narrow aperture; cropping shortens it instead.
            if ((imageAspect > apertureAspect) == (framing.conform == ApertureConform::ExpandAperture))
                hAperture = vAperture * imageAspect;
            else
                vAperture = hAperture / imageAspect;
            break;
        case ApertureConform::AdjustApertureWidth: hAperture = vAperture * imageAspect; break;
        case ApertureConform::AdjustApertureHeight: vAperture = hAperture / imageAspect; break;
        case ApertureConform::AdjustPixelAspectRatio: pixelAspectRatio_ = apertureAspect / pixels; break;
    }
    hAperture_ = hAperture;
    vAperture_ = vAperture;
    setLens(frameLens);

    std::optional<Matrix4> toCamera = toWorld_.inverse();
    if (!toCamera) throw std::invalid_argument("camera " + d.name + ": its transform is singular");
    toCamera_ = *toCamera;
    place(toWorld_);
    if ((!d.motionTransforms.empty() && d.motionTransforms.size() < 2) ||
        (!d.motionLenses.empty() && d.motionLenses.size() < 2))
        throw std::invalid_argument("camera " + d.name + ": motion needs at least two time steps");
    if (!d.motionTransforms.empty() || !d.motionLenses.empty())
        motion_ = std::make_shared<const CameraMotion>(CameraMotion{d.motionTransforms, d.motionLenses});
}

void Camera::setLens(const CameraLensStep& lens) {
    float scale = projection_ == Projection::Perspective ? 1.0f / lens.focalLength : kOrthographicApertureUnit;
    halfWidth_ = 0.5f * hAperture_ * scale;
    halfHeight_ = 0.5f * vAperture_ * scale;
    centreX_ = hOffset_ * scale;
    centreY_ = vOffset_ * scale;
    lens_ = ThinLens{};
    if (projection_ == Projection::Perspective && lens.fStop > 0.0f && lens.focusDistance > 0.0f)
        lens_ = ThinLens{kLensUnit * lens.focalLength / (2.0f * lens.fStop), lens.focusDistance, apertureBlades_,
                         apertureRotation_};
}

void Camera::place(const Matrix4& toWorld) {
    toWorld_ = toWorld;
    position_ = Vec3f(toWorld.transformPoint({0, 0, 0}));
    forward_ = normalize(Vec3f(toWorld.transformVector({0, 0, -1})));
    axisX_ = Vec3f(toWorld.transformVector({1, 0, 0}));
    axisY_ = Vec3f(toWorld.transformVector({0, 1, 0}));
    axisZ_ = Vec3f(toWorld.transformVector({0, 0, 1}));
}

Camera Camera::at(float time) const {
    Camera still = *this;
    if (!motion_) return still;
    still.motion_.reset();
    if (!motion_->transforms.empty()) {
        still.place(cameraTransformAt(motion_->transforms, time));
        // Left as the frame's where the interpolated transform is singular (a scale through 0).
        if (std::optional<Matrix4> toCamera = still.toWorld_.inverse()) still.toCamera_ = *toCamera;
    }
    if (!motion_->lenses.empty()) still.setLens(cameraLensAt(motion_->lenses, time));
    return still;
}

Ray Camera::generateRay(float x, float y, Vec2f lens, float time) const {
    if (motion_) return at(time).generateRay(x, y, lens);
    float sx = 2.0f * x / static_cast<float>(width_) - 1.0f;   // -1 left .. 1 right
    float sy = 1.0f - 2.0f * y / static_cast<float>(height_);  // 1 top .. -1 bottom
    float wx = centreX_ + sx * halfWidth_, wy = centreY_ + sy * halfHeight_;
    Ray ray;
    ray.fromCamera = true;
    if (projection_ == Projection::Perspective) {
        Vec3f dir = normalize(axisX_ * wx + axisY_ * wy - axisZ_);
        ray.origin = position_;
        if (!lens_.isPinhole()) {
            // From the aperture point towards where the pinhole ray meets the plane of focus.
            const Vec2f a = lens_.sampleAperture(lens);
            const float f = lens_.focusDistance;
            ray.origin = position_ + axisX_ * a.x + axisY_ * a.y;
            dir = normalize(axisX_ * (wx * f - a.x) + axisY_ * (wy * f - a.y) - axisZ_ * f);
        }
        float cosView = dot(dir, forward_);
        ray.direction = dir;
        ray.tMin = near_ / cosView;
        ray.tMax = far_ / cosView;
    } else {
        ray.origin = Vec3f(toWorld_.transformPoint({wx, wy, 0.0}));
        ray.direction = forward_;
        ray.tMin = near_;
        ray.tMax = far_;
    }
    return ray;
}

Matrix4 Camera::worldToCamera() const { return Matrix4::scale({1.0, 1.0, -1.0}) * toCamera_; }

Matrix4 Camera::worldToNdc() const {
    // In the camera space of worldToCamera(), the window point of (x, y, z) is (x, y) / z for a
    // perspective camera and (x, y) for an orthographic one.
    const double sx = 0.5 / halfWidth_, sy = -0.5 / halfHeight_;
    const double ox = 0.5 - centreX_ * sx, oy = 0.5 - centreY_ * sy;
    const double n = near_, f = far_;
    Matrix4 ndc{};
    if (projection_ == Projection::Perspective) {
        ndc.m[0] = {sx, 0.0, ox, 0.0};
        ndc.m[1] = {0.0, sy, oy, 0.0};
        ndc.m[2] = {0.0, 0.0, f / (f - n), -f * n / (f - n)};
        ndc.m[3] = {0.0, 0.0, 1.0, 0.0};
    } else {
        ndc.m[0] = {sx, 0.0, 0.0, ox};
        ndc.m[1] = {0.0, sy, 0.0, oy};
        ndc.m[2] = {0.0, 0.0, 1.0 / (f - n), -n / (f - n)};
        ndc.m[3] = {0.0, 0.0, 0.0, 1.0};
    }
    return ndc * worldToCamera();
}

float Camera::viewDepth(const Vec3f& p) const { return dot(p - position_, forward_); }

float Camera::pixelsPerUnitAt(const Vec3f& p) const {
    float pixelsPerWindowUnit = static_cast<float>(width_) / (2.0f * halfWidth_);
    if (projection_ == Projection::Orthographic) return pixelsPerWindowUnit;
    return pixelsPerWindowUnit / std::max(length(p - position_), std::max(near_, 1e-6f));
}

bool Camera::sees(const Vec3f& p, float margin) const {
    Vec3d local = toCamera_.transformPoint(Vec3d(p));
    double wx = local.x, wy = local.y;
    if (projection_ == Projection::Perspective) {
        if (local.z >= 0.0) return false;  // the camera looks along -Z
        wx /= -local.z;
        wy /= -local.z;
    }
    return std::abs(wx - centreX_) <= halfWidth_ * (1.0 + 2.0 * margin) &&
           std::abs(wy - centreY_) <= halfHeight_ * (1.0 + 2.0 * margin);
}

}  // namespace fluence::render
