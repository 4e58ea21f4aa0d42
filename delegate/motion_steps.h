// The time steps of the world primitives that move during the shutter (delegate/motion_samples.h):
// meshes, curves and points described again at each motion step, their positions (and curves' and
// points' radii) gathered step by step, and stored as the frame's description's motion once every
// step is in. A primitive whose topology changes between steps (other triangles, segments or
// point count) renders still, with one warning.
#pragma once

#include <string>
#include <vector>

#include "core/vec.h"
#include "delegate/material_adapter.h"  // Warn
#include "render/scene_description.h"

namespace fluence::delegate {

template <typename Desc>
class MotionSteps {
public:
    explicit MotionSteps(std::size_t count) : positions_(count), radii_(count), still_(count, false) {}

    // Adds the step `step` of the primitives `frame` describes at the frame.
    void add(const std::vector<Desc>& frame, const std::vector<Desc>& step, const Warn& warn);
    // Stores the motion of each primitive of `frame` that moved (its positions or radii changed).
    void store(std::vector<Desc>& frame);

private:
    std::vector<std::vector<std::vector<Vec3f>>> positions_;
    std::vector<std::vector<std::vector<float>>> radii_;
    std::vector<bool> still_;
};

// MotionSteps for the meshes, curves and points of each prototype of the frame's description.
class PrototypeMotionSteps {
public:
    explicit PrototypeMotionSteps(const std::vector<render::PrototypeDesc>& frame);
    // Adds the step `step` of the prototypes `frame` describes at the frame (matched by name: a
    // prototype missing from the step renders still, with a warning).
    void add(const std::vector<render::PrototypeDesc>& frame, const std::vector<render::PrototypeDesc>& step,
             const Warn& warn);
    void store(std::vector<render::PrototypeDesc>& frame);

private:
    struct Steps {
        MotionSteps<render::MeshDesc> meshes;
        MotionSteps<render::CurvesDesc> curves;
        MotionSteps<render::PointsDesc> points;
    };
    std::vector<Steps> steps_;
};

extern template class MotionSteps<render::MeshDesc>;
extern template class MotionSteps<render::CurvesDesc>;
extern template class MotionSteps<render::PointsDesc>;

}  // namespace fluence::delegate
