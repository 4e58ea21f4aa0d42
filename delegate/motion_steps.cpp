#include "delegate/motion_steps.h"

#include <algorithm>

namespace fluence::delegate {

namespace {

// What each kind of primitive moves, and what must stay the same for it to move.
const std::vector<Vec3f>& positionsOf(const render::MeshDesc& m) { return m.positions; }
const std::vector<Vec3f>& positionsOf(const render::CurvesDesc& c) { return c.points; }
const std::vector<Vec3f>& positionsOf(const render::PointsDesc& p) { return p.positions; }
std::vector<std::vector<Vec3f>>& motionOf(render::MeshDesc& m) { return m.motionPositions; }
std::vector<std::vector<Vec3f>>& motionOf(render::CurvesDesc& c) { return c.motionPoints; }
std::vector<std::vector<Vec3f>>& motionOf(render::PointsDesc& p) { return p.motionPositions; }
std::vector<float> radiiOf(const render::MeshDesc&) { return {}; }
std::vector<float> radiiOf(const render::CurvesDesc& c) { return c.radii; }
std::vector<float> radiiOf(const render::PointsDesc& p) { return p.radii; }
void storeRadii(render::MeshDesc&, std::vector<std::vector<float>>&&) {}
void storeRadii(render::CurvesDesc& c, std::vector<std::vector<float>>&& radii) { c.motionRadii = std::move(radii); }
void storeRadii(render::PointsDesc& p, std::vector<std::vector<float>>&& radii) { p.motionRadii = std::move(radii); }

bool sameTopology(const render::MeshDesc& a, const render::MeshDesc& b) {
    return a.name == b.name && a.positions.size() == b.positions.size() && a.indices == b.indices;
}
bool sameTopology(const render::CurvesDesc& a, const render::CurvesDesc& b) {
    return a.name == b.name && a.basis == b.basis && a.points.size() == b.points.size() && a.segments == b.segments;
}
bool sameTopology(const render::PointsDesc& a, const render::PointsDesc& b) {
    return a.name == b.name && a.positions.size() == b.positions.size();
}

const char* topologyChange(const render::MeshDesc&) {
    return "its triangles change during the shutter; rendered without motion blur";
}
const char* topologyChange(const render::CurvesDesc&) {
    return "its curves change during the shutter; rendered without motion blur";
}
const char* topologyChange(const render::PointsDesc&) {
    return "its number of points changes during the shutter; rendered without motion blur";
}

// Whether any step differs from the first.
template <typename T>
bool varies(const std::vector<T>& steps) {
    return std::any_of(steps.begin(), steps.end(), [&](const T& s) { return s != steps.front(); });
}

}  // namespace

template <typename Desc>
void MotionSteps<Desc>::add(const std::vector<Desc>& frame, const std::vector<Desc>& step, const Warn& warn) {
    for (std::size_t i = 0; i < frame.size(); ++i) {
        const bool same = i < step.size() && sameTopology(frame[i], step[i]);
        if (!same && !still_[i]) warn(frame[i].name, topologyChange(frame[i]));
        still_[i] = still_[i] || !same;
        if (still_[i]) continue;
        positions_[i].push_back(positionsOf(step[i]));
        radii_[i].push_back(radiiOf(step[i]));
    }
}

template <typename Desc>
void MotionSteps<Desc>::store(std::vector<Desc>& frame) {
    for (std::size_t i = 0; i < frame.size(); ++i) {
        if (still_[i] || positions_[i].size() < 2) continue;
        const bool radiiVary = varies(radii_[i]);
        if (!varies(positions_[i]) && !radiiVary) continue;
        motionOf(frame[i]) = std::move(positions_[i]);
        if (radiiVary) storeRadii(frame[i], std::move(radii_[i]));
    }
}

PrototypeMotionSteps::PrototypeMotionSteps(const std::vector<render::PrototypeDesc>& frame) {
    for (const render::PrototypeDesc& p : frame)
        steps_.push_back({MotionSteps<render::MeshDesc>(p.meshes.size()),
                          MotionSteps<render::CurvesDesc>(p.curves.size()),
                          MotionSteps<render::PointsDesc>(p.points.size())});
}

void PrototypeMotionSteps::add(const std::vector<render::PrototypeDesc>& frame,
                               const std::vector<render::PrototypeDesc>& step, const Warn& warn) {
    static const render::PrototypeDesc kMissing;
    for (std::size_t i = 0; i < frame.size(); ++i) {
        const render::PrototypeDesc* match = i < step.size() && step[i].name == frame[i].name ? &step[i] : nullptr;
        for (std::size_t j = 0; !match && j < step.size(); ++j)
            if (step[j].name == frame[i].name) match = &step[j];
        const render::PrototypeDesc& s = match ? *match : kMissing;
        steps_[i].meshes.add(frame[i].meshes, s.meshes, warn);
        steps_[i].curves.add(frame[i].curves, s.curves, warn);
        steps_[i].points.add(frame[i].points, s.points, warn);
    }
}

void PrototypeMotionSteps::store(std::vector<render::PrototypeDesc>& frame) {
    for (std::size_t i = 0; i < frame.size(); ++i) {
        steps_[i].meshes.store(frame[i].meshes);
        steps_[i].curves.store(frame[i].curves);
        steps_[i].points.store(frame[i].points);
    }
}

template class MotionSteps<render::MeshDesc>;
template class MotionSteps<render::CurvesDesc>;
template class MotionSteps<render::PointsDesc>;

}  // namespace fluence::delegate
