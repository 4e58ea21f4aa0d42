#include "render/bsdfs/thin_dielectric_albedo.h"

#include <cmath>

#include "render/bsdfs/albedo_table.h"
#include "render/bsdfs/fresnel.h"
#include "render/bsdfs/local_geometry.h"

namespace fluence::render {

namespace {

float tableAlbedo(const GgxDistribution& ggx, float mu, float f0) {
    return thinSheetQuadrature(ggx, mu, etaFromF0(f0));
}

using SheetTable = AlbedoTable<tableAlbedo>;

}  // namespace

float thinSheetQuadrature(const GgxDistribution& ggx, float mu, float eta) {
    return facetQuadrature(ggx, mu, [&](const Vec3f& wo, const Vec3f& h, float cosO, float g1) {
        const float F = fresnelDielectric(cosO, eta), slab = 2.0f * F / (1.0f + F);
        double weight = 1.0 - slab;  // straight through: never masked
        if (const Vec3f r = reflect(wo, h); r.z > 0.0f) weight += double(slab) * ggx.G2(wo, r) / g1;
        return weight;
    });
}

float thinSheetAlbedo(float cosTheta, float alpha, float eta) {
    return SheetTable::albedo(cosTheta, alpha, f0FromEta(eta));
}

float thinSheetAverageAlbedo(float alpha, float eta) { return SheetTable::average(alpha, f0FromEta(eta)); }

}  // namespace fluence::render
