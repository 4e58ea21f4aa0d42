// A one-joint skinned agent as a class prim, for the delegate tests of skinned prims inside
// instances and prototypes.
#pragma once

#include <string>

namespace fluence::delegate::testing {

// A one-joint agent: a unit quad in z = 0 rigidly bound to joint Root (bind and rest identity).
// `skeletonLines` adds to its Skeleton.
inline std::string agentClass(const std::string& skeletonLines = "", const std::string& insideLines = "") {
    return R"(
class SkelRoot "Agent"
{
    def Skeleton "Skel"
    {
        uniform token[] joints = ["Root"]
        uniform matrix4d[] bindTransforms = [((1,0,0,0),(0,1,0,0),(0,0,1,0),(0,0,0,1))]
        uniform matrix4d[] restTransforms = [((1,0,0,0),(0,1,0,0),(0,0,1,0),(0,0,0,1))]
)" + skeletonLines +
           R"(
    }
    def Mesh "Quad" (prepend apiSchemas = ["SkelBindingAPI"])
    {
        uniform token subdivisionScheme = "none"
        int[] faceVertexCounts = [4]
        int[] faceVertexIndices = [0, 1, 2, 3]
        point3f[] points = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]
        int[] primvars:skel:jointIndices = [0] (interpolation = "constant"; elementSize = 1)
        float[] primvars:skel:jointWeights = [1] (interpolation = "constant"; elementSize = 1)
        rel skel:skeleton = </Agent/Skel>
    }
)" + insideLines +
           R"(
}
)";
}

}  // namespace fluence::delegate::testing
