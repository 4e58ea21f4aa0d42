#include "delegate/skel_skinning.h"

#include <cmath>

namespace fluence::delegate {

namespace {

struct Quat {
    double w = 0.0;
    Vec3d v{0.0, 0.0, 0.0};

    Quat operator*(const Quat& o) const { return {w * o.w - dot(v, o.v), o.v * w + v * o.w + cross(v, o.v)}; }
    Quat operator*(double s) const { return {w * s, v * s}; }
    Quat operator+(const Quat& o) const { return {w + o.w, v + o.v}; }
    Quat conjugate() const { return {w, -v}; }
    // Rotates `p` (a unit quaternion).
    Vec3d rotate(const Vec3d& p) const { return p + cross(v, p) * (2.0 * w) + cross(v, cross(v, p)) * 2.0; }
};

double dot(const Quat& a, const Quat& b) { return a.w * b.w + fluence::dot(a.v, b.v); }

// The unit quaternion of a rotation matrix's upper 3x3 (column-vector convention).
Quat quaternionOf(const Matrix4& r) {
    const auto& m = r.m;
    const double trace = m[0][0] + m[1][1] + m[2][2];
    if (trace > 0.0) {
        const double s = 2.0 * std::sqrt(trace + 1.0);
        return {0.25 * s, {(m[2][1] - m[1][2]) / s, (m[0][2] - m[2][0]) / s, (m[1][0] - m[0][1]) / s}};
    }
    if (m[0][0] > m[1][1] && m[0][0] > m[2][2]) {
        const double s = 2.0 * std::sqrt(1.0 + m[0][0] - m[1][1] - m[2][2]);
        return {(m[2][1] - m[1][2]) / s, {0.25 * s, (m[0][1] + m[1][0]) / s, (m[0][2] + m[2][0]) / s}};
    }
    if (m[1][1] > m[2][2]) {
        const double s = 2.0 * std::sqrt(1.0 + m[1][1] - m[0][0] - m[2][2]);
        return {(m[0][2] - m[2][0]) / s, {(m[0][1] + m[1][0]) / s, 0.25 * s, (m[1][2] + m[2][1]) / s}};
    }
    const double s = 2.0 * std::sqrt(1.0 + m[2][2] - m[0][0] - m[1][1]);
    return {(m[1][0] - m[0][1]) / s, {(m[0][2] + m[2][0]) / s, (m[1][2] + m[2][1]) / s, 0.25 * s}};
}

// A rigid transform as a dual quaternion: rotation `real`, translation t in dual = t·real / 2.
struct DualQuat {
    Quat real, dual;

    DualQuat operator*(double s) const { return {real * s, dual * s}; }
    DualQuat operator+(const DualQuat& o) const { return {real + o.real, dual + o.dual}; }
    // As GfDualQuatd::Normalize: a unit real part, and a dual part orthogonal to it.
    DualQuat normalized() const {
        const double len = std::sqrt(dot(real, real));
        if (len == 0.0) return {};
        DualQuat n{real * (1.0 / len), dual * (1.0 / len)};
        n.dual = n.dual + n.real * -dot(n.real, n.dual);
        return n;
    }
    Vec3d translation() const { return (dual * real.conjugate()).v * 2.0; }
    Vec3d transformPoint(const Vec3d& p) const { return real.rotate(p) + translation(); }
};

// A joint's skinning transform M factored as M = T · R · S (column vectors): the rigid part T·R as
// a dual quaternion and the rest, S = Rᵀ·M₃ (scale and shear), as a matrix. R comes from the
// Gram-Schmidt orthonormalised columns of M's 3x3, which is USD's rotation for any joint of
// rotation and scale; a mirroring joint keeps a proper rotation and its reflection goes to S.
struct FactoredJoint {
    DualQuat rigid;
    Matrix4 rest = Matrix4::identity();
    bool restIsIdentity = true;
};

FactoredJoint factor(const Matrix4& m) {
    Vec3d c0{m.m[0][0], m.m[1][0], m.m[2][0]}, c1{m.m[0][1], m.m[1][1], m.m[2][1]};
    if (length(c0) == 0.0 || length(cross(c0, c1)) == 0.0) return {};  // degenerate: a zero quaternion, as USD's
    const Vec3d r0 = normalize(c0);
    const Vec3d r1 = normalize(c1 - r0 * fluence::dot(r0, c1));
    const Vec3d r2 = cross(r0, r1);
    Matrix4 rotation = Matrix4::identity();
    for (int i = 0; i < 3; ++i) {
        rotation.m[i][0] = r0[i];
        rotation.m[i][1] = r1[i];
        rotation.m[i][2] = r2[i];
    }
    FactoredJoint joint;
    const Quat q = quaternionOf(rotation);
    const Vec3d t{m.m[0][3], m.m[1][3], m.m[2][3]};
    joint.rigid = {q, Quat{0.0, t} * q * 0.5};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            double s = 0.0;
            for (int k = 0; k < 3; ++k) s += rotation.m[k][i] * m.m[k][j];
            joint.rest.m[i][j] = s;
            if (std::abs(s - (i == j ? 1.0 : 0.0)) > 1e-6) joint.restIsIdentity = false;
        }
    return joint;
}

// The influences of point `p`: `visit(joint, weight)` for each.
template <typename Visit>
void forEachInfluence(const JointInfluences& influences, std::size_t p, Visit&& visit) {
    const std::size_t first = influences.constant ? 0 : p * static_cast<std::size_t>(influences.perPoint);
    for (int k = 0; k < influences.perPoint; ++k) {
        const double w = influences.weights[first + static_cast<std::size_t>(k)];
        if (w != 0.0) visit(static_cast<std::size_t>(influences.indices[first + static_cast<std::size_t>(k)]), w);
    }
}

// The joint of point `p` with the largest weight (the first of equals), or -1 without influences.
int pivotJoint(const JointInfluences& influences, std::size_t p) {
    int pivot = -1;
    double best = 0.0;
    const std::size_t first = influences.constant ? 0 : p * static_cast<std::size_t>(influences.perPoint);
    for (int k = 0; k < influences.perPoint; ++k) {
        const double w = influences.weights[first + static_cast<std::size_t>(k)];
        if (pivot < 0 || w > best) {
            best = w;
            pivot = influences.indices[first + static_cast<std::size_t>(k)];
        }
    }
    return pivot;
}

// The blended rigid transform of point `p`, normalised.
DualQuat blendedRigid(const std::vector<FactoredJoint>& joints, const JointInfluences& influences, std::size_t p) {
    const int pivot = pivotJoint(influences, p);
    const Quat pivotRotation = pivot >= 0 ? joints[static_cast<std::size_t>(pivot)].rigid.real : Quat{};
    DualQuat sum{{0.0, {0.0, 0.0, 0.0}}, {0.0, {0.0, 0.0, 0.0}}};
    forEachInfluence(influences, p, [&](std::size_t j, double w) {
        const DualQuat& rigid = joints[j].rigid;
        sum = sum + rigid * (dot(rigid.real, pivotRotation) < 0.0 ? -w : w);
    });
    return sum.normalized();
}

std::vector<FactoredJoint> factorAll(const std::vector<Matrix4>& skinning, bool& anyRest) {
    std::vector<FactoredJoint> joints;
    joints.reserve(skinning.size());
    anyRest = false;
    for (const Matrix4& m : skinning) {
        joints.push_back(factor(m));
        anyRest = anyRest || !joints.back().restIsIdentity;
    }
    return joints;
}

}  // namespace

std::optional<std::string> JointInfluences::problem(std::size_t pointCount, std::size_t jointCount) const {
    if (perPoint < 1) return "the joint influences' elementSize is " + std::to_string(perPoint) + ", not 1 or more";
    if (indices.size() != weights.size())
        return "primvars:skel:jointIndices has " + std::to_string(indices.size()) +
               " values but primvars:skel:jointWeights has " + std::to_string(weights.size());
    const std::size_t need = static_cast<std::size_t>(perPoint) * (constant ? 1 : pointCount);
    if (indices.size() != need)
        return "the joint influences have " + std::to_string(indices.size()) + " values but " +
               (constant ? std::string("constant") : "vertex") + " interpolation with elementSize " +
               std::to_string(perPoint) + " over " + std::to_string(pointCount) + " points needs " +
               std::to_string(need);
    for (std::size_t i = 0; i < indices.size(); ++i)
        if (indices[i] < 0 || static_cast<std::size_t>(indices[i]) >= jointCount)
            return "primvars:skel:jointIndices[" + std::to_string(i) + "] = " + std::to_string(indices[i]) +
                   " is out of range (" + std::to_string(jointCount) + " joints)";
    return std::nullopt;
}

void skinPoints(SkinningMethod method, const Matrix4& geomBind, const std::vector<Matrix4>& skinning,
                const JointInfluences& influences, std::vector<Vec3d>& points) {
    if (method == SkinningMethod::ClassicLinear) {
        for (std::size_t p = 0; p < points.size(); ++p) {
            const Vec3d bound = geomBind.transformPoint(points[p]);
            Vec3d sum{0.0, 0.0, 0.0};
            forEachInfluence(influences, p,
                             [&](std::size_t j, double w) { sum += skinning[j].transformPoint(bound) * w; });
            points[p] = sum;
        }
        return;
    }
    bool anyRest = false;
    const std::vector<FactoredJoint> joints = factorAll(skinning, anyRest);
    for (std::size_t p = 0; p < points.size(); ++p) {
        Vec3d bound = geomBind.transformPoint(points[p]);
        if (anyRest) {
            Vec3d scaled{0.0, 0.0, 0.0};
            forEachInfluence(influences, p,
                             [&](std::size_t j, double w) { scaled += joints[j].rest.transformVector(bound) * w; });
            bound = scaled;
        }
        points[p] = blendedRigid(joints, influences, p).transformPoint(bound);
    }
}

void skinNormals(SkinningMethod method, const Matrix4& geomBind, const std::vector<Matrix4>& skinning,
                 const JointInfluences& influences, const std::vector<std::size_t>& pointOf,
                 std::vector<Vec3d>& normals) {
    if (method == SkinningMethod::ClassicLinear) {
        for (std::size_t i = 0; i < normals.size(); ++i) {
            const Vec3d bound = geomBind.transformNormal(normals[i]);
            Vec3d sum{0.0, 0.0, 0.0};
            forEachInfluence(influences, pointOf[i],
                             [&](std::size_t j, double w) { sum += skinning[j].transformNormal(bound) * w; });
            normals[i] = sum;
        }
        return;
    }
    bool anyRest = false;
    const std::vector<FactoredJoint> joints = factorAll(skinning, anyRest);
    for (std::size_t i = 0; i < normals.size(); ++i) {
        Vec3d bound = geomBind.transformNormal(normals[i]);
        if (anyRest) {
            Vec3d scaled{0.0, 0.0, 0.0};
            forEachInfluence(influences, pointOf[i],
                             [&](std::size_t j, double w) { scaled += joints[j].rest.transformNormal(bound) * w; });
            bound = scaled;
        }
        normals[i] = blendedRigid(joints, influences, pointOf[i]).real.rotate(bound);
    }
}

}  // namespace fluence::delegate
