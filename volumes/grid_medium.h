// A heterogeneous medium made from OpenVDB grids: smoke, clouds, fire.
//
// MODEL (units of media/medium.h: coefficients per scene unit, RGB in the rendering space). With
// d(p) = max(density grid(p), 0), c(p) = albedo * max(colour grid(p), 0) per channel (albedo alone
// without a colour grid) and a = absorptionColor:
//
//   sigmaS(p) = densityScale * d(p) * c(p)
//   sigmaA(p) = densityScale * d(p) * max(1 - c(p), 0) * (1 - a)
//   Le(p)     = emissionScale * emissionColor + blackbodyIntensity * L_bb(T(p)),
//   T(p)      = temperatureOffset + temperatureScale * temperature grid(p)   (kelvin; the grid
//               counts as 0 where absent), L_bb from volumes/blackbody_radiance.h
//
// so with the default black absorption colour, sigmaT = densityScale * d: the extinction is the
// density times densityScale per scene unit, as in Cycles' Principled Volume and Houdini, and
// albedo is the single-scattering albedo. The absorption colour is the tint that absorption gives
// transmitted light (Cycles' Absorption Color, without its square root): white absorbs nothing.
// Le is radiance per unit absorption (media/medium.h): the medium's source term is sigmaA * Le,
// which carries the density; Cycles' volume emission is per unit length instead.
//
// | parameter          | type  | default | unit           | meaning                                  |
// |--------------------|-------|---------|----------------|------------------------------------------|
// | densityScale       | float | 1       | 1/scene unit   | extinction per unit of density, >= 0      |
// | albedo             | RGB   | 0.8     | -              | scattering colour, >= 0 (x colour grid)  |
// | absorptionColor    | RGB   | 0       | -              | transmitted tint of absorption, in [0, 1] |
// | anisotropy         | float | 0       | -              | Henyey-Greenstein g, in (-1, 1)          |
// | emissionScale      | float | 0       | radiance       | constant emission, >= 0                  |
// | emissionColor      | RGB   | 1       | -              | its colour, >= 0                         |
// | blackbodyIntensity | float | 0       | -              | blackbody emission strength, >= 0        |
// | temperatureScale   | float | 1       | K per grid unit| temperature grid to kelvin               |
// | temperatureOffset  | float | 0       | K              | added after the scale                    |
//
// The parameters are GridMediumParams (volumes/grid_medium_params.h), which render::VolumeDesc
// holds and the delegate fills from a UsdVol Volume's material; bad values throw std::invalid_argument naming the
// parameter. The grids may have different transforms and resolutions; each is sampled at the
// world point. The medium is confined to the density grid's support (volumes/vdb_grid.h).
//
// MAJORANTS come from a MajorantGrid over the density grid, scaled by densityScale times the
// largest extinction factor c + max(1 - c, 0) (1 - a) any point can have, per channel: that factor
// grows with c, so its largest value is at the colour grid's maximum. The grid's minorants are
// scaled by densityScale times the smallest factor: the albedo's without a colour grid, 1 - a (that
// of c = 0) with one.
//
// EXACT EXTINCTION (media/medium.h). Without a colour grid, sigmaT = densityScale * d(p) * the
// extinction factor of the albedo, a constant per channel; where no stored value (nor the
// background) is negative, d = the trilinear reconstruction itself, whose pieces along a ray are
// the cubics of volumes/trilinear_cells.h. Such a medium offers them (hasExactExtinction), walking
// the dual cells only inside the majorant grid's non-empty segments; a colour grid, a negative
// value or a grid too large for the dense copy leaves it tracked only.
#pragma once

#include <optional>

#include "media/medium.h"
#include "volumes/grid_medium_params.h"
#include "volumes/majorant_grid.h"
#include "volumes/trilinear_cells.h"
#include "volumes/vdb_grid.h"

namespace fluence::volumes {

class GridMedium final : public media::Medium {
public:
    GridMedium(FloatVdbGrid density, const GridMediumParams& params, std::optional<FloatVdbGrid> temperature = {},
               std::optional<Vec3VdbGrid> color = {}, const MajorantGridOptions& majorantOptions = {});

    media::MediumProperties at(const Vec3f& p) const override;
    void majorants(const Vec3f& origin, const Vec3f& direction, float tMin, float tMax,
                   FunctionRef<bool(const media::MajorantSegment&)> visit) const override;
    bool hasExactExtinction() const override { return cells_.available(); }
    void extinctionPieces(const Vec3f& origin, const Vec3f& direction, float tMin, float tMax,
                          FunctionRef<bool(const media::ExtinctionPiece&)> visit) const override;
    media::OpticalDepth exactOpticalDepth(const Vec3f& origin, const Vec3f& direction, float tMin,
                                          float tMax) const override;
    media::DepthCrossing exactDepthCrossing(const Vec3f& origin, const Vec3f& direction, float tMin, float tMax,
                                            int hero, double target) const override;

    // The world-space box outside which the medium is empty.
    WorldBounds bounds() const { return density_.worldBounds(); }
    const MajorantGrid& majorantGrid() const { return majorantGrid_; }
    // sigmaMaj of a majorant-grid cell of value v is v * majorantScale().
    const RGB& majorantScale() const { return majorantScale_; }
    // sigmaMin of a cell of minorant v is v * minorantScale().
    const RGB& minorantScale() const { return minorantScale_; }

private:
    // Hands `visit` (a template argument, inlined into the cells' walk) each cell's stretch as a
    // piece of media/exact_depth.h (PIECES): its integral, and its cubic only when asked.
    template <class Visit>
    void forEachPiece(const Vec3f& origin, const Vec3f& direction, float tMin, float tMax, Visit& visit) const;

    FloatVdbGrid density_;
    std::optional<FloatVdbGrid> temperature_;
    std::optional<Vec3VdbGrid> color_;
    GridMediumParams params_;
    MajorantGrid majorantGrid_;
    RGB majorantScale_, minorantScale_;
    TrilinearCells cells_;  // unavailable unless the medium has exact extinction (EXACT EXTINCTION)
};

}  // namespace fluence::volumes
