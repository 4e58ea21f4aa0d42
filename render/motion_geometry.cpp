#include "render/motion_geometry.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace fluence::render {

MotionSegment motionSegment(std::size_t steps, float time) {
    const float x = std::clamp(time, 0.0f, 1.0f) * static_cast<float>(steps - 1);
    const std::size_t step = std::min(static_cast<std::size_t>(x), steps - 2);
    return {step, x - static_cast<float>(step)};
}

Vec3f positionAt(const std::vector<std::vector<Vec3f>>& steps, std::uint32_t index, float time) {
    const MotionSegment s = motionSegment(steps.size(), time);
    const Vec3f& a = steps[s.step][index];
    const Vec3f& b = steps[s.step + 1][index];
    return a * (1.0f - s.fraction) + b * s.fraction;
}

Matrix4 transformAt(const std::vector<Matrix4>& steps, float time) {
    const MotionSegment s = motionSegment(steps.size(), time);
    const double f = s.fraction;
    Matrix4 m = steps[s.step];
    for (int row = 0; row < 4; ++row)
        for (int column = 0; column < 4; ++column)
            m.m[row][column] = (1.0 - f) * m.m[row][column] + f * steps[s.step + 1].m[row][column];
    return m;
}

namespace {

// A buffer of 3-float vectors (`type`: vertex positions or curve normals) in `slot`.
void fillFloat3Buffer(RTCGeometry geom, RTCBufferType type, unsigned slot, const std::vector<Vec3f>& vectors) {
    auto* v = static_cast<float*>(
        rtcSetNewGeometryBuffer(geom, type, slot, RTC_FORMAT_FLOAT3, 3 * sizeof(float), vectors.size()));
    for (std::size_t i = 0; i < vectors.size(); ++i)
        for (int k = 0; k < 3; ++k) v[3 * i + k] = vectors[i][k];
}

void fillPointRadiusBuffer(RTCGeometry geom, unsigned slot, const std::vector<Vec3f>& points,
                           const std::vector<float>& radii) {
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, slot, RTC_FORMAT_FLOAT4,
                                                          4 * sizeof(float), points.size()));
    for (std::size_t i = 0; i < points.size(); ++i) {
        v[4 * i] = points[i].x;
        v[4 * i + 1] = points[i].y;
        v[4 * i + 2] = points[i].z;
        v[4 * i + 3] = std::max(radii[i], 0.0f);
    }
}

void setTransform(RTCGeometry instance, unsigned step, const Matrix4& transform) {
    float xfm[12];
    for (int column = 0; column < 4; ++column)
        for (int row = 0; row < 3; ++row) xfm[3 * column + row] = static_cast<float>(transform.m[row][column]);
    rtcSetGeometryTransform(instance, step, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, xfm);
}

}  // namespace

RTCGeometryTy* newTriangleGeometry(RTCDeviceTy* device, const std::vector<Vec3f>& positions,
                                   const std::vector<std::vector<Vec3f>>& motion,
                                   const std::vector<std::uint32_t>& indices) {
    RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    if (motion.empty()) {
        fillFloat3Buffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, positions);
    } else {
        rtcSetGeometryTimeStepCount(geom, static_cast<unsigned>(motion.size()));
        for (std::size_t step = 0; step < motion.size(); ++step)
            fillFloat3Buffer(geom, RTC_BUFFER_TYPE_VERTEX, static_cast<unsigned>(step), motion[step]);
    }
    auto* index = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                 3 * sizeof(unsigned), indices.size() / 3));
    std::copy(indices.begin(), indices.end(), index);
    return geom;
}

void setPointRadiusBuffers(RTCGeometryTy* geom, const std::vector<Vec3f>& points, const std::vector<float>& radii,
                           const std::vector<std::vector<Vec3f>>& motionPoints,
                           const std::vector<std::vector<float>>& motionRadii, const std::vector<Vec3f>& normals) {
    const std::size_t steps = std::max<std::size_t>(motionPoints.size(), 1);
    if (!motionPoints.empty()) rtcSetGeometryTimeStepCount(geom, static_cast<unsigned>(steps));
    for (std::size_t step = 0; step < steps; ++step) {
        const auto slot = static_cast<unsigned>(step);
        fillPointRadiusBuffer(geom, slot, motionPoints.empty() ? points : motionPoints[step],
                              motionRadii.empty() ? radii : motionRadii[step]);
        if (!normals.empty()) fillFloat3Buffer(geom, RTC_BUFFER_TYPE_NORMAL, slot, normals);
    }
}

void setInstanceTransforms(RTCGeometryTy* instance, const Matrix4& transform, const std::vector<Matrix4>& motion) {
    if (motion.empty()) {
        setTransform(instance, 0, transform);
        return;
    }
    rtcSetGeometryTimeStepCount(instance, static_cast<unsigned>(motion.size()));
    for (std::size_t step = 0; step < motion.size(); ++step)
        setTransform(instance, static_cast<unsigned>(step), motion[step]);
}

void checkMotionPositions(const std::string& name, const std::vector<std::vector<Vec3f>>& motion,
                          std::size_t vertices) {
    if (motion.empty()) return;
    if (motion.size() < 2) throw std::invalid_argument(name + ": motion needs at least two time steps");
    for (const std::vector<Vec3f>& step : motion)
        if (step.size() != vertices)
            throw std::invalid_argument(name + ": every motion time step needs one position per vertex (" +
                                        std::to_string(vertices) + ")");
}

void checkMotionRadii(const std::string& name, const std::vector<std::vector<float>>& radii,
                      const std::vector<std::vector<Vec3f>>& motion, std::size_t vertices) {
    if (radii.empty()) return;
    if (radii.size() != motion.size())
        throw std::invalid_argument(name + ": motion radii need one set per time step of the positions");
    for (const std::vector<float>& step : radii)
        if (step.size() != vertices)
            throw std::invalid_argument(name + ": every motion time step needs one radius per vertex (" +
                                        std::to_string(vertices) + ")");
}

}  // namespace fluence::render
