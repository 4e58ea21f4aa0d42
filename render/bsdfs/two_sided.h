// TwoSidedReflection: the two-sided convention of reflection-only BSDFs, written once.
//
// A reflection-only model derives from TwoSidedReflection<Model> (the curiously recurring
// template pattern, so the call to the model is direct, not a second virtual dispatch) and
// implements, for wo strictly above the surface (wo.z > 0):
//     RGB fUpper(wo, wi)      f for wi.z > 0 (the wrapper has checked both sides)
//     float pdfUpper(wo, wi)  pdf for wi.z > 0
//     std::optional<BsdfSample> sampleUpper(wo, uLobe, u)   a sample with wi.z > 0, or nullopt
// The wrapper implements the Bsdf interface from them: f and pdf are zero unless wo and wi are
// strictly on the same side, wo below the surface mirrors both directions (render/bsdf.h,
// "SIDES"), and a grazing wo (wo.z == 0) scatters nothing. A model that also transmits fits the
// wrapper when its two sides are alike and its transmission is a delta (which f and pdf never
// report): the thin dielectric sheet, whose straight-through sample -wo mirrors back to -wo.
#pragma once

#include <optional>

#include "render/bsdf.h"
#include "render/bsdfs/bsdf_checks.h"
#include "render/bsdfs/local_geometry.h"

namespace fluence::render {

template <typename Model>
class TwoSidedReflection : public Bsdf {
public:
    RGB f(const Vec3f& wo, const Vec3f& wi) const final {
        dcheckDirections(wo, wi);
        if (!(wo.z * wi.z > 0.0f)) return RGB(0.0f);
        return wo.z > 0.0f ? model().fUpper(wo, wi) : model().fUpper(mirrorZ(wo), mirrorZ(wi));
    }
    float pdf(const Vec3f& wo, const Vec3f& wi) const final {
        dcheckDirections(wo, wi);
        if (!(wo.z * wi.z > 0.0f)) return 0.0f;
        return wo.z > 0.0f ? model().pdfUpper(wo, wi) : model().pdfUpper(mirrorZ(wo), mirrorZ(wi));
    }
    // A model with two kinds of lobe implements LobeSplit splitUpper(wo, wi) as fUpper's parts.
    LobeSplit fByKind(const Vec3f& wo, const Vec3f& wi) const final {
        if constexpr (requires(const Model& m) { m.splitUpper(wo, wi); }) {
            if (!(wo.z * wi.z > 0.0f)) return {RGB(0.0f), RGB(0.0f)};
            return wo.z > 0.0f ? model().splitUpper(wo, wi) : model().splitUpper(mirrorZ(wo), mirrorZ(wi));
        } else {
            return Bsdf::fByKind(wo, wi);
        }
    }
    std::optional<BsdfSample> sample(const Vec3f& wo, float uLobe, Vec2f u) const final {
        if (wo.z == 0.0f) return std::nullopt;
        std::optional<BsdfSample> s = model().sampleUpper(wo.z > 0.0f ? wo : mirrorZ(wo), uLobe, u);
        if (s && wo.z < 0.0f) s->wi = mirrorZ(s->wi);
        dcheckSample(wo, s);
        return s;
    }

protected:
    ~TwoSidedReflection() = default;

private:
    const Model& model() const { return static_cast<const Model&>(*this); }
};

}  // namespace fluence::render
