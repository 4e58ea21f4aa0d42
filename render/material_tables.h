// The tables the materials' BSDFs build on first use (the GGX albedo slices of
// render/bsdfs/albedo_table.h, the redistribution and sheen tables), built when the scene is:
// before the render's clock starts (integrators/renderer.cpp plans time-budgeted passes from the
// time of the first), and not inside the first pass.
//
// Each material's BSDF (and, with subsurface, the exit BSDF of render/material_bsdf.h) is made at
// its authored parameters and evaluated, sampled and asked densities from both sides, which
// builds every table those parameters read; the materials are taken in parallel. The tables are
// pure functions of their parameters, built once whichever thread asks first, so building them
// earlier changes no value. Parameters that textures drive build theirs on first use, as before.
//
// The BSDF made at the authored parameters is kept (MaterialBsdfs): a hit whose parameters are
// those (RenderScene::shadeMesh: no texture and no vertex colour drives them) carries it, and the
// path tracer shades it with that BSDF instead of making its own (materialBsdf). materialBsdf is a
// pure function of the parameters, so the kept BSDF is the one the hit would have made, value for
// value; a made BSDF is immutable (const methods, no state of their own), so every thread of the
// render shares it. The skin of the Cycles subsurface peer made its layered BSDF (the specular
// layer's albedo tables and remembered passes) at every hit, 4% of the render's CPU in perf.
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include "render/bsdf_arena.h"
#include "render/scene_description.h"

namespace fluence::render {

class Bsdf;

// Each material's BSDF at its authored parameters, made once (buildMaterialTables).
class MaterialBsdfs {
public:
    const Bsdf& operator[](std::size_t material) const { return *bsdfs_[material]; }

private:
    friend MaterialBsdfs buildMaterialTables(const std::vector<MaterialDesc>& materials);
    std::vector<std::unique_ptr<BsdfArena>> arenas_;  // each material's BSDF lives in its own
    std::vector<const Bsdf*> bsdfs_;
};

// Builds the tables of every material's parameters and returns the BSDFs made at them.
MaterialBsdfs buildMaterialTables(const std::vector<MaterialDesc>& materials);

}  // namespace fluence::render
