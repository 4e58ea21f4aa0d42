// modifiedPhong(): the energy-conserving modified Phong model (Lewis 1994; Lafortune & Willems
// 1994), the seeds' fix of the original (003, "modified Phong model").
//
//   f = rhoD / pi + rhoS (n + 2) / (2 pi) max(0, cos alpha)^n,    cos alpha = r . wi
//
// | parameter | meaning                                                                |
// |-----------|------------------------------------------------------------------------|
// | rhoD      | diffuse albedo, per channel                                            |
// | rhoS      | specular albedo at normal incidence, per channel; rhoD + rhoS <= 1     |
// | n         | Phong exponent (>= 0)                                                  |
//
// The lobe's constant (n + 2) / (2 pi) is 1 / (its albedo at normal incidence, 2 pi / (n + 2)),
// so the model reflects exactly rhoD + rhoS at normal incidence and less at every other angle
// (the lobe tilts away from the normal and is cut by the horizon): with rhoD + rhoS <= 1 it
// conserves energy. Reciprocal; two-sided. It is PhongBsdf with these constants, sampled the same
// way. Flags: reflection, diffuse, glossy. Path-class label: D.
#pragma once

#include "render/bsdfs/phong.h"

namespace fluence::render {

inline PhongBsdf modifiedPhong(const RGB& rhoD, const RGB& rhoS, float n) {
    return PhongBsdf::normalised(rhoD, rhoS, n);
}

}  // namespace fluence::render
