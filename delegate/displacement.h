// Displacement: UsdPreviewSurface `inputs:displacement` applied to the geometry as it is diced.
//
// The specification's displacement is a scalar distance along the surface normal, in object-space
// units. It is geometry, not shading: the delegate moves the vertices of a diced mesh (a
// subdivision surface's limit tessellation, delegate/subdivision_mesh.h, or a polygon mesh cut
// finer for the camera, delegate/polygon_dicing.h) and the render core receives ordinary
// triangles, whose bounds Embree computes itself (no procedural bounds, nothing to pad).
//
// The value is a constant, or a node that drives it (MaterialDesc::displacementBinding): a
// UsdUVTexture's channel (texel * scale + bias), a primvar reader, a MaterialX graph over them. The
// node is evaluated through the render core's own shading network (render/material_shader.h) and
// texture system (texture/), at each vertex with its triangle corner's primvars (st), point-sampled
// at the finest mip level. A texture that cannot be read gives its fallback (0 unless authored):
// with --allow-missing a missing displacement map displaces nothing.
//
// After the move the shading normals are the displaced surface's own: per vertex, the
// area-weighted normal of the triangles meeting at its position (welded by exact position, so the
// separately diced pieces of a polygon mesh shade smoothly across their shared edges). The
// geometric normals are the triangles' own, so the two agree up to the smoothing. Sharp creases
// of a displaced subdivision surface are smoothed by this.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "render/material_shader.h"
#include "render/scene_description.h"
#include "texture/texture_system.h"

namespace fluence::delegate {

class MaterialDisplacement {
public:
    // Whether `material` moves anything: a non-zero constant, or a node driving it.
    static bool displaces(const render::MaterialDesc& material);

    // `textures` may be null: a textured displacement then takes its texture's fallback. What goes
    // wrong opening a texture is appended to `warnings`.
    MaterialDisplacement(const render::MaterialDesc& material, texture::TextureSystem* textures,
                         std::vector<render::Warning>& warnings);
    MaterialDisplacement(const MaterialDisplacement&) = delete;
    MaterialDisplacement& operator=(const MaterialDisplacement&) = delete;

    // Writes into amounts[v] the displacement (object units) of each vertex v of `mesh` for which
    // `where(v)` holds, read at the first triangle corner that uses the vertex. `amounts` has one
    // entry per vertex.
    void atVertices(const render::MeshDesc& mesh, const std::function<bool(std::size_t)>& where,
                    std::vector<float>& amounts) const;

private:
    render::MaterialDesc material_;  // the constant and the displacement binding alone
    render::MaterialShader shader_;
};

// The displacements of the materials a scene description dices with, each built once.
class MaterialDisplacements {
public:
    using Warn = std::function<void(const std::string& path, const std::string& message)>;
    MaterialDisplacements(texture::TextureSystem* textures, Warn warn) : textures_(textures), warn_(std::move(warn)) {}
    // Null when `material` displaces nothing.
    const MaterialDisplacement* of(const render::MaterialDesc& material);

private:
    texture::TextureSystem* textures_;
    Warn warn_;
    std::map<std::string, std::unique_ptr<MaterialDisplacement>> built_;  // by material path
};

// Moves every vertex of `mesh` along its unit normal `normals[v]` by `amounts[v]`, then replaces
// the shading normals with the displaced surface's (recomputeShadingNormals).
void displaceAlongNormals(render::MeshDesc& mesh, const std::vector<Vec3f>& normals, const std::vector<float>& amounts);

// Sets `mesh.cornerNormals` to the smooth normals of the surface as it now stands: per corner, the
// normalised sum of the (area-weighted) normals of the triangles with a corner at the same position.
void recomputeShadingNormals(render::MeshDesc& mesh);

}  // namespace fluence::delegate
