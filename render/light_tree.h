// Choosing the light for next-event estimation by where the shading point is: a bounding volume
// hierarchy over the lights with an importance bound per node, after Conty Estevez & Kulla,
// "Importance Sampling of Many Lights with Adaptive Tree Splitting" (HPG 2018), the model pbrt-v4's
// BVH light sampler also follows. Choosing costs one importance evaluation per level, O(log N),
// and nearby, facing, bright lights are chosen more often than far, turned-away or dim ones,
// which the power-proportional choice cannot do.
//
// Leaves hold one light each, with its LightBounds (Light::bounds()): box, power phi, and the cone
// of normals (axis, theta_o) plus the spread theta_e beyond them. An inner node bounds its two
// children: union of the boxes, the smallest cone holding both cones, the wider theta_e, the sum of
// the powers. The importance of a node for a point p with unit normal n is
//     phi * cos(theta') * cos(theta_i') / d^2
//   d        distance from p to the box's centre, at least the box's bounding-sphere radius;
//   theta_u  the angle that bounding sphere subtends at p (every direction when p is inside it);
//   theta'   = max(0, theta - theta_o - theta_u), theta the angle between the axis and the
//            direction from the centre to p; the node is 0 when theta' > theta_e (it emits nothing
//            towards p) and two-sided nodes use |cos theta|;
//   theta_i' = max(0, theta_i - theta_u), theta_i the angle between n and the direction to the
//            centre; 0 beyond 90 degrees. A zero n drops this factor (no surface at p).
// It bounds, up to the orientation cones and a factor pi, the irradiance the node's lights can
// give p, and is 0
// only where none of them can reach p: a light is never given probability 0 where it contributes.
// Walking down, each child is taken with probability importance(child) / (sum of both). When both
// children bound to 0 although their parent did not (their bounds are tighter), the choice goes on
// by the children's powers, so that the probabilities of all lights always sum to 1 (pbrt-v4
// returns no light there instead); the light so chosen cannot reach p and its sample is empty.
//
// Only the lights next-event estimation may choose are in it (the constructor's `chosen`): the others
// (RenderScene leaves a constant dome to BSDF and phase sampling, render/dome_light_sampling.h) are
// never chosen, and their probability is 0.
//
// Lights at infinity are not in the tree. Each has the constant weight power / R^2 (R the scene's
// bounding radius: pi times the irradiance its power spreads over the scene's cross-section, in
// the units of the importance), and the tree as a whole weighs its root's importance at p; the
// choice between them comes first.
//
// One light and none at infinity (a tree of one leaf): the rule above gives that light with
// probability importance / importance = 1 where its importance is above 0, and no light elsewhere,
// so only that zero test is made (Node::reaches). It is decided without square roots or divisions
// from where p lies against two planes, one for emission and one for reception: the importance
// is above 0 exactly when dot(axis, p - centre) > -radius, for a cosine emitter (theta_o = 0,
// theta_e = 90 degrees; |dot| for a two-sided one), and dot(n, p - centre) < radius. Within a
// slack of 2^-10 (|p - centre|_1 + radius) of either plane, or when the bounding sphere subtends
// nearly a hemisphere, and for any other cone, importance() itself is evaluated, so that the
// answer is importance() > 0's; except where that importance underflows to 0 (below FLT_MIN,
// e.g. phi / d^2 < 1e-38), where the light is conservatively still chosen, and where it overflows
// to infinity (a point light 1e-19 away), where the general rule's inf / inf is NaN and this is 1.
//
// The tree is built top down: a node's lights are split along the axis, and at the boundary among
// 12 buckets over their centroids' extent, that minimises Conty Estevez & Kulla's
// surface-area-orientation cost, phi * M_omega(theta_o, theta_e) * area for each side, times the
// node box's aspect ratio along that axis (which discourages long thin boxes). Below depth 48,
// lights are split at the median instead, which bounds the depth by 48 + log2(N).
#pragma once

#include <memory>
#include <vector>

#include "render/light.h"

namespace fluence::render {

// A light index and the probability it was chosen with (light -1: no light can reach the point).
struct LightChoice {
    int light = -1;
    float probability = 0.0f;
};

class LightTree {
public:
    LightTree() = default;
    // `chosen[i]`: whether light i may be chosen (empty: every light; a mask of another size than
    // `lights` throws std::invalid_argument).
    LightTree(const std::vector<std::unique_ptr<Light>>& lights, const SceneBounds& scene,
              const std::vector<bool>& chosen = {});

    // Chooses a light for a point p with unit normal n (zero: none) from u in [0, 1).
    LightChoice choose(const Vec3f& p, const Vec3f& n, float u) const;
    // The probability choose(p, n, .) returns `light` with.
    float probability(const Vec3f& p, const Vec3f& n, int light) const;

    std::size_t nodeCount() const { return nodes_.size(); }
    int depth() const { return depth_; }

private:
    // A node's bounds in the form the importance needs at every query.
    struct Node {
        Vec3f centre;
        float radius = 0.0f;  // of the bounding sphere of the box
        Vec3f axis;
        float cosO = -1.0f, sinO = 0.0f, cosE = 0.0f, phi = 0.0f;
        bool twoSided = false;
        int children[2] = {-1, -1};
        int light = -1;  // a leaf's light; -1 for inner nodes
        int parent = -1;

        void setBounds(const LightBounds& b);
        // phi cos(theta') cos(theta_i') / d^2, with the sines taken only when needed.
        float importance(const Vec3f& p, const Vec3f& n) const;
        // importance(p, n) > 0 (conservatively where it underflows), mostly without evaluating it.
        bool reaches(const Vec3f& p, const Vec3f& n) const;
    };
    struct Item;
    int build(std::vector<Item>& items, std::size_t begin, std::size_t end, int parent, int depth);
    // The probability of taking an inner node's first child at (p, n).
    float leftProbability(const Node& inner, const Vec3f& p, const Vec3f& n) const;
    float rootWeight(const Vec3f& p, const Vec3f& n, float& total) const;
    // A single leaf and no lights at infinity: the choice is that light or none (Node::reaches).
    bool oneLightOnly() const { return nodes_.size() == 1 && infinite_.empty(); }

    std::vector<Node> nodes_;  // root first
    std::vector<int> leafOf_;  // light -> its leaf, -1 for lights at infinity and those never chosen
    std::vector<int> infinite_;
    std::vector<float> infiniteWeights_;
    float infiniteTotal_ = 0.0f;
    int depth_ = 0;
};

}  // namespace fluence::render
