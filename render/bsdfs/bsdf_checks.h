// The conventions of render/bsdf.h, checked in debug builds (FLUENCE_DCHECK, core/check.h; nothing
// in Release): the directions a BSDF is asked about are unit vectors, and a sample is a unit
// direction with a finite value and a finite, non-negative density (a lobe probability in (0, 1]
// for a delta sample). Called by the models that every material goes through: the two-sided
// reflectors' wrapper (two_sided.h), the mix (mix.h) and the rough/smooth dielectric.
#pragma once

#include <optional>

#include "core/check.h"
#include "render/bsdf.h"

namespace fluence::render {

inline void dcheckDirections(const Vec3f& wo, const Vec3f& wi) {
    FLUENCE_DCHECK(isUnit(wo));
    FLUENCE_DCHECK(isUnit(wi));
}

inline void dcheckSample(const Vec3f& wo, const std::optional<BsdfSample>& s) {
    FLUENCE_DCHECK(isUnit(wo));
    if (!s) return;
    FLUENCE_DCHECK(isUnit(s->wi));
    FLUENCE_DCHECK(isFinite(s->f));
    FLUENCE_DCHECK(isValidDensity(s->pdf));
    FLUENCE_DCHECK(!s->specular || (s->pdf > 0.0f && s->pdf <= 1.0f));
}

}  // namespace fluence::render
