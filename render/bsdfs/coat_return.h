// A clear coat over a glossy base that keeps the light its underside sends back down: Kulla &
// Conty's energy compensation (2017) applied to the whole coated stack.
//
// A coat laid over a base by albedo scaling (render/bsdfs/layered.h) drops the light the base
// reflects towards directions where the coat reflects it back down: from wo,
//
//   loss(wo) = (1 - A(wo)) B(wo),   B(w) = integral A(wi) f_base(w, wi) cos theta_i dwi
//   A: the coat's directional albedo (render/bsdfs/dielectric_reflection.h)
//
// Over a diffuse base B is a constant and the layer's normalisation returns the loss exactly
// (layered.h, ENERGY-PRESERVING LAYERING). Over a plastic or a metal the base sends its glossy
// reflection towards grazing directions when lit at grazing angles, where A is largest: a coat
// over a white plastic read 0.956 at 80 degrees and 1.008 at normal incidence with that
// normalisation, a coat over a white metal 0.84 at 80 degrees without it; the same holds of a
// sheen (a coat over white sheen read 1.011 at normal incidence and 0.961 at 85 degrees), of the
// specular layer over subsurface (0.863 at 85 degrees: the light the layer reflects towards
// grazing angles is sent back down by the coat, and dropped) and of glass's reflection (0.853).
// Here the lost light comes back as a lobe symmetric in wo and wi,
//
//   f = f_coated(wo, wi) + filter loss(wo) loss(wi) / (pi Lavg),   Lavg = 1/pi integral loss cos
//
// on the coated side (+z; mirrored below when the stack is two-sided), whose albedo is loss(wo)
// exactly: a white stack reflects 1 at every angle, and the result stays reciprocal. Over a base
// that transmits into an interior (subsurface, solid glass) the light that crosses is the stack's
// own (it is not part of the loss: what goes in comes out in the interior), and the inside of the
// stack is left as it is; a thin-walled sheet has a second outside, handled below (without it a
// coat over a white sheet read 0.817 at 85 degrees from the front and 0.490 from behind). The
// returned lobe is sampled, cosine-weighted on the side chosen (below), with probability
// lobeProbability(loss(wo)), else the stack; a non-delta sample returns the whole f and the mixture's pdf, a delta one of the
// stack its coefficient with its probability times 1 - lobeProbability(loss(wo)).
//
// B is computed for a base made of parts, each a glossy lobe of albedo E(mu) plus a
// diffuse-shaped lobe K g(wo) g(wi) / pi, mixed by weights:
//   - a plastic: the specular layer (GGX) over its diffuse base, g = 1 - E, K = the albedo the
//     base reflects (diffuse x (1 - subsurface): subsurface transmits) / (1 - Eavg);
//   - a sheen over the diffuse base (when no specular layer reflects): the Charlie lobe, g = 1 - E,
//     K likewise;
//   - a metal: its single scattering and its multiple-scattering lobe, g = 1 - E,
//     K = Fms / (1 - Eavg);
//   - solid glass: its single-scattering GGX reflection from outside, and the multiple-scattering
//     lobe's reflected part, g = 1 - E_glass (render/bsdfs/ggx_dielectric_multiple_scattering.h);
//   - a thin-walled sheet: its single-scattering reflection, E_sheet - S, and the reflected part of
//     its multiple-scattering lobe, g = 1 - E_sheet (render/bsdfs/thin_dielectric_albedo.h,
//     thin_dielectric_multiple_scattering.h);
//
//   B(mu) = sum over parts  weight (E(mu) sum_k A(mu_k) spread_k(mu) + K g(mu) G)
//   G     = 2 integral A(nu) g(nu) nu dnu
//
// spread (render/bsdfs/ggx_redistribution.h, sheen_redistribution.h) says where the glossy lobe
// sends the light; the loss is tabulated at the 32 mu nodes of render/bsdfs/albedo_table.h and
// interpolated linearly, and Lavg integrated exactly from the same interpolant.
//
// A THIN SHEET UNDER THE COAT has two outsides: light arriving from the uncoated side (-z) crosses
// the sheet, straight (S) or by its multiple-scattering lobe's transmitted part (K_T g g / pi),
// and the coat's underside sends A of it back down: from wi on that side the loss is
//
//   loss'(mu) = sum over sheet parts  weight (S(mu) A(mu) + K_T g(mu) G)
//
// (straight through, the light meets the coat at its own elevation). The light both losses stand
// for meets the sheet again from above, and leaves by either side; the returned lobes are
//
//   f = filter c_ss' loss_s(wo) loss_s'(wi) / pi     (s, s' the sides of wo and wi)
//   c_same = (L - X) / L^2 on each side,   c_crossed = X / (L L')
//
// with L, L' the two losses' cosine-weighted averages and X the light exchanged between the sides,
// symmetric, so the lobes stay reciprocal and each side's albedo is its loss exactly, whatever X
// in [0, min(L, L')]. X is what the front loss sends through the sheet if it bounced between the
// sheet and the coat's underside at its own elevation (the geometric series of the two),
//
//   X = 2 integral loss(mu) t(mu) / (1 - r(mu) A(mu)) mu dmu,   clamped to min(L, L')
//
// with r and t the base's and the sheet's directional reflectance and transmittance (the lobes'
// albedos, E and S, plus their diffuse-shaped lobes'); in total exact for a smooth coat over a
// smooth sheet, where the light keeps its elevation (by Fresnel's equations, a cosine-weighted
// average of the sheet's transmittance instead puts 0.857 of the front loss through a sheet of
// index 1.5 under a coat of 1.5, where the series puts 0.682: the loss lies at grazing angles,
// where the sheet reflects most).
//
// LABELS (light path expressions, render/bsdf.h THE LOBE SPLIT): the returned light is credited
// to the kind of lobe of the base it comes from, as the layer's normalisation over a diffuse base
// credits its light to that base: the diffuse-shaped lobe of a diffuse base (a plastic's or a
// sheen's base, the diffuse base alone) is diffuse; the glossy lobes, and the diffuse-shaped lobes
// that stand for a glossy lobe's multiple scattering (a metal's, glass's, a sheet's), are glossy.
// A side's diffuse share is that of its cosine-weighted loss (0 on a sheet's uncoated side,
// which only glossy lobes reach); a lobe between the sides takes the mean of the two sides'
// shares, so the split stays symmetric in wo and wi.
//
// Approximations: the base is isotropic (an anisotropic lobe spreads as its geometric-mean
// width), a coloured specular layer spreads as the one of its first channel's index, a coloured
// metal as its bare lobe, a sheet's reflection as the interface's of its faces (R_s spreads as F);
// a sheen under a specular layer counts as diffuse; the returned lobe has the shape the symmetric
// form gives it, not that of a simulation of the layers, and over solid glass or subsurface it
// leaves by reflection even where a real coat would send part of it into the base (over a thin
// sheet it leaves by both sides as above); light returned to a coloured base is not coloured
// again.
#pragma once

#include <array>

#include "core/function_ref.h"
#include "core/rgb.h"
#include "render/bsdf.h"
#include "render/bsdf_arena.h"
#include "render/bsdfs/albedo_table.h"
#include "render/bsdfs/ggx_redistribution.h"

namespace fluence::render {

class CoatReturn {
public:
    using NodeValues = std::array<RGB, albedo_table::kCosines>;

    // coatAlbedo: the coat's directional albedo A at each mu node (cosineAt(i)).
    explicit CoatReturn(const std::array<float, albedo_table::kCosines>& coatAlbedo);

    // The kind of lobe a part's diffuse-shaped lobe is (LABELS above): a diffuse base seen through
    // the part's glossy lobe, or the glossy lobe's own multiple scattering.
    enum class ShapedLobe { Diffuse, Glossy };

    // A part of the base of mix weight `weight`: a lobe of albedo lobe[i] at the mu nodes that
    // spreads the light arriving at node i as spreadFrom(i) does (render/bsdfs/ggx_redistribution.h,
    // sheen_redistribution.h), and the diffuse-shaped lobe scale g(wo) g(wi) / pi, of kind `shaped`.
    void addPart(float weight, FunctionRef<ElevationWeights(int)> spreadFrom, const NodeValues& lobe,
                 const NodeValues& g, const RGB& scale, ShapedLobe shaped);
    // A thin sheet of mix weight `weight`: on the coated side a part as addPart's (reflected, g,
    // reflectedScale); from the other side the share straight[i] that crosses it straight and the
    // transmitted lobe transmittedScale g(wo) g(wi) / pi.
    void addSheetPart(float weight, FunctionRef<ElevationWeights(int)> spreadFrom, const NodeValues& reflected,
                      const NodeValues& straight, const NodeValues& g, const RGB& reflectedScale,
                      const RGB& transmittedScale);

    // `coated` (the coat over the base, reflection only) with the light it loses returned,
    // through the coat's filter.
    const Bsdf& compensate(const Bsdf& coated, const RGB& filter, BsdfArena& arena) const;

    // The returned lobes: the loss on each side, side 0 the coated one (+z), side 1 the other, and
    // the couplings c_same per side and c_crossed, before the filter and 1 / pi.
    struct Lobes {
        std::array<NodeValues, 2> loss{};
        std::array<RGB, 2> same{};
        RGB crossed{0.0f};
        std::array<float, 2> crossingProbability{};  // the share of the returned light that changes side
        std::array<RGB, 2> diffuseShare{};           // per side, the share of its loss labelled diffuse
        unsigned kinds = 0;                          // BsdfFlags: the kinds of lobe the light returns by
    };

private:
    // Adds the light a part sends into the coat, per unit of the light it receives, to into[i], and
    // what of it its diffuse-shaped lobe sends to shapedInto[i] (when not null).
    void addMeetingCoat(NodeValues& into, NodeValues* shapedInto, float weight,
                        FunctionRef<ElevationWeights(int)> spreadFrom, const NodeValues& lobe, const NodeValues& g,
                        const RGB& scale) const;
    // The lobes from the parts added so far.
    void updateLobes();

    std::array<float, albedo_table::kCosines> coatAlbedo_;
    NodeValues returned_{};                       // B at the mu nodes
    NodeValues returnedDiffuse_{};                // the part of B from diffuse lobes (LABELS)
    NodeValues returnedBelow_{};                  // what the sheet lets through into the coat from its other side
    NodeValues reflectance_{}, transmittance_{};  // the base's r(mu) and the sheets' t(mu)
    Lobes lobes_;
};

}  // namespace fluence::render
