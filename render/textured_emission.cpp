#include "render/textured_emission.h"

#include <algorithm>

namespace fluence::render {

bool mayEmit(const MaterialDesc& material) {
    return !isBlack(material.emission) ||
           std::any_of(material.bindings.begin(), material.bindings.end(),
                       [](const InputBinding& b) { return b.input == MaterialInput::Emission; });
}

TexturedEmission::TexturedEmission(const MaterialShader& shader, const std::vector<Vec3f>& positions,
                                   const std::vector<std::uint32_t>& indices, const CornerPrimvar* const* primvars,
                                   const std::optional<Camera>& filterCamera)
    : shader_(shader),
      positions_(positions.data()),
      indices_(indices.data()),
      primvars_(primvars),
      filterCamera_(filterCamera),
      subdivisions_(indices.size() / 3 > kFinePowerTriangles ? 2 : kPowerSubdivisions) {}

RGB TexturedEmission::at(unsigned triangle, float b1, float b2) const {
    const std::size_t c = 3 * std::size_t(triangle);
    const Vec3f &p0 = positions_[indices_[c]], &p1 = positions_[indices_[c + 1]], &p2 = positions_[indices_[c + 2]];
    const float b0 = 1.0f - b1 - b2;
    ShadingPatch patch{c, b0, b1, b2, p1 - p0, p2 - p0, {}};
    if (filterCamera_) {
        const Vec3f point = p0 * b0 + p1 * b1 + p2 * b2, ng = cross(patch.e1, patch.e2);
        patch.footprint = pixelFootprint(point, lengthSquared(ng) > 0.0f ? normalize(ng) : Vec3f(0, 0, 1),
                                         filterCamera_->position(), filterCamera_->pixelsPerUnitAt(point));
    }
    return shader_.emission(patch, primvars_);
}

RGB TexturedEmission::mean(unsigned triangle) const {
    const std::size_t c = 3 * std::size_t(triangle);
    const Vec3f& p0 = positions_[indices_[c]];
    const float n = static_cast<float>(subdivisions_);
    ShadingPatch patch{c, 0.0f, 0.0f, 0.0f, positions_[indices_[c + 1]] - p0, positions_[indices_[c + 2]] - p0, {}};
    // Half a sub-triangle's edges: the filter around each centroid then covers its sub-triangle
    // without reaching far into the neighbours'.
    patch.footprint = {patch.e1 / (2.0f * n), patch.e2 / (2.0f * n), true};
    RGB sum(0.0f);
    auto addCentroid = [&](float b1, float b2) {
        patch.b1 = b1 / n;
        patch.b2 = b2 / n;
        patch.b0 = 1.0f - patch.b1 - patch.b2;
        sum += shader_.emission(patch, primvars_);
    };
    for (int i = 0; i < subdivisions_; ++i)
        for (int j = 0; i + j < subdivisions_; ++j) {
            addCentroid(float(i) + 1.0f / 3.0f, float(j) + 1.0f / 3.0f);  // the sub-triangle with corner (i, j)
            if (i + j + 1 < subdivisions_)
                addCentroid(float(i) + 2.0f / 3.0f, float(j) + 2.0f / 3.0f);  // the one pointing the other way
        }
    return sum / (n * n);
}

}  // namespace fluence::render
