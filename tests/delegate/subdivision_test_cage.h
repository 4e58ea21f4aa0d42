// Shared by the subdivision tests: the topology of a cube cage (8 points, 6 quads wound outwards
// for points ordered (-,-,-), (+,-,-), (+,+,-), (-,+,-), then the same at +z).
#pragma once

#include "delegate/subdivision.h"

namespace fluence::delegate::testing {

inline SubdivisionTopology cubeTopology() {
    SubdivisionTopology t;
    t.pointCount = 8;
    t.faceVertexCounts = {4, 4, 4, 4, 4, 4};
    t.faceVertexIndices = {0, 3, 2, 1, 4, 5, 6, 7, 0, 1, 5, 4, 1, 2, 6, 5, 2, 3, 7, 6, 3, 0, 4, 7};
    return t;
}

}  // namespace fluence::delegate::testing
