#include "render/bsdfs/ggx_albedo.h"

#include <cmath>

#include "render/bsdfs/albedo_table.h"
#include "render/bsdfs/fresnel.h"
#include "render/bsdfs/local_geometry.h"

namespace fluence::render {

namespace {

// E at (mu, alpha) for the reflectance f0, wo in the xz plane.
float quadratureAlbedo(const GgxDistribution& ggx, float mu, float f0) {
    return ggxReflectionQuadrature(ggx, Vec3f(std::sqrt(std::max(0.0f, 1.0f - mu * mu)), 0.0f, mu), f0);
}

using ReflectionTable = AlbedoTable<quadratureAlbedo>;

}  // namespace

float ggxFacetReflectance(float cosTheta, float f0) {
    if (f0 >= 1.0f) return 1.0f;
    if (f0 <= 0.0f) return 0.0f;
    return fresnelDielectric(cosTheta, etaFromF0(f0));
}

// f cos / pdf of the reflection off each visible normal of wo, averaged.
float ggxReflectionQuadrature(const GgxDistribution& ggx, const Vec3f& wo, float f0) {
    return visibleNormalQuadrature(ggx, wo, [&](const Vec3f& h) {
        const Vec3f wi = reflect(wo, h);
        if (wi.z <= 0.0f) return 0.0;
        const float pdf = ggx.reflectionPdf(wo, h);
        if (!(pdf > 0.0f)) return 0.0;
        return double(ggxFacetReflectance(dot(wo, h), f0)) * ggx.reflectionTerm(wo, wi, h) * wi.z / pdf;
    });
}

float ggxReflectionAlbedo(float cosTheta, float alpha, float f0) {
    return ReflectionTable::albedo(cosTheta, alpha, f0);
}

float ggxReflectionAverageAlbedo(float alpha, float f0) { return ReflectionTable::average(alpha, f0); }

}  // namespace fluence::render
