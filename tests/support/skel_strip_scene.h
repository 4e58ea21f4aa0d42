// A skinned strip and its hand-posed twin, for the end-to-end UsdSkel tests (tests/apps): a strip
// of 2 quads along x from -1 to 1, the left column bound to joint J, the middle half to J and half
// to J/K, the right column to K; K (bound at x = 0) turns about z by 0° at code 1 and 50° at code 2
// while J moves. The twin's points are posed by hand from the joint transforms, J =
// T(jTranslate), K = J · T(1, 0, 0) · Rz (K's bind transform is the identity, so its skinning
// transform is K itself), keyed at the same codes.
#pragma once

#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

#include "core/matrix.h"

namespace fluence::test::skel_strip {

struct Pose {
    double kDegrees;
    Vec3d jTranslate;
};
constexpr Pose kPoses[] = {{0.0, {0.25, 0.0, 0.0}}, {50.0, {-0.25, 0.5, 0.0}}};
constexpr double kWeightJ[] = {1.0, 0.5, 0.0};

inline const std::string kTopology = R"(
        uniform token subdivisionScheme = "none"
        int[] faceVertexCounts = [4, 4]
        int[] faceVertexIndices = [0, 1, 4, 3, 1, 2, 5, 4]
)";

// A stage keyed at codes 1 and 2, a Camera on +z at `distance` looking down -z (`cameraLines`
// added to it) and a DistantLight.
inline std::string stripStage(const std::string& cameraLines, double distance) {
    return R"(#usda 1.0
(
    startTimeCode = 1
    endTimeCode = 2
)
def Camera "Cam"
{
)" + cameraLines +
           "    double3 xformOp:translate = (0, 0, " + std::to_string(distance) + R"()
    uniform token[] xformOpOrder = ["xformOp:translate"]
}
def DistantLight "Sun"
{
    float inputs:intensity = 2
}
)";
}

inline std::string number(double v) {
    std::ostringstream s;
    s.precision(17);
    s << v;
    return s.str();
}

inline std::string vec(const Vec3d& v) { return "(" + number(v.x) + ", " + number(v.y) + ", " + number(v.z) + ")"; }

inline Vec3d restPoint(int i) { return {static_cast<double>(i % 3) - 1.0, i < 3 ? -0.5 : 0.5, 0.0}; }

// The SkelRoot at the root prim `name` (`specifier`: def, or class for a prototype that instances
// reference), holding the skeleton, its animation and the skinned Mesh "Strip".
inline std::string skinnedRoot(const std::string& specifier, const std::string& name) {
    std::string points, indices, weights;
    for (int i = 0; i < 6; ++i) {
        points += vec(restPoint(i)) + ", ";
        indices += "0, 1, ";
        weights += number(kWeightJ[i % 3]) + ", " + number(1.0 - kWeightJ[i % 3]) + ", ";
    }
    std::string translations, rotations;
    for (int f = 0; f < 2; ++f) {
        const double half = kPoses[f].kDegrees * std::numbers::pi / 360.0;
        translations += std::to_string(f + 1) + ": [" + vec(kPoses[f].jTranslate) + ", (1, 0, 0)], ";
        rotations += std::to_string(f + 1) + ": [(1, 0, 0, 0), (" + number(std::cos(half)) + ", 0, 0, " +
                     number(std::sin(half)) + ")], ";
    }
    return specifier + " SkelRoot \"" + name + R"("
{
    def Skeleton "Skel"
    {
        uniform token[] joints = ["J", "J/K"]
        uniform matrix4d[] bindTransforms = [((1,0,0,0),(0,1,0,0),(0,0,1,0),(0,0,0,1)), ((1,0,0,0),(0,1,0,0),(0,0,1,0),(0,0,0,1))]
        uniform matrix4d[] restTransforms = [((1,0,0,0),(0,1,0,0),(0,0,1,0),(0,0,0,1)), ((1,0,0,0),(0,1,0,0),(0,0,1,0),(0,0,0,1))]
        rel skel:animationSource = </)" +
           name + R"(/Skel/Anim>
        def SkelAnimation "Anim"
        {
            uniform token[] joints = ["J", "J/K"]
            float3[] translations.timeSamples = {)" +
           translations + R"(}
            quatf[] rotations.timeSamples = {)" +
           rotations + R"(}
            half3[] scales = [(1, 1, 1), (1, 1, 1)]
        }
    }
    def Mesh "Strip" (prepend apiSchemas = ["SkelBindingAPI"])
    {)" + kTopology +
           R"(
        point3f[] points = [)" +
           points + R"(]
        int[] primvars:skel:jointIndices = [)" +
           indices + R"(] (
            interpolation = "vertex"
            elementSize = 2
        )
        float[] primvars:skel:jointWeights = [)" +
           weights + R"(] (
            interpolation = "vertex"
            elementSize = 2
        )
        rel skel:skeleton = </)" +
           name + R"(/Skel>
    }
}
)";
}

// The twin: a plain Mesh "Strip" whose points are the strip's, posed by hand, keyed at codes 1 and 2.
inline std::string posedStrip() {
    std::string samples;
    for (int f = 0; f < 2; ++f) {
        const Matrix4 j = Matrix4::translate(kPoses[f].jTranslate);
        const Matrix4 k = j * Matrix4::translate({1, 0, 0}) * Matrix4::rotateZ(kPoses[f].kDegrees);
        samples += std::to_string(f + 1) + ": [";
        for (int i = 0; i < 6; ++i) {
            const double w = kWeightJ[i % 3];
            samples += vec(j.transformPoint(restPoint(i)) * w + k.transformPoint(restPoint(i)) * (1.0 - w)) + ", ";
        }
        samples += "], ";
    }
    return R"(
def Mesh "Strip"
{)" + kTopology +
           R"(
    point3f[] points.timeSamples = {)" +
           samples + R"(}
}
)";
}

}  // namespace fluence::test::skel_strip
