// A material's shading network evaluated at a surface point: MaterialDesc bindings (UsdUVTexture
// lookups, primvar reads, and graphs of MaterialX multiply and mix nodes over them) written over
// its constant parameters.
//
// Built once per material when the RenderScene is built: each texture is opened in the
// texture::TextureSystem (a file that cannot be read is reported once in `warnings` and its
// binding uses the texture's fallback value). Per hit, evaluate() interpolates each binding's
// primvar on the hit triangle, applies the UsdTransform2d, looks the texture up with the pixel
// footprint mapped into st (render/surface_differentials.h), applies scale and bias, and writes
// the channels into the parameter; a binding's graph (render::ShadingNode) is evaluated node by
// node over its sources' values, on the stack. A material without graphs pays nothing for them.
// A Normal binding perturbs the shading normal in the tangent
// frame of its st (tangent along dp/ds, bitangent along dp/dt, Gram-Schmidt against the
// interpolated normal).
//
// Primvars are looked up by name once per mesh: primvarSlots() lists the names, one per source
// (a binding without a graph is its own source; a graph's sources follow each other), in binding
// order, and a mesh hands evaluate() the matching CornerPrimvar pointers (nullptr where it lacks
// one: the source's fallback st or value is used).
#pragma once

#include <string>
#include <vector>

#include "render/scene_description.h"
#include "render/surface_differentials.h"
#include "texture/texture_system.h"

namespace fluence::render {

// Something that went wrong building, that did not stop it: where (a prim path) and what.
struct Warning {
    std::string where, message;
};

// A point on a triangle, with what the network needs there.
struct ShadingPatch {
    std::size_t corner = 0;                 // 3 * triangle index: the first corner's index in CornerPrimvar values
    float b0 = 1.0f, b1 = 0.0f, b2 = 0.0f;  // barycentric weights of the corners
    Vec3f e1{0.0f}, e2{0.0f};               // the triangle's edges, in the space of the footprint
    PixelFootprint footprint;               // invalid: point sampling at the finest level
    // Curves (render/curve_primvars.h): each slot's primvar already evaluated at the point, 4 floats
    // per slot (its first CornerPrimvar::components meaningful), read in place of the corners; the
    // corner, weights and edges are then unused, and there is no st parameterisation (no footprint,
    // no tangent frame).
    const float (*atPoint)[4] = nullptr;
};

// Writes a driven value (`channels` of v: one replicated into a colour) into the parameter `input`
// (Normal is not a parameter: nothing is written).
void setMaterialInput(MaterialParams& p, MaterialInput input, const float* v, int channels);

class MaterialShader {
public:
    // Throws std::invalid_argument (naming the material) for a graph whose operands are not earlier
    // nodes, whose sources are out of range or graphs themselves, or that has more than
    // kMaxShadingNodes nodes.
    MaterialShader(const MaterialDesc& material, texture::TextureSystem* textures, std::vector<Warning>& warnings);

    const MaterialDesc& material() const { return *material_; }
    bool hasBindings() const { return !material_->bindings.empty(); }
    // Whether some point of the surface may be less than fully present (opacity < 1, or a cut-out).
    bool mayBeTransparent() const;
    // The primvar each source reads (a texture's st or a primvar reader's), "" for none.
    const std::vector<std::string>& primvarSlots() const { return slots_; }
    // The primvar whose st the tangent frame follows (the first texture's), as an index into
    // primvarSlots(), or -1.
    int tangentSlot() const { return tangentSlot_; }

    // The parameters at `patch`; `primvars[i]` is the mesh's primvar for slot i (or nullptr).
    // shadingNormal (unit, in the space of patch.e1/e2) is perturbed by a Normal binding;
    // `tangent` is set to the unit dp/ds of the tangent slot's st made perpendicular to the
    // final shading normal (zero without one).
    void evaluate(const ShadingPatch& patch, const CornerPrimvar* const* primvars, MaterialParams& out,
                  Vec3f& shadingNormal, Vec3f& tangent) const;
    // The surface's presence at `patch` (1 = opaque, 0 = a hole): opacity, or with a cut-out
    // threshold 0 or 1. Point-sampled.
    float presence(const ShadingPatch& patch, const CornerPrimvar* const* primvars) const;
    // Whether a binding drives `input` per point (Emission: render/textured_emission.h).
    bool drives(MaterialInput input) const;
    // The emitted radiance at `patch`: the emission binding's value there, as evaluate() writes it
    // into MaterialParams::emission, without evaluating the other bindings.
    RGB emission(const ShadingPatch& patch, const CornerPrimvar* const* primvars) const;

private:
    // A texture lookup or primvar read: a binding without a graph, or a source of a graph.
    struct Source {
        const InputBinding* binding;
        const texture::TextureSystem::Texture* opened;  // nullptr: the fallback, or a primvar
    };
    // The binding's value (4 channels, times its factor) at the patch.
    void bindingValue(std::size_t binding, const ShadingPatch& patch, const CornerPrimvar* const* primvars,
                      float value[4]) const;
    // Source s's value (4 channels, before its factor) at the patch; `primvar` is its slot's.
    void sourceValue(std::size_t s, const ShadingPatch& patch, const CornerPrimvar* primvar, float value[4]) const;
    // The value of the last binding driving `input` at the patch (4 channels, the binding's first
    // channel first), or nullptr and `value` untouched when no binding drives it.
    const InputBinding* drivenValue(MaterialInput input, const ShadingPatch& patch,
                                    const CornerPrimvar* const* primvars, float value[4]) const;

    const MaterialDesc* material_;
    texture::TextureSystem* textures_;
    std::vector<Source> sources_;           // in slot order
    std::vector<std::size_t> firstSource_;  // per binding: its (graph's first) source
    std::vector<std::string> slots_;
    int tangentSlot_ = -1;
};

// Interpolates `components` floats of a corner primvar at the patch.
void interpolateCorners(const CornerPrimvar& primvar, const ShadingPatch& patch, float* out);

// The st parameterisation of the patch's triangle in `primvar` (a 2-component primvar).
TriangleParameterisation stParameterisation(const CornerPrimvar& primvar, const ShadingPatch& patch);

}  // namespace fluence::render
