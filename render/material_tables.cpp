#include "render/material_tables.h"

#include <cmath>

#include <oneapi/tbb/parallel_for.h>

#include "render/bsdf_arena.h"
#include "render/material_bsdf.h"

namespace fluence::render {

namespace {

// Evaluates, samples and asks the density of `bsdf` from above and below the surface.
void exercise(const Bsdf& bsdf) {
    const float s = std::sqrt(0.5f);
    const Vec3f directions[] = {{s, 0.0f, s}, {0.0f, s, -s}};
    for (const Vec3f& wo : directions) {
        for (const Vec3f& wi : directions) {
            (void)bsdf.f(wo, wi);
            (void)bsdf.pdf(wo, wi);
        }
        for (float uLobe : {0.1f, 0.5f, 0.9f}) (void)bsdf.sample(wo, uLobe, Vec2f(0.3f, 0.6f));
    }
}

}  // namespace

MaterialBsdfs buildMaterialTables(const std::vector<MaterialDesc>& materials) {
    MaterialBsdfs made;
    made.arenas_.resize(materials.size());
    made.bsdfs_.resize(materials.size());
    tbb::parallel_for(std::size_t(0), materials.size(), [&](std::size_t i) {
        const MaterialParams& m = materials[i];
        made.arenas_[i] = std::make_unique<BsdfArena>();
        made.bsdfs_[i] = &materialBsdf(m, *made.arenas_[i]);
        exercise(*made.bsdfs_[i]);
        if (!(m.subsurface > 0.0f)) return;
        BsdfArena arena;
        exercise(subsurfaceExitBsdf(m, arena));
    });
    return made;
}

}  // namespace fluence::render
