// UsdLux DomeLight, a light at infinity (and DomeLight_1, whose pole axis the
// delegate folds into the transform).
//
// | UsdLux input   | type  | default | notes                                                  |
// |----------------|-------|---------|--------------------------------------------------------|
// | texture:file   | asset | none    | lat-long image (below)                                 |
// | normalize      | bool  | false   | no effect                                              |
// | shaping:*      |       |         | ignored (the delegate warns)                           |
// Only the rotation of the transform matters (orthonormalised; its scale and translation are
// ignored).
//
// The dome's image follows OpenEXR's lat-long convention, which UsdLux's DomeLight adopts: the
// top row is latitude +pi/2 (the dome's +Y), the bottom row -pi/2; the left column is longitude
// +pi and the right one -pi; latitude 0, longitude 0 is +Z and longitude +pi/2 is +X. So image
// coordinates (u, v) in [0,1]^2 (u from the left edge, v from the top) map to longitude
// phi = pi - 2 pi u and polar angle theta = pi v from +Y, the direction
// (sin theta sin phi, cos theta, sin theta cos phi). Each texel is a cell of that grid (texel x
// spans u in [x/W, (x+1)/W]); OpenEXR puts the first and last columns' centres on exactly +-pi,
// half a texel away, which we accept so that every texel is one cell of the sampling grid.
// Radiance is the texel's (nearest texel, no filtering) times the light's radiance.
//
// A textured dome is importance-sampled: a piecewise-constant distribution over the texels with
// weights luminance x sin(theta) at each row's centre (the sin(theta) is the area a texel row
// covers on the sphere), so the density in solid angle is p(u, v) / (2 pi^2 sin theta). Without a
// texture the dome is sampled uniformly over the sphere; its radiance is then the same from every
// direction (constantRadiance), and by default next-event estimation does not sample it at all:
// the BSDF- and phase-sampled rays that leave the scene gather it at MIS weight 1, as Cycles
// gathers a constant world (render/dome_light_sampling.h; `--dome-sampling always` samples it).
// Emission sampling: a direction by sample() (reversed), and a point on the disk of the scene's
// bounding radius facing it (emission_at_infinity.h).
#pragma once

#include <memory>

#include "core/frame.h"
#include "render/lights/infinite_light.h"
#include "render/light_image_distribution.h"
#include "render/scene_description.h"

namespace fluence::render {

class DomeLight final : public InfiniteLight {
public:
    explicit DomeLight(const LightDesc& desc);

    std::optional<LightSample> sample(const Vec3f& p, Vec2f u) const override;
    float pdf(const Vec3f& p, const Vec3f& wi, const LightHit& hit) const override;
    RGB escaped(const Vec3f& direction) const override;
    bool constantRadiance() const override { return !texture_; }
    float power(const SceneBounds& bounds) const override;
    std::optional<EmissionSample> sampleEmission(Vec2f uPosition, Vec2f uDirection,
                                                 const SceneBounds& scene) const override;
    EmissionDensity emissionDensity(const Vec3f& point, const Vec3f& direction,
                                    const SceneBounds& scene) const override;

    // World direction of lat-long image coordinates (u, v), and back (see the top of this file).
    Vec3f direction(Vec2f uv) const;
    Vec2f imageCoordinates(const Vec3f& direction) const;

private:
    RGB radianceAt(Vec2f uv) const;

    RGB radiance_;
    Frame frame_;  // the world images of the dome's X (s), Y (t) and Z (n) axes
    std::shared_ptr<const RgbImage> texture_;
    ImageDistribution distribution_;
    RGB meanRadiance_;  // over solid angle
};

}  // namespace fluence::render
