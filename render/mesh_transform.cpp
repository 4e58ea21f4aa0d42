#include "render/mesh_transform.h"

#include <utility>

namespace fluence::render {

MeshDesc transformMesh(const MeshDesc& mesh, const Matrix4& transform) {
    MeshDesc out = mesh;
    for (Vec3f& p : out.positions) p = Vec3f(transform.transformPoint(Vec3d(p)));
    for (Vec3f& n : out.cornerNormals) {
        Vec3d t = transform.transformNormal(Vec3d(n));
        double len = length(t);
        n = Vec3f(len > 0.0 ? t / len : t);
    }
    if (transform.determinant3x3() < 0.0)
        for (std::size_t c = 0; c + 2 < out.indices.size(); c += 3) {
            std::swap(out.indices[c + 1], out.indices[c + 2]);
            if (!out.cornerNormals.empty()) std::swap(out.cornerNormals[c + 1], out.cornerNormals[c + 2]);
            if (!out.cornerColors.empty()) std::swap(out.cornerColors[c + 1], out.cornerColors[c + 2]);
        }
    return out;
}

}  // namespace fluence::render
