#include "volumes/grid_medium.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "media/exact_depth.h"
#include "volumes/blackbody_radiance.h"

namespace fluence::volumes {

namespace {

void require(bool ok, const std::string& what) {
    if (!ok) throw std::invalid_argument("GridMedium: " + what);
}

bool inRange(const RGB& c, float lo, float hi) {
    return c.x >= lo && c.x <= hi && c.y >= lo && c.y <= hi && c.z >= lo && c.z <= hi;
}
bool finiteNonNegative(float v) { return v >= 0.0f && std::isfinite(v); }
bool finiteNonNegative(const RGB& c) {
    return finiteNonNegative(c.x) && finiteNonNegative(c.y) && finiteNonNegative(c.z);
}

void validate(const GridMediumParams& p) {
    require(finiteNonNegative(p.densityScale), "densityScale must be finite and >= 0");
    require(finiteNonNegative(p.albedo), "albedo must be finite and >= 0");
    require(inRange(p.absorptionColor, 0.0f, 1.0f), "absorptionColor must lie in [0, 1]");
    require(p.anisotropy > -1.0f && p.anisotropy < 1.0f, "anisotropy must lie in (-1, 1)");
    require(finiteNonNegative(p.emissionScale), "emissionScale must be finite and >= 0");
    require(finiteNonNegative(p.emissionColor), "emissionColor must be finite and >= 0");
    require(finiteNonNegative(p.blackbodyIntensity), "blackbodyIntensity must be finite and >= 0");
    require(std::isfinite(p.temperatureScale) && std::isfinite(p.temperatureOffset),
            "temperatureScale and temperatureOffset must be finite");
}

// sigmaT / (densityScale * d) for scattering colour c and absorption colour a (see MODEL).
RGB extinctionFactor(const RGB& c, const RGB& a) { return c + vmax(RGB(1.0f) - c, RGB(0.0f)) * (RGB(1.0f) - a); }

}  // namespace

GridMedium::GridMedium(FloatVdbGrid density, const GridMediumParams& params, std::optional<FloatVdbGrid> temperature,
                       std::optional<Vec3VdbGrid> color, const MajorantGridOptions& majorantOptions)
    : density_(std::move(density)), temperature_(std::move(temperature)), color_(std::move(color)), params_(params) {
    validate(params_);
    majorantGrid_ = MajorantGrid(density_, majorantOptions);
    RGB largestColour = params_.albedo * (color_ ? vmax(color_->maxValue(), RGB(0.0f)) : RGB(1.0f));
    majorantScale_ = extinctionFactor(largestColour, params_.absorptionColor) * params_.densityScale;
    RGB smallestColour = color_ ? RGB(0.0f) : params_.albedo;
    minorantScale_ = extinctionFactor(smallestColour, params_.absorptionColor) * params_.densityScale;
    if (!color_) {
        cells_ = TrilinearCells(density_);
        if (!(cells_.minValue() >= 0.0f)) cells_ = TrilinearCells();
    }
}

media::MediumProperties GridMedium::at(const Vec3f& p) const {
    media::MediumProperties m;
    m.g = params_.anisotropy;
    float d = density_.sample(p) * params_.densityScale;
    if (!(d > 0.0f)) return m;
    RGB c = params_.albedo;
    if (color_) c *= vmax(color_->sample(p), RGB(0.0f));
    m.sigmaS = c * d;
    m.sigmaA = vmax(RGB(1.0f) - c, RGB(0.0f)) * (RGB(1.0f) - params_.absorptionColor) * d;
    m.emission = params_.emissionColor * params_.emissionScale;
    if (params_.blackbodyIntensity > 0.0f) {
        float kelvin =
            params_.temperatureOffset + params_.temperatureScale * (temperature_ ? temperature_->sample(p) : 0.0f);
        m.emission += blackbodyRadiance(kelvin) * params_.blackbodyIntensity;
    }
    return m;
}

void GridMedium::majorants(const Vec3f& origin, const Vec3f& direction, float tMin, float tMax,
                           FunctionRef<bool(const media::MajorantSegment&)> visit) const {
    MajorantDda dda(majorantGrid_, origin, direction, tMin, tMax, majorantScale_, minorantScale_);
    while (std::optional<media::MajorantSegment> segment = dda.next())
        if (!visit(*segment)) return;
}

namespace {

// A dual cell's stretch times the medium's constant extinction factor: a piece for media/exact_depth.h's
// visitors (PIECES), its integral the walk's and its cubic computed only when asked.
struct ScaledStretch {
    const CellStretch& stretch;
    Vec3d scale;
};
double wholePieceIntegral(const ScaledStretch& piece) { return piece.stretch.integral; }
media::ExtinctionPiece cubicPiece(const ScaledStretch& piece) {
    media::ExtinctionPiece cubic;
    cubic.tMin = piece.stretch.tMin;
    cubic.tMax = piece.stretch.tMax;
    cubic.scale = piece.scale;
    piece.stretch.cubic(cubic.polynomial);
    return cubic;
}

}  // namespace

template <class Visit>
void GridMedium::forEachPiece(const Vec3f& origin, const Vec3f& direction, float tMin, float tMax, Visit& visit) const {
    // Without a colour grid the majorant scale is the constant extinction factor (MAJORANTS).
    const Vec3d scale(majorantScale_.x, majorantScale_.y, majorantScale_.z);
    const CellRay ray = cells_.prepare(origin, direction);
    const auto walk = [&](double t0, double t1) {
        return cells_.walk(ray, t0, t1, [&](const CellStretch& stretch) {
            return visit(ScaledStretch{stretch, scale});
        });
    };
    // The dual cells are walked over each run of consecutive non-empty majorant segments (which
    // share their ends exactly), so the walk starts once per run, not once per majorant cell.
    MajorantDda dda(majorantGrid_, origin, direction, tMin, tMax, majorantScale_, minorantScale_);
    while (std::optional<MajorantRun> run = dda.nextRun())
        if (!walk(run->tMin, run->tMax)) return;
}

void GridMedium::extinctionPieces(const Vec3f& origin, const Vec3f& direction, float tMin, float tMax,
                                  FunctionRef<bool(const media::ExtinctionPiece&)> visit) const {
    const auto cubicVisit = [&](const ScaledStretch& piece) { return visit(cubicPiece(piece)); };
    forEachPiece(origin, direction, tMin, tMax, cubicVisit);
}

media::OpticalDepth GridMedium::exactOpticalDepth(const Vec3f& origin, const Vec3f& direction, float tMin,
                                                  float tMax) const {
    media::OpticalDepthSum sum;
    forEachPiece(origin, direction, tMin, tMax, sum);
    return sum.depth;
}

media::DepthCrossing GridMedium::exactDepthCrossing(const Vec3f& origin, const Vec3f& direction, float tMin, float tMax,
                                                    int hero, double target) const {
    media::DepthCrossingSearch search{hero, target, {}};
    forEachPiece(origin, direction, tMin, tMax, search);
    return search.crossing;
}

}  // namespace fluence::volumes
