// BSDFs: the interface every scattering model in Fluence implements, and its conventions.
//
// FRAME. All directions are unit vectors in the local shading frame (z = shading normal, x = the
// surface's tangent where it has one, which anisotropic lobes stretch along) and point away from
// the surface: `wo` towards the viewer (the previous path vertex), `wi` towards the light (the
// next path vertex).
//
// THE TRIPLE.
//   f(wo, wi)        the BSDF value, WITHOUT the cosine factor |cos theta_i| = |wi.z|: the
//                    reflected radiance is the integral of f(wo, wi) L(wi) |wi.z| dwi.
//   pdf(wo, wi)      the solid-angle density with which sample() returns wi, counting only the
//                    non-delta part (0 where a delta lobe is the only way to reach wi). It may
//                    integrate to less than 1: sample() can fail, and delta lobes carry the rest.
//   sample(wo, uLobe, u)  draws wi. `uLobe` in [0,1) picks a lobe (or reflection against
//                    refraction); `u` in [0,1)^2 draws the direction within it. Returns nullopt
//                    when no direction is produced (for instance below the horizon).
//   flags()          which kinds of lobes the BSDF has (BsdfFlags), constant per instance.
//
// THE SAMPLE RECORD. f and pdf are returned separately, never pre-divided: the path weight is
// f * |wi.z| / pdf.
//   - For a non-delta sample (specular == false), f == f(wo, wi) and pdf == pdf(wo, wi) (the
//     whole BSDF's value and density, summed over its lobes; tests/render/bsdf_properties_test.cpp
//     checks this for every model).
//   - For a delta sample (specular == true), f and pdf are the coefficients of the two Dirac
//     deltas: f = (reflectance or transmittance) / |wi.z| and pdf = the probability of having
//     chosen that lobe, so f * |wi.z| / pdf is the correct weight. f() and pdf() never return
//     a delta: for them the delta lobes are zero (they cannot be hit by another strategy, so
//     an integrator must not apply MIS to a specular sample).
//   - eta is the relative index of refraction crossed: (IOR on wi's side) / (IOR on wo's side)
//     for a transmitted sample (1 through a thin sheet), 1 for a reflected one.
//
// SIDES.
//   - Reflection-only BSDFs are two-sided: with wo below the shading hemisphere (wo.z < 0) both
//     directions are mirrored to the upper side, so a single-sided wall reflects the same from
//     either side; f and pdf are zero when wo and wi are on different sides.
//   - Transmissive BSDFs are one-sided: wo.z > 0 is outside (the side the normal points to,
//     IOR 1 relative to the interior's eta), wo.z < 0 inside. The integrator must therefore not
//     flip the shading frame towards wo for a transmissive surface (kBsdfTransmission); it
//     continues a path on the side the sampled wi leaves by (the ray's origin offset to that
//     side) and gathers light from both sides. A BSDF may still treat its two sides alike: a
//     thin dielectric sheet (same medium on both sides, straight-through transmission, eta 1)
//     mirrors wo below to above as a reflector does.
//   - wo.z == 0 (grazing) scatters nothing: f = 0, pdf = 0, sample() = nullopt.
//
// TRANSPORT MODE. A model's virtual f and sample() are the BSDF for radiance transport (paths
// traced from the camera, as `path` and `naive` do). Refraction compresses solid angle, so radiance is
// scaled by eta^-2 across the interface: the transmitted part of f carries 1 / eta^2 (eta as in
// the sample record), and f obeys the generalised reciprocity
//     f(wo, wi) / n(wo)^2 == f(wi, wo) / n(wi)^2
// (n = IOR on that direction's side) instead of plain symmetry. Energy (flux) is conserved as
// the integral of f(wo, wi) * (n(wi)/n(wo))^2 * |wi.z| dwi <= 1. Paths that carry importance (the
// light subpaths of `bdpt`, the photons of `sppm`) scatter by the adjoint f*(wo, wi) = f(wi, wo),
// which differs from f where f is not symmetric: refraction's 1 / eta^2, and any model that is not
// reciprocal. They say so with Transport::Importance to the non-virtual f(wo, wi, mode) and
// sample(wo, uLobe, u, mode) below (called through a Bsdf&): f(wi, wo) evaluated, and a sampled
// delta refraction's coefficient times eta^2 (the generalised reciprocity above). Shading
// normals break the symmetry of the cosine too; that correction needs the geometric normal, so it
// is the integrator's: integrators/surface_frame.h's adjointShadingCosine.
//
// LABELS. For the path classes integrators declare (Heckbert's L(S|D)*E), a delta lobe is S and
// every other lobe, diffuse or glossy, counts as D: what the class decides is whether a vertex
// can be connected to a light or another vertex (next-event estimation), which any non-delta
// lobe can.
//
// THE LOBE SPLIT. Light path expressions (integrators/light_path_expression.h) tell a diffuse
// bounce from a glossy one, so a BSDF also reports its value split by the kind of lobe:
// fByKind(wo, wi) = {diffuse part, glossy part}, whose sum is f(wo, wi) (delta lobes, which f
// never reports, are S by construction). A model with one kind of non-delta lobe gives all of f to
// it (the default below); models that combine kinds (Phong-style diffuse + lobe, layers, mixes)
// split it. tests/render/bsdf_properties_test.cpp checks the sum for every model.
//
// The models live in render/bsdfs/, one per file. An integrator creates the BSDF of a hit in a
// BsdfArena (render/bsdf_arena.h) without a heap allocation.
#pragma once

#include <optional>
#include <utility>

#include "core/rgb.h"
#include "core/vec.h"

namespace fluence::render {

// What kinds of lobes a BSDF has (bitwise OR): at least one of reflection or transmission, and
// one or more of diffuse, glossy or specular (none for a black surface).
enum BsdfFlags : unsigned {
    kBsdfReflection = 1u << 0,
    kBsdfTransmission = 1u << 1,
    kBsdfDiffuse = 1u << 2,
    kBsdfGlossy = 1u << 3,
    kBsdfSpecular = 1u << 4,  // a Dirac delta lobe (perfect mirror or perfect refraction)
};

// What a path carries (TRANSPORT MODE): radiance from the camera, or importance from a light.
enum class Transport { Radiance, Importance };

// f(wo, wi) split by the kind of lobe that produces it (THE LOBE SPLIT).
struct LobeSplit {
    RGB diffuse, glossy;
};

struct BsdfSample {
    RGB f;                  // BSDF value (non-delta) or delta coefficient (specular), no cosine
    Vec3f wi;               // sampled direction, unit, local shading frame
    float pdf = 0.0f;       // solid-angle density (non-delta) or lobe probability (specular)
    bool specular = false;  // sampled from a delta lobe
    float eta = 1.0f;       // relative IOR crossed: n(wi side) / n(wo side); 1 for reflection
};

class Bsdf {
public:
    virtual RGB f(const Vec3f& wo, const Vec3f& wi) const = 0;
    virtual float pdf(const Vec3f& wo, const Vec3f& wi) const = 0;
    virtual std::optional<BsdfSample> sample(const Vec3f& wo, float uLobe, Vec2f u) const = 0;
    virtual unsigned flags() const = 0;
    // Exactly {f(wo, wi), pdf(wo, wi)}, as next-event estimation asks: a model whose two compute the
    // same thing of wo overrides it to do so once (wrappers need not forward: the default is exact).
    virtual std::pair<RGB, float> fAndPdf(const Vec3f& wo, const Vec3f& wi) const { return {f(wo, wi), pdf(wo, wi)}; }
    // f(wo, wi) as its diffuse and glossy parts; by default all of it is the model's one kind:
    // glossy if it has a glossy lobe, else diffuse.
    virtual LobeSplit fByKind(const Vec3f& wo, const Vec3f& wi) const {
        const RGB value = f(wo, wi);
        return (flags() & kBsdfGlossy) ? LobeSplit{RGB(0.0f), value} : LobeSplit{value, RGB(0.0f)};
    }

    // The BSDF a path carrying `mode` scatters by (TRANSPORT MODE): f(wo, wi) for radiance, the
    // adjoint f(wi, wo) for importance.
    RGB f(const Vec3f& wo, const Vec3f& wi, Transport mode) const {
        return mode == Transport::Radiance ? f(wo, wi) : f(wi, wo);
    }
    // sample() for `mode`: the same direction and density, with the sample's f that of `mode`.
    std::optional<BsdfSample> sample(const Vec3f& wo, float uLobe, Vec2f u, Transport mode) const {
        std::optional<BsdfSample> s = sample(wo, uLobe, u);
        if (s && mode == Transport::Importance) s->f = s->specular ? s->f * (s->eta * s->eta) : f(s->wi, wo);
        return s;
    }

protected:
    // BSDFs live in a BsdfArena and are never deleted through this interface; a protected,
    // trivial destructor keeps every model trivially destructible (the arena relies on it).
    ~Bsdf() = default;
};

}  // namespace fluence::render
