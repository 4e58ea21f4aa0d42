#include "render/mesh_transform.h"

#include <cmath>
#include <utility>

namespace fluence::render {

MeshDesc transformMesh(const MeshDesc& mesh, const Matrix4& transform) {
    MeshDesc out = mesh;
    if (out.light) out.light->lightToWorld = transform * out.light->lightToWorld;
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

float surfaceArea(const MeshDesc& mesh) {
    float area = 0.0f;
    for (std::size_t c = 0; c + 2 < mesh.indices.size(); c += 3) {
        const Vec3f& p0 = mesh.positions[mesh.indices[c]];
        area +=
            0.5f * length(cross(mesh.positions[mesh.indices[c + 1]] - p0, mesh.positions[mesh.indices[c + 2]] - p0));
    }
    return area;
}

void transformPrimitives(std::vector<Vec3f>& points, std::vector<float>& radii, std::vector<Vec3f>& normals,
                         const Matrix4& transform) {
    const auto scale = static_cast<float>(std::cbrt(std::abs(transform.determinant3x3())));
    for (Vec3f& p : points) p = Vec3f(transform.transformPoint(Vec3d(p)));
    for (float& r : radii) r *= scale;
    for (Vec3f& n : normals) {
        const Vec3d world = transform.transformNormal(Vec3d(n));
        n = length(world) > 0.0 ? Vec3f(world / length(world)) : n;
    }
}

}  // namespace fluence::render
