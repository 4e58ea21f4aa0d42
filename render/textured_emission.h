// The emission of a mesh whose material's emission a texture, a primvar reader or a shading graph
// drives (MaterialShader::drives(MaterialInput::Emission)): one function of the point on a
// triangle, which both camera and BSDF rays that hit the mesh (RenderScene::shadeMesh) and
// next-event estimation and light subpaths (render/lights/triangle_light.h) evaluate, so that
// every strategy of multiple importance sampling sees the same radiance at the same point.
//
// The texture is filtered as at any other hit: by the pixel footprint of the camera given to
// RenderScene::setTextureFilterCamera (point-sampled at the finest level without one), the
// footprint computed from the point itself, whichever ray reached it.
//
// Each triangle's mean radiance sets its power, for power-proportional light selection and the
// light tree, so that a dark part of a textured screen is chosen less often than a bright one:
// the triangle is cut into n x n congruent sub-triangles (n = kPowerSubdivisions, 2 for meshes of
// more than kFinePowerTriangles triangles), and each is looked up once at its centroid with a
// footprint of half its edges, so the texture's mip level that covers the sub-triangle gives its
// mean without reaching far into its neighbours. Within a triangle, points are still sampled
// uniformly by area.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "core/rgb.h"
#include "render/camera.h"
#include "render/material_shader.h"

namespace fluence::render {

// Whether a material may emit: a constant emission that is not black, or a binding driving it.
bool mayEmit(const MaterialDesc& material);

class TexturedEmission {
public:
    static constexpr int kPowerSubdivisions = 4;
    static constexpr std::size_t kFinePowerTriangles = 4096;

    // The mesh's world-space triangles (`indices` into `positions`), its material's shader and the
    // primvar of each of the shader's slots (MaterialShader::primvarSlots); `filterCamera` is read
    // at each evaluation. The vectors' buffers (not the vectors themselves: a mesh may be moved
    // with them) and the rest are kept by reference and must outlive this object.
    TexturedEmission(const MaterialShader& shader, const std::vector<Vec3f>& positions,
                     const std::vector<std::uint32_t>& indices, const CornerPrimvar* const* primvars,
                     const std::optional<Camera>& filterCamera);

    // The radiance emitted (from both sides) at the point of triangle `triangle` with barycentric
    // weights b1, b2 of its second and third corners.
    RGB at(unsigned triangle, float b1, float b2) const;
    // The mean radiance over the triangle (see above).
    RGB mean(unsigned triangle) const;

private:
    const MaterialShader& shader_;
    const Vec3f* positions_;
    const std::uint32_t* indices_;
    const CornerPrimvar* const* primvars_;
    const std::optional<Camera>& filterCamera_;
    int subdivisions_;
};

}  // namespace fluence::render
