#include "render/light_tree.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/sampling.h"

namespace fluence::render {

namespace {

constexpr int kBuckets = 12;
constexpr int kMedianSplitDepth = 48;
constexpr float kOneMinusEpsilon = 0x1.fffffep-1f;

float safeAcos(float c) { return std::acos(std::clamp(c, -1.0f, 1.0f)); }

// The smallest cone (axis, cos of half-angle) holding the cones a and b.
void uniteCones(Vec3f axisA, float cosA, Vec3f axisB, float cosB, Vec3f& axis, float& cosO) {
    float thetaA = safeAcos(cosA), thetaB = safeAcos(cosB);
    if (thetaA < thetaB) {
        std::swap(axisA, axisB);
        std::swap(thetaA, thetaB);
    }
    float thetaD = safeAcos(dot(axisA, axisB));
    axis = axisA;
    cosO = std::cos(thetaA);
    if (std::min(thetaD + thetaB, kPi) <= thetaA) return;  // a holds b
    float thetaO = 0.5f * (thetaA + thetaD + thetaB);
    Vec3f k = cross(axisA, axisB);
    if (thetaO >= kPi || lengthSquared(k) == 0.0f) {
        cosO = -1.0f;
        return;
    }
    // Rotate axisA towards axisB by thetaO - thetaA (Rodrigues, about k, which is normal to axisA).
    k = normalize(k);
    float turn = thetaO - thetaA;
    axis = normalize(axisA * std::cos(turn) + cross(k, axisA) * std::sin(turn));
    cosO = std::cos(thetaO);
}

LightBounds unite(const LightBounds& a, const LightBounds& b) {
    if (a.phi <= 0.0f) return b;
    if (b.phi <= 0.0f) return a;
    LightBounds u;
    u.lo = vmin(a.lo, b.lo);
    u.hi = vmax(a.hi, b.hi);
    u.phi = a.phi + b.phi;
    uniteCones(a.axis, a.cosThetaO, b.axis, b.cosThetaO, u.axis, u.cosThetaO);
    u.cosThetaE = std::min(a.cosThetaE, b.cosThetaE);
    u.twoSided = a.twoSided || b.twoSided;
    return u;
}

// Conty Estevez & Kulla's orientation measure: the integral of the cosine-weighted emission of a
// cone of normals theta_o spreading light up to theta_e beyond them.
float orientationMeasure(const LightBounds& b) {
    float thetaO = safeAcos(b.cosThetaO), thetaE = safeAcos(b.cosThetaE);
    float thetaW = std::min(thetaO + thetaE, kPi);
    float sinO = std::sin(thetaO);
    return 2.0f * kPi * (1.0f - std::cos(thetaO)) +
           0.5f * kPi *
               (2.0f * thetaW * sinO - std::cos(thetaO - 2.0f * thetaW) - 2.0f * thetaO * sinO + std::cos(thetaO));
}

// The bucket a centroid falls in, of kBuckets spanning [lo, lo + span] along an axis.
int bucketOf(float centroid, float lo, float span) {
    return std::min(kBuckets - 1, int(kBuckets * (centroid - lo) / span));
}

float surfaceArea(const Vec3f& lo, const Vec3f& hi, float pad) {
    Vec3f e = hi - lo + Vec3f(2.0f * pad);
    return 2.0f * (e.x * e.y + e.y * e.z + e.z * e.x);
}

// Node::reaches: the slack, relative to |p - centre|_1 + radius, within which a plane test is left
// to importance(). importance()'s rounding moves its cosines by at most ~25 eps / cos(theta_u),
// while a point the slack away from the plane has them at least 2/pi of the slack over d away from
// 0; so the slack holds them apart while cos(theta_u) >= 1/64, i.e. 4096 (d^2 - r^2) >= d^2.
constexpr float kReachSlack = 0x1p-10f;
constexpr float kReachHemisphere = 4096.0f;

enum class Reach { No, Yes, Unclear };

// Whether x > -radius, the form both of Node::reaches's plane tests take, when x is clear of the
// slack (NaN: unclear).
Reach beyondPlane(float x, float radius, float slack) {
    if (x > slack - radius) return Reach::Yes;
    if (x < -radius - slack) return Reach::No;
    return Reach::Unclear;
}

}  // namespace

void LightTree::Node::setBounds(const LightBounds& b) {
    centre = (b.lo + b.hi) * 0.5f;
    radius = 0.5f * length(b.hi - b.lo);
    axis = b.axis;
    cosO = b.cosThetaO;
    sinO = std::sqrt(std::max(0.0f, 1.0f - cosO * cosO));
    cosE = b.cosThetaE;
    phi = b.phi;
    twoSided = b.twoSided;
}

float LightTree::Node::importance(const Vec3f& p, const Vec3f& n) const {
    if (phi <= 0.0f) return 0.0f;
    Vec3f v = p - centre;
    float d2 = lengthSquared(v), r2 = radius * radius;
    if (d2 <= r2) return phi / std::max(r2, 1e-20f);  // inside the bounding sphere: any direction
    float invD = 1.0f / std::sqrt(d2);
    Vec3f w = v * invD;
    float sinU = radius * invD, cosU = std::sqrt(std::max(0.0f, 1.0f - sinU * sinU));
    // Emission: theta' = max(0, theta - (theta_o + theta_u)); nothing to cut when the sum
    // reaches pi (its sine turns negative).
    float cosTheta = dot(axis, w);
    if (twoSided) cosTheta = std::abs(cosTheta);
    float cosOU = cosO * cosU - sinO * sinU, sinOU = sinO * cosU + cosO * sinU;
    float cosEmit = 1.0f;
    if (sinOU >= 0.0f && cosTheta < cosOU)
        cosEmit = cosTheta * cosOU + std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta)) * sinOU;
    if (cosEmit < cosE) return 0.0f;
    // Reception: theta_i' = max(0, theta_i - theta_u).
    float cosReceive = 1.0f;
    if (n.x != 0.0f || n.y != 0.0f || n.z != 0.0f) {
        float cosI = -dot(n, w);
        if (cosI < cosU) cosReceive = cosI * cosU + std::sqrt(std::max(0.0f, 1.0f - cosI * cosI)) * sinU;
        if (cosReceive <= 0.0f) return 0.0f;
    }
    return phi * std::max(cosEmit, 0.0f) * cosReceive / d2;
}

bool LightTree::Node::reaches(const Vec3f& p, const Vec3f& n) const {
    if (!(phi > 0.0f)) return false;
    Vec3f v = p - centre;
    float d2 = lengthSquared(v), r2 = radius * radius;
    if (d2 <= r2) return true;  // importance() = phi / r^2
    if (kReachHemisphere * (d2 - r2) >= d2) {
        float slack = kReachSlack * (std::abs(v.x) + std::abs(v.y) + std::abs(v.z) + radius);
        // Emission: every direction (theta_o = 180 degrees) or, for a cosine emitter, the plane
        // through the centre pushed back by the radius.
        Reach emits = Reach::Unclear;
        if (cosO == -1.0f) {
            emits = Reach::Yes;
        } else if (cosO == 1.0f && cosE == 0.0f) {
            float along = dot(axis, v);
            emits = beyondPlane(twoSided ? std::abs(along) : along, radius, slack);
        }
        // Reception: the bounding sphere must rise above the plane of p (n roughly unit, as the
        // slack assumes).
        Reach receives = Reach::Yes;
        if (n.x != 0.0f || n.y != 0.0f || n.z != 0.0f)
            receives = std::abs(lengthSquared(n) - 1.0f) <= 1.0f / 64.0f ? beyondPlane(-dot(n, v), radius, slack)
                                                                         : Reach::Unclear;
        if (emits == Reach::No || receives == Reach::No) return false;
        if (emits == Reach::Yes && receives == Reach::Yes) return true;
    }
    return importance(p, n) > 0.0f;
}

struct LightTree::Item {
    LightBounds bounds;
    int light;
    Vec3f centroid;
};

LightTree::LightTree(const std::vector<std::unique_ptr<Light>>& lights, const SceneBounds& scene,
                     const std::vector<bool>& chosen) {
    if (!chosen.empty() && chosen.size() != lights.size())
        throw std::invalid_argument("LightTree: a choice mask of " + std::to_string(chosen.size()) + " entries for " +
                                    std::to_string(lights.size()) + " lights");
    leafOf_.assign(lights.size(), -1);
    std::vector<Item> items;
    for (std::size_t i = 0; i < lights.size(); ++i) {
        if (!chosen.empty() && !chosen[i]) continue;
        if (std::optional<LightBounds> b = lights[i]->bounds()) {
            items.push_back({*b, static_cast<int>(i), (b->lo + b->hi) * 0.5f});
        } else {
            infinite_.push_back(static_cast<int>(i));
            infiniteWeights_.push_back(std::max(0.0f, lights[i]->power(scene)) / (scene.radius * scene.radius));
            infiniteTotal_ += infiniteWeights_.back();
        }
    }
    if (!items.empty()) {
        nodes_.reserve(2 * items.size() - 1);
        build(items, 0, items.size(), -1, 0);
    }
}

int LightTree::build(std::vector<Item>& items, std::size_t begin, std::size_t end, int parent, int depth) {
    int index = static_cast<int>(nodes_.size());
    nodes_.push_back(Node{});
    nodes_[index].parent = parent;
    depth_ = std::max(depth_, depth);
    if (end - begin == 1) {
        nodes_[index].setBounds(items[begin].bounds);
        nodes_[index].light = items[begin].light;
        leafOf_[items[begin].light] = index;
        return index;
    }
    LightBounds all = items[begin].bounds;
    Vec3f centroidLo = items[begin].centroid, centroidHi = items[begin].centroid;
    for (std::size_t i = begin + 1; i < end; ++i) {
        all = unite(all, items[i].bounds);
        centroidLo = vmin(centroidLo, items[i].centroid);
        centroidHi = vmax(centroidHi, items[i].centroid);
    }

    // The cheapest bucket boundary over the three axes.
    Vec3f extent = all.hi - all.lo;
    float pad = 1e-3f * length(extent);
    float bestCost = std::numeric_limits<float>::infinity();
    int bestAxis = -1, bestBoundary = 0;
    for (int axis = 0; axis < 3 && depth < kMedianSplitDepth; ++axis) {
        float lo = centroidLo[axis], span = centroidHi[axis] - lo;
        if (!(span > 0.0f)) continue;
        std::array<LightBounds, kBuckets> buckets{};
        std::array<int, kBuckets> counts{};
        for (std::size_t i = begin; i < end; ++i) {
            int b = bucketOf(items[i].centroid[axis], lo, span);
            buckets[b] = counts[b]++ ? unite(buckets[b], items[i].bounds) : items[i].bounds;
        }
        // below[b]: buckets 0..b united, with belowCount[b] lights; above[b]: buckets b..K-1.
        std::array<LightBounds, kBuckets> below{}, above{};
        std::array<int, kBuckets> belowCount{};
        for (int b = 0, seen = 0; b < kBuckets; ++b) {
            below[b] =
                !counts[b] ? (b ? below[b - 1] : LightBounds{}) : (seen ? unite(below[b - 1], buckets[b]) : buckets[b]);
            seen += counts[b];
            belowCount[b] = seen;
        }
        for (int b = kBuckets - 1, seen = 0; b >= 0; --b) {
            above[b] = !counts[b] ? (b < kBuckets - 1 ? above[b + 1] : LightBounds{})
                                  : (seen ? unite(above[b + 1], buckets[b]) : buckets[b]);
            seen += counts[b];
        }
        auto cost = [&](const LightBounds& b) { return b.phi * orientationMeasure(b) * surfaceArea(b.lo, b.hi, pad); };
        float aspect = maxComponent(extent) / std::max(extent[axis], 1e-20f);
        const int count = static_cast<int>(end - begin);
        for (int boundary = 1; boundary < kBuckets; ++boundary) {
            if (belowCount[boundary - 1] == 0 || belowCount[boundary - 1] == count) continue;
            float c = aspect * (cost(below[boundary - 1]) + cost(above[boundary]));
            if (c < bestCost) {
                bestCost = c;
                bestAxis = axis;
                bestBoundary = boundary;
            }
        }
    }

    std::size_t middle;
    if (bestAxis >= 0) {
        float lo = centroidLo[bestAxis], span = centroidHi[bestAxis] - lo;
        middle = std::partition(
                     items.begin() + begin, items.begin() + end,
                     [&](const Item& item) { return bucketOf(item.centroid[bestAxis], lo, span) < bestBoundary; }) -
                 items.begin();
    } else {
        // Median split along the widest centroid axis (also when every centroid coincides).
        Vec3f span = centroidHi - centroidLo;
        int axis = span.x >= span.y && span.x >= span.z ? 0 : (span.y >= span.z ? 1 : 2);
        middle = (begin + end) / 2;
        std::nth_element(items.begin() + begin, items.begin() + middle, items.begin() + end,
                         [axis](const Item& a, const Item& b) { return a.centroid[axis] < b.centroid[axis]; });
    }
    int left = build(items, begin, middle, index, depth + 1);
    int right = build(items, middle, end, index, depth + 1);
    nodes_[index].children[0] = left;
    nodes_[index].children[1] = right;
    nodes_[index].setBounds(all);
    return index;
}

float LightTree::leftProbability(const Node& inner, const Vec3f& p, const Vec3f& n) const {
    const Node& left = nodes_[inner.children[0]];
    const Node& right = nodes_[inner.children[1]];
    float a = left.importance(p, n), b = right.importance(p, n);
    if (!(a + b > 0.0f)) {
        a = left.phi;
        b = right.phi;
    }
    return a + b > 0.0f ? a / (a + b) : 0.5f;
}

float LightTree::rootWeight(const Vec3f& p, const Vec3f& n, float& total) const {
    float weight = nodes_.empty() ? 0.0f : nodes_[0].importance(p, n);
    total = weight + infiniteTotal_;
    return weight;
}

LightChoice LightTree::choose(const Vec3f& p, const Vec3f& n, float u) const {
    if (oneLightOnly()) return nodes_[0].reaches(p, n) ? LightChoice{nodes_[0].light, 1.0f} : LightChoice{};
    float total;
    float treeWeight = rootWeight(p, n, total);
    if (!(total > 0.0f)) return {};
    float scaled = u * total;
    if (scaled < infiniteTotal_ || treeWeight == 0.0f) {
        float running = 0.0f;
        int chosen = -1;
        for (std::size_t i = 0; i < infinite_.size(); ++i) {
            if (infiniteWeights_[i] == 0.0f) continue;
            chosen = static_cast<int>(i);
            running += infiniteWeights_[i];
            if (scaled < running) break;
        }
        return {infinite_[chosen], infiniteWeights_[chosen] / total};
    }
    u = std::min((scaled - infiniteTotal_) / treeWeight, kOneMinusEpsilon);
    float probability = treeWeight / total;
    int node = 0;
    while (nodes_[node].light < 0) {
        const Node& inner = nodes_[node];
        float pLeft = leftProbability(inner, p, n);
        if (u < pLeft) {
            node = inner.children[0];
            probability *= pLeft;
            u = std::min(u / pLeft, kOneMinusEpsilon);
        } else {
            node = inner.children[1];
            probability *= 1.0f - pLeft;
            u = std::min((u - pLeft) / (1.0f - pLeft), kOneMinusEpsilon);
        }
    }
    return {nodes_[node].light, probability};
}

float LightTree::probability(const Vec3f& p, const Vec3f& n, int light) const {
    if (light < 0 || light >= static_cast<int>(leafOf_.size())) return 0.0f;
    int node = leafOf_[light];
    const auto infinite = node < 0 ? std::find(infinite_.begin(), infinite_.end(), light) : infinite_.end();
    if (node < 0 && infinite == infinite_.end()) return 0.0f;          // never chosen
    if (oneLightOnly()) return nodes_[0].reaches(p, n) ? 1.0f : 0.0f;  // `light` is the leaf's (the only one)
    float total;
    float treeWeight = rootWeight(p, n, total);
    if (!(total > 0.0f)) return 0.0f;
    if (node < 0) return infiniteWeights_[infinite - infinite_.begin()] / total;
    float probability = treeWeight / total;
    for (; node != 0 && probability > 0.0f; node = nodes_[node].parent) {
        const Node& parent = nodes_[nodes_[node].parent];
        float pLeft = leftProbability(parent, p, n);
        probability *= node == parent.children[0] ? pLeft : 1.0f - pLeft;
    }
    return probability;
}

}  // namespace fluence::render
