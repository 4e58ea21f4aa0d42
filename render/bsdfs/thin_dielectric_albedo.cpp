#include "render/bsdfs/thin_dielectric_albedo.h"

#include <cmath>

#include "render/bsdfs/albedo_table.h"
#include "render/bsdfs/fresnel.h"
#include "render/bsdfs/local_geometry.h"
#include "render/bsdfs/thin_dielectric.h"

namespace fluence::render {

namespace {

float tableAlbedo(const GgxDistribution& ggx, float mu, float f0) {
    return thinSheetQuadrature(ggx, mu, etaFromF0(f0));
}

float tableStraightThrough(const GgxDistribution& ggx, float mu, float f0) {
    const float eta = etaFromF0(f0);
    return facetQuadrature(ggx, mu, [&](const Vec3f&, const Vec3f&, float cosO, float) {
        return 1.0 - double(slabReflectance(cosO, eta));
    });
}

using SheetTable = AlbedoTable<tableAlbedo>;
using StraightThroughTable = AlbedoTable<tableStraightThrough>;

}  // namespace

float thinSheetQuadrature(const GgxDistribution& ggx, float mu, float eta) {
    return facetQuadrature(ggx, mu, [&](const Vec3f& wo, const Vec3f& h, float cosO, float g1) {
        const double slab = slabReflectance(cosO, eta);
        double weight = 1.0 - slab;  // straight through: never masked
        if (const Vec3f r = reflect(wo, h); r.z > 0.0f) weight += slab * ggx.G2(wo, r) / g1;
        return weight;
    });
}

float thinSheetAlbedo(float cosTheta, float alpha, float eta) {
    return SheetTable::albedo(cosTheta, alpha, f0FromEta(eta));
}

float thinSheetAverageAlbedo(float alpha, float eta) { return SheetTable::average(alpha, f0FromEta(eta)); }

float thinSheetStraightThrough(float cosTheta, float alpha, float eta) {
    return StraightThroughTable::albedo(cosTheta, alpha, f0FromEta(eta));
}

}  // namespace fluence::render
