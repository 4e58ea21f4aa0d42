#include "delegate/motion_samples.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "delegate/motion_steps.h"
#include "delegate/prim_copy.h"
#include "delegate/scene_delegate.h"
#include "scene/layer_stack.h"

namespace fluence::delegate {

namespace {

// Whether the attribute `name` of `prim` has more than one time sample (its value changes).
bool timeSampled(const usd::PrimSpec& prim, const char* name) {
    const usd::AttributeSpec* attribute = prim.attribute(name);
    return attribute && attribute->timeSamples.size() > 1;
}

// The seconds from `from` to `to`, in time codes of the stage.
double secondsBetween(const usd::Stage& stage, double from, double to) {
    return (to - from) / usd::detail::timeCodesPerSecond(stage.rootLayer());
}

// Vectors of `name` read at `time`, when it holds `count` of them.
std::optional<std::vector<double>> vectorsOf(const usd::PrimSpec& prim, double time, const char* name,
                                             std::size_t count) {
    std::optional<std::vector<double>> values = PrimReader(prim, time).numbers(name, 3);
    if (!values || values->size() != 3 * count) return std::nullopt;
    return values;
}

// The transforms at each motion step of the frame's instances or lights (each has a name, a
// transform and motionTransforms), matched to the step's by index and by `same`; one that does not
// match at some step renders still, with one warning.
template <class Item>
class TransformSteps {
public:
    TransformSteps(std::size_t count, const char* changed) : steps_(count), still_(count, false), changed_(changed) {}

    template <class Same>
    void add(const std::vector<Item>& frame, const std::vector<Item>& step, Same&& same, const Warn& warn) {
        for (std::size_t i = 0; i < frame.size(); ++i) {
            const bool matches = i < step.size() && step[i].name == frame[i].name && same(step[i], frame[i]);
            if (!matches && !still_[i]) warn(frame[i].name, changed_);
            still_[i] = still_[i] || !matches;
            if (!still_[i]) steps_[i].push_back(step[i].transform);
        }
    }
    // Gives each item that moved (its transform differs between steps) its motionTransforms.
    void store(std::vector<Item>& frame) {
        for (std::size_t i = 0; i < frame.size(); ++i) {
            std::vector<Matrix4>& steps = steps_[i];
            if (still_[i] ||
                std::all_of(steps.begin(), steps.end(), [&](const Matrix4& s) { return s.m == steps.front().m; }))
                continue;
            frame[i].motionTransforms = std::move(steps);
        }
    }

private:
    std::vector<std::vector<Matrix4>> steps_;
    std::vector<bool> still_;
    const char* changed_;
};

}  // namespace

std::vector<double> motionStepTimes(const usd::Stage& stage, double frame, double open, double close) {
    const double lo = frame + open, hi = frame + close, span = hi - lo;
    std::set<double> inside;  // the authored sample times strictly inside the shutter
    stage.traverse([&](const usd::PrimSpec& prim) {
        for (const usd::AttributeSpec& attribute : prim.attributes)
            for (const auto& sample : attribute.timeSamples)
                if (sample.first > lo && sample.first < hi) inside.insert(sample.first);
        return true;
    });
    int segments = 1;
    auto onSteps = [&](int n) {
        return std::all_of(inside.begin(), inside.end(), [&](double t) {
            const double x = (t - lo) / span * n;
            return std::abs(x - std::round(x)) < 1e-6 * n;
        });
    };
    while (segments < kMaxMotionSteps - 1 && !onSteps(segments)) ++segments;
    std::vector<double> times;
    for (int k = 0; k <= segments; ++k) times.push_back(lo + span * k / segments);
    times.back() = hi;
    return times;
}

void moveByVelocities(const usd::Stage& stage, const usd::PrimSpec& prim, double time, double velocityFrame,
                      const Matrix4& toWorld, std::vector<Vec3f>& positions) {
    if (std::isnan(velocityFrame) || timeSampled(prim, "points")) return;
    const std::optional<std::vector<double>> velocities =
        vectorsOf(prim, velocityFrame, "velocities", positions.size());
    if (!velocities) return;
    const std::optional<std::vector<double>> accelerations =
        vectorsOf(prim, velocityFrame, "accelerations", positions.size());
    const double dt = secondsBetween(stage, velocityFrame, time);
    for (std::size_t i = 0; i < positions.size(); ++i) {
        Vec3d step = Vec3d((*velocities)[3 * i], (*velocities)[3 * i + 1], (*velocities)[3 * i + 2]) * dt;
        if (accelerations)
            step = step + Vec3d((*accelerations)[3 * i], (*accelerations)[3 * i + 1], (*accelerations)[3 * i + 2]) *
                              (0.5 * dt * dt);
        positions[i] = Vec3f(Vec3d(positions[i]) + toWorld.transformVector(step));
    }
}

std::unique_ptr<usd::PrimSpec> withPointsMovedByVelocities(const usd::Stage& stage, const usd::PrimSpec& prim,
                                                           double time, double velocityFrame) {
    if (std::isnan(velocityFrame) || !movesByVelocities(prim)) return nullptr;
    const std::optional<std::vector<double>> points = PrimReader(prim, time).numbers("points", 3);
    if (!points) return nullptr;
    std::vector<Vec3f> positions;
    for (std::size_t i = 0; i + 2 < points->size(); i += 3)
        positions.push_back(Vec3f(Vec3d((*points)[i], (*points)[i + 1], (*points)[i + 2])));
    moveByVelocities(stage, prim, time, velocityFrame, Matrix4::identity(), positions);
    std::vector<double> moved;
    moved.reserve(points->size());
    for (const Vec3f& p : positions) moved.insert(moved.end(), {p.x, p.y, p.z});
    std::unique_ptr<usd::PrimSpec> copy = copyPrim(prim);
    setArray(*copy, "points", "point3f[]", std::move(moved), 3);
    return copy;
}

std::optional<InstanceVelocityMotion> instanceVelocityMotion(const usd::Stage& stage, const usd::PrimSpec& instancer,
                                                             double time, double velocityFrame, std::size_t count) {
    if (std::isnan(velocityFrame) || timeSampled(instancer, "positions")) return std::nullopt;
    const std::optional<std::vector<double>> velocities = vectorsOf(instancer, velocityFrame, "velocities", count);
    const std::optional<std::vector<double>> angular = vectorsOf(instancer, velocityFrame, "angularVelocities", count);
    if (!velocities && !angular) return std::nullopt;
    const std::optional<std::vector<double>> accelerations =
        vectorsOf(instancer, velocityFrame, "accelerations", count);
    const double dt = secondsBetween(stage, velocityFrame, time);
    InstanceVelocityMotion motion;
    for (std::size_t i = 0; velocities && i < count; ++i) {
        Vec3d offset = Vec3d((*velocities)[3 * i], (*velocities)[3 * i + 1], (*velocities)[3 * i + 2]) * dt;
        if (accelerations)
            offset = offset + Vec3d((*accelerations)[3 * i], (*accelerations)[3 * i + 1], (*accelerations)[3 * i + 2]) *
                                  (0.5 * dt * dt);
        motion.offsets.push_back(offset);
    }
    for (std::size_t i = 0; angular && i < count; ++i) {
        const Vec3d w((*angular)[3 * i], (*angular)[3 * i + 1], (*angular)[3 * i + 2]);
        const double speed = length(w);  // degrees per second
        if (!(speed > 0.0)) {
            motion.rotations.push_back(Matrix4::identity());
            continue;
        }
        const double half = 0.5 * speed * dt * M_PI / 180.0;
        const Vec3d axis = w / speed * std::sin(half);
        motion.rotations.push_back(Matrix4::fromQuaternion(std::cos(half), axis.x, axis.y, axis.z));
    }
    return motion;
}

bool movesByVelocities(const usd::PrimSpec& prim) {
    return (prim.attribute("velocities") || prim.attribute("angularVelocities")) && !timeSampled(prim, "points") &&
           !timeSampled(prim, "positions");
}

bool movesByVelocitiesAtOrBelow(const usd::PrimSpec& root) {
    bool moves = false;
    usd::Stage::traverse(root, [&](const usd::PrimSpec& prim) {
        moves = moves || movesByVelocities(prim);
        return !moves;
    });
    return moves;
}

void addMotion(SceneDelegate& delegate, usd::Stage& stage, const DelegateOptions& options,
               const render::CameraDesc& camera, render::SceneDescription& scene) {
    if (std::isnan(options.time) || !(camera.shutterClose > camera.shutterOpen)) return;
    const std::vector<double> times = motionStepTimes(stage, options.time, camera.shutterOpen, camera.shutterClose);
    MotionSteps<render::MeshDesc> meshSteps(scene.meshes.size());
    MotionSteps<render::CurvesDesc> curveSteps(scene.curves.size());
    MotionSteps<render::PointsDesc> pointSteps(scene.points.size());
    PrototypeMotionSteps prototypeSteps(scene.prototypes);
    TransformSteps<render::InstanceDesc> instanceSteps(
        scene.instances.size(), "the instances change during the shutter; rendered without motion blur");
    TransformSteps<render::LightDesc> lightSteps(scene.lights.size(),
                                                 "the lights change during the shutter; rendered without motion blur");
    std::vector<Matrix4> cameraSteps;
    std::vector<render::CameraLensStep> lensSteps;
    for (double time : times) {
        delegate.setMotionStep(time, options.time);
        delegate.sync();
        const render::SceneDescription step = delegate.sceneDescription();
        meshSteps.add(scene.meshes, step.meshes, options.warn);
        curveSteps.add(scene.curves, step.curves, options.warn);
        pointSteps.add(scene.points, step.points, options.warn);
        prototypeSteps.add(scene.prototypes, step.prototypes, options.warn);
        if (step.camera && scene.camera && step.camera->name == scene.camera->name) {
            cameraSteps.push_back(step.camera->transform);
            lensSteps.push_back({step.camera->focalLength, step.camera->fStop, step.camera->focusDistance});
        }
        instanceSteps.add(
            scene.instances, step.instances,
            [](const render::InstanceDesc& a, const render::InstanceDesc& b) { return a.prototype == b.prototype; },
            options.warn);
        lightSteps.add(
            scene.lights, step.lights,
            [](const render::LightDesc& a, const render::LightDesc& b) { return a.type == b.type; }, options.warn);
    }
    meshSteps.store(scene.meshes);
    curveSteps.store(scene.curves);
    pointSteps.store(scene.points);
    prototypeSteps.store(scene.prototypes);
    if (scene.camera && cameraSteps.size() == times.size() &&
        std::any_of(cameraSteps.begin(), cameraSteps.end(),
                    [&](const Matrix4& s) { return s.m != cameraSteps.front().m; }))
        scene.camera->motionTransforms = std::move(cameraSteps);
    auto sameLens = [&](const render::CameraLensStep& l) {
        const render::CameraLensStep& first = lensSteps.front();
        return l.focalLength == first.focalLength && l.fStop == first.fStop && l.focusDistance == first.focusDistance;
    };
    if (scene.camera && lensSteps.size() == times.size() && !std::all_of(lensSteps.begin(), lensSteps.end(), sameLens))
        scene.camera->motionLenses = std::move(lensSteps);
    instanceSteps.store(scene.instances);
    lightSteps.store(scene.lights);
}

}  // namespace fluence::delegate
