#include "delegate/skel_skeleton.h"

#include <map>

namespace fluence::delegate {

namespace {

std::vector<Matrix4> matrices(const std::vector<double>& numbers) {
    std::vector<Matrix4> out;
    for (std::size_t i = 0; i + 15 < numbers.size(); i += 16) out.push_back(Matrix4::fromUsdRowMajor(&numbers[i]));
    return out;
}

// The joint-local transforms an animation gives, by skeleton joint (nullopt where it gives none).
struct AnimatedJoints {
    std::vector<std::optional<Matrix4>> local;
    bool complete = true;  // every skeleton joint is animated
};

std::optional<AnimatedJoints> animatedJoints(const Skeleton& skeleton, const PrimReader& animation,
                                             const std::function<void(const std::string&)>& warn) {
    const std::vector<std::string> joints = animation.strings("joints").value_or(std::vector<std::string>{});
    const std::vector<double> t = animation.numbers("translations", 3).value_or(std::vector<double>{});
    const std::vector<double> r = animation.numbers("rotations", 4).value_or(std::vector<double>{});
    const std::vector<double> s = animation.numbers("scales", 3).value_or(std::vector<double>{});
    if (joints.empty()) return std::nullopt;
    if (t.size() != 3 * joints.size() || r.size() != 4 * joints.size() || s.size() != 3 * joints.size()) {
        warn(animation.path() + " animates " + std::to_string(joints.size()) + " joints but has " +
             std::to_string(t.size() / 3) + " translations, " + std::to_string(r.size() / 4) + " rotations and " +
             std::to_string(s.size() / 3) + " scales; its joints are left in their rest pose, as UsdSkel does");
        return std::nullopt;
    }
    std::map<std::string, std::size_t> index;
    for (std::size_t j = 0; j < skeleton.joints.size(); ++j) index.emplace(skeleton.joints[j], j);
    AnimatedJoints result;
    result.local.resize(skeleton.joints.size());
    for (std::size_t a = 0; a < joints.size(); ++a) {
        auto it = index.find(joints[a]);
        if (it == index.end()) continue;  // a joint of another skeleton
        const Matrix4 rotation = Matrix4::fromQuaternion(r[4 * a], r[4 * a + 1], r[4 * a + 2], r[4 * a + 3]);
        result.local[it->second] = Matrix4::translate({t[3 * a], t[3 * a + 1], t[3 * a + 2]}) * rotation *
                                   Matrix4::scale({s[3 * a], s[3 * a + 1], s[3 * a + 2]});
    }
    for (const auto& m : result.local) result.complete = result.complete && m.has_value();
    return result;
}

}  // namespace

Skeleton readSkeleton(const PrimReader& prim, const std::function<void(const std::string&)>& warn) {
    Skeleton skeleton;
    skeleton.path = prim.path();
    skeleton.joints = prim.strings("joints").value_or(std::vector<std::string>{});
    const std::size_t n = skeleton.joints.size();
    std::map<std::string, int> index;
    for (std::size_t j = 0; j < n; ++j)
        if (!index.emplace(skeleton.joints[j], static_cast<int>(j)).second)
            prim.fail("joint '" + skeleton.joints[j] + "' is listed twice");
    for (std::size_t j = 0; j < n; ++j) {
        int parent = -1;
        for (std::string p = skeleton.joints[j]; parent < 0;) {
            const std::size_t slash = p.rfind('/');
            if (slash == std::string::npos || slash == 0) break;
            p.resize(slash);
            if (auto it = index.find(p); it != index.end()) parent = it->second;
        }
        if (parent >= static_cast<int>(j))
            prim.fail("joint '" + skeleton.joints[j] + "' is listed before its parent '" +
                      skeleton.joints[static_cast<std::size_t>(parent)] + "'");
        skeleton.parents.push_back(parent);
    }
    const std::vector<Matrix4> bind = matrices(prim.numbers("bindTransforms", 16).value_or(std::vector<double>{}));
    if (bind.size() != n)
        prim.fail("has " + std::to_string(bind.size()) + " bindTransforms for " + std::to_string(n) + " joints");
    for (std::size_t j = 0; j < n; ++j) {
        std::optional<Matrix4> inverse = bind[j].inverse();
        if (!inverse)
            prim.fail("bindTransforms[" + std::to_string(j) + "] (joint '" + skeleton.joints[j] +
                      "') is not invertible");
        skeleton.inverseBind.push_back(*inverse);
    }
    skeleton.rest = matrices(prim.numbers("restTransforms", 16).value_or(std::vector<double>{}));
    if (!skeleton.rest.empty() && skeleton.rest.size() != n) {
        warn("has " + std::to_string(skeleton.rest.size()) + " restTransforms for " + std::to_string(n) +
             " joints; they are ignored");
        skeleton.rest.clear();
    }
    return skeleton;
}

SkeletonPose poseSkeleton(const Skeleton& skeleton, const PrimReader* animation,
                          const std::function<void(const std::string&)>& warn) {
    SkeletonPose pose;
    std::optional<AnimatedJoints> animated = animation ? animatedJoints(skeleton, *animation, warn) : std::nullopt;
    if (animation) {
        pose.blendShapes = animation->strings("blendShapes").value_or(std::vector<std::string>{});
        pose.blendShapeWeights = animation->numbers("blendShapeWeights", 1).value_or(std::vector<double>{});
        if (pose.blendShapeWeights.size() != pose.blendShapes.size()) {
            warn(animation->path() + " has " + std::to_string(pose.blendShapeWeights.size()) +
                 " blendShapeWeights for " + std::to_string(pose.blendShapes.size()) +
                 " blendShapes; its blend shapes are not applied");
            pose.blendShapes.clear();
            pose.blendShapeWeights.clear();
        }
    }
    if (!skeleton.joints.empty() && skeleton.rest.empty() && !(animated && animated->complete))
        throw SceneError(
            skeleton.path + ": has no pose: restTransforms are not authored (or of the wrong size) and " +
            (animated ? "the animation leaves joints out" : std::string("no animation gives every joint")));
    std::vector<Matrix4> world(skeleton.joints.size());
    pose.skinning.reserve(world.size());
    for (std::size_t j = 0; j < world.size(); ++j) {
        const Matrix4& local = animated && animated->local[j] ? *animated->local[j] : skeleton.rest[j];
        const int parent = skeleton.parents[j];
        world[j] = parent < 0 ? local : world[static_cast<std::size_t>(parent)] * local;
        pose.skinning.push_back(world[j] * skeleton.inverseBind[j]);
    }
    return pose;
}

}  // namespace fluence::delegate
