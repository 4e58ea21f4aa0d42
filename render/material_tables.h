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
#pragma once

#include <vector>

#include "render/scene_description.h"

namespace fluence::render {

void buildMaterialTables(const std::vector<MaterialDesc>& materials);

}  // namespace fluence::render
