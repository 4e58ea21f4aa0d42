#include "render/bsdfs/ggx_dielectric_albedo.h"

#include <cmath>

#include "render/bsdfs/albedo_table.h"
#include "render/bsdfs/fresnel.h"
#include "render/bsdfs/local_geometry.h"

namespace fluence::render {

namespace {

// Beyond this f0 (an index above 1e4) the interface is a mirror: F = 1 on both sides.
constexpr float kMirrorF0 = 0.9996f;

// E at (mu, alpha) from the side whose relative index is `eta`.
float interfaceAlbedo(const GgxDistribution& ggx, float mu, float eta) {
    return facetQuadrature(ggx, mu, [&](const Vec3f& wo, const Vec3f& h, float cosO, float g1) {
        const float F = eta > 0.0f ? fresnelDielectric(cosO, eta) : 1.0f;
        double weight = 0.0;
        if (const Vec3f r = reflect(wo, h); r.z > 0.0f) weight += double(F) * ggx.G2(wo, r) / g1;
        if (F < 1.0f)
            if (const std::optional<Vec3f> t = refract(wo, h, eta); t && t->z < 0.0f)
                weight += double(1.0f - F) * ggx.G2(wo, *t) / g1;
        return weight;
    });
}

float enteringAlbedo(const GgxDistribution& ggx, float mu, float f0) {
    return interfaceAlbedo(ggx, mu, f0 < kMirrorF0 ? etaFromF0(f0) : 0.0f);
}
float leavingAlbedo(const GgxDistribution& ggx, float mu, float f0) {
    return interfaceAlbedo(ggx, mu, f0 < kMirrorF0 ? 1.0f / etaFromF0(f0) : 0.0f);
}

using EnteringTable = AlbedoTable<enteringAlbedo>;
using LeavingTable = AlbedoTable<leavingAlbedo>;

}  // namespace

float ggxDielectricAlbedo(float cosTheta, float alpha, float eta) {
    return eta >= 1.0f ? EnteringTable::albedo(cosTheta, alpha, f0FromEta(eta))
                       : LeavingTable::albedo(cosTheta, alpha, f0FromEta(eta));
}

float ggxDielectricAverageAlbedo(float alpha, float eta) {
    return eta >= 1.0f ? EnteringTable::average(alpha, f0FromEta(eta)) : LeavingTable::average(alpha, f0FromEta(eta));
}

}  // namespace fluence::render
