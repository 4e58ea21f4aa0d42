#include "integrators/scene_path_classes.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "integrators/path_classes.h"
#include "render/bsdfs/ggx.h"
#include "render/lights/light_registry.h"

namespace fluence::integrators {

namespace {

using render::MaterialDesc;
using render::MaterialInput;

bool driven(const MaterialDesc& m, MaterialInput input) {
    return std::any_of(m.bindings.begin(), m.bindings.end(),
                       [&](const render::InputBinding& b) { return b.input == input; });
}

// The least and greatest values a scalar parameter takes over the surface.
struct Span {
    float lo, hi;
};
Span spanOf(const MaterialDesc& m, MaterialInput input, float value) {
    return driven(m, input) ? Span{0.0f, 1.0f} : Span{value, value};
}

bool mayBeNonBlack(const MaterialDesc& m, MaterialInput input, const RGB& value) {
    return driven(m, input) || !isBlack(value);
}

// Whether a lobe of GGX roughness `roughness` can be smooth (a delta lobe) and can be rough.
struct Smoothness {
    bool smooth, rough;
};
Smoothness smoothnessOf(Span roughness, float anisotropy) {
    return {render::GgxDistribution::fromRoughness(roughness.lo, anisotropy).isSmooth(),
            !render::GgxDistribution::fromRoughness(roughness.hi, anisotropy).isSmooth()};
}

// What light can do at a surface of material `m` (the lobes of render/material_bsdf.h).
struct SurfaceLobes {
    bool diffuseOrGlossy = false;
    bool delta = false;
    bool emits = false;
    bool subsurface = false;
    bool scatteringInterior = false;
};

SurfaceLobes lobesOf(const MaterialDesc& m) {
    const Span transmission = spanOf(m, MaterialInput::Transmission, m.transmission);
    const Span metallic = spanOf(m, MaterialInput::Metallic, m.metallic);
    const Span coat = spanOf(m, MaterialInput::Coat, m.coat);
    const bool base = transmission.lo < 1.0f && metallic.lo < 1.0f;
    const bool specularReflects = m.specularWorkflow
                                      ? mayBeNonBlack(m, MaterialInput::SpecularColor, m.specularColor)
                                      : (m.ior > 1.0f || driven(m, MaterialInput::Ior)) &&
                                            spanOf(m, MaterialInput::Specular, m.specular).hi > 0.0f &&
                                            mayBeNonBlack(m, MaterialInput::SpecularColor, m.specularColor);
    const bool glass = transmission.hi > 0.0f && metallic.lo < 1.0f;
    const bool metal = metallic.hi > 0.0f;
    const bool specularLike = (base && specularReflects) || glass || metal;
    const bool coated = coat.hi > 0.0f && m.coatIor > 1.0f;
    const Smoothness specular = smoothnessOf(spanOf(m, MaterialInput::Roughness, m.roughness), m.anisotropy);
    const Smoothness clearCoat = smoothnessOf(spanOf(m, MaterialInput::CoatRoughness, m.coatRoughness), 0.0f);

    SurfaceLobes lobes;
    lobes.diffuseOrGlossy = base || (specularLike && specular.rough) || (coated && clearCoat.rough);
    lobes.delta = (specularLike && specular.smooth) || (coated && clearCoat.smooth);
    lobes.emits = mayBeNonBlack(m, MaterialInput::Emission, m.emission);
    lobes.subsurface = m.subsurface > 0.0f;
    lobes.scatteringInterior = glass && m.interior && !isBlack(m.interior->sigmaS);
    return lobes;
}

// Whether every point of `mesh` lies in one plane (to a millionth of its size).
bool isFlat(const render::MeshDesc& mesh) {
    const auto& p = mesh.positions;
    Vec3f lo = p.empty() ? Vec3f(0.0f) : p.front(), hi = lo;
    for (const Vec3f& q : p) {
        lo = vmin(lo, q);
        hi = vmax(hi, q);
    }
    const float tolerance = 1e-6f * length(hi - lo);
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const Vec3f& a = p[mesh.indices[t]];
        const Vec3f n = cross(p[mesh.indices[t + 1]] - a, p[mesh.indices[t + 2]] - a);
        if (lengthSquared(n) == 0.0f) continue;
        const Vec3f unit = normalize(n);
        return std::all_of(p.begin(), p.end(), [&](const Vec3f& q) { return std::abs(dot(q - a, unit)) <= tolerance; });
    }
    return true;  // no triangle with an area
}

// Every surface the scene places (a prototype's mesh once per instance), with its lobes.
struct Surface {
    const render::MeshDesc* mesh;
    SurfaceLobes lobes;
};
std::vector<Surface> surfacesOf(const render::SceneDescription& scene) {
    MaterialDesc plain;  // what a mesh without a material is shaded with
    static_cast<render::MaterialParams&>(plain) = render::lambertianParams(RGB(0.18f));
    const SurfaceLobes lambertian = lobesOf(plain);
    std::vector<Surface> surfaces;
    auto place = [&](const render::MeshDesc& mesh) {
        SurfaceLobes lobes = mesh.material >= 0 ? lobesOf(scene.materials[std::size_t(mesh.material)]) : lambertian;
        if (mesh.light) {  // a UsdLux mesh light emits; with noMaterialResponse it reflects nothing
            if (!mesh.light->materialResponse) lobes = {};
            lobes.emits = true;
        }
        surfaces.push_back({&mesh, lobes});
    };
    for (const render::MeshDesc& mesh : scene.meshes) place(mesh);
    for (const render::InstanceDesc& instance : scene.instances)
        for (const render::MeshDesc& mesh : scene.prototypes[std::size_t(instance.prototype)].meshes) place(mesh);
    return surfaces;
}

}  // namespace

unsigned scenePathClasses(const render::SceneDescription& scene) {
    const std::vector<Surface> surfaces = surfacesOf(scene);
    auto anySurface = [&](auto has) { return std::any_of(surfaces.begin(), surfaces.end(), has); };
    const bool diffuseOrGlossy = anySurface([](const Surface& s) { return s.lobes.diffuseOrGlossy; });
    const bool delta = anySurface([](const Surface& s) { return s.lobes.delta; });
    const bool emissiveSurface = anySurface([](const Surface& s) { return s.lobes.emits; });
    const bool deltaLight = std::any_of(scene.lights.begin(), scene.lights.end(), render::isDeltaLight);
    const bool areaLight =
        emissiveSurface || std::any_of(scene.lights.begin(), scene.lights.end(),
                                       [](const render::LightDesc& l) { return !render::isDeltaLight(l); });
    const bool receiver = diffuseOrGlossy || !scene.volumes.empty();
    const bool lightReturns = surfaces.size() > 1 || anySurface([](const Surface& s) { return !isFlat(*s.mesh); });
    const bool focused = delta && receiver && (lightReturns || !scene.volumes.empty());

    unsigned classes = 0;
    auto claim = [&](bool when, PathClass c) { classes |= when ? unsigned(c) : 0u; };
    claim(!scene.lights.empty() || emissiveSurface, kEmitterSeen);
    claim(diffuseOrGlossy, kDirect);
    claim(delta, kSpecularSeen);
    claim(diffuseOrGlossy && lightReturns, kIndirect);
    claim(focused && areaLight, kCaustics);
    claim(focused && deltaLight, kDeltaLightCaustics);
    claim(deltaLight, kDeltaLights);
    claim(!scene.volumes.empty() || anySurface([](const Surface& s) { return s.lobes.scatteringInterior; }), kVolumes);
    claim(anySurface([](const Surface& s) { return s.lobes.subsurface; }), kSubsurface);
    return classes;
}

}  // namespace fluence::integrators
