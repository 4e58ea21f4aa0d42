// OpenVDB grids made in the volumes tests: a float or vec3s grid with a voxel size and a translation
// (a non-trivial index-to-object transform), the object-to-world placement the tests share, and
// writing grids to a file.
#pragma once

#include <openvdb/openvdb.h>

#include <string>

#include "core/matrix.h"

namespace fluence::test {

template <typename GridT>
typename GridT::Ptr makeGrid(const std::string& name, double voxelSize, const openvdb::Vec3d& translation,
                             typename GridT::ValueType background = typename GridT::ValueType(0)) {
    openvdb::initialize();
    typename GridT::Ptr grid = GridT::create(background);
    grid->setName(name);
    openvdb::math::Transform::Ptr transform = openvdb::math::Transform::createLinearTransform(voxelSize);
    transform->postTranslate(translation);
    grid->setTransform(transform);
    return grid;
}

// A rotated, anisotropically scaled and translated prim transform.
inline Matrix4 tiltedObjectToWorld() {
    return Matrix4::translate({-2.0, 0.5, 4.0}) * Matrix4::rotateY(30.0) * Matrix4::rotateX(-20.0) *
           Matrix4::scale({2.0, 1.5, 0.75});
}

inline void writeGrids(const std::string& path, const openvdb::GridPtrVec& grids) {
    openvdb::io::File file(path);
    file.write(grids);
    file.close();
}

}  // namespace fluence::test
