// The base of the lights at infinity (distant and dome lights): light that arrives from directions
// only, from beyond the scene. Such a light has no position, so no bounds for the light tree and
// no surface for rays to hit (a ray that leaves the scene asks escaped()), and every one offers
// emission sampling: a direction, and a point on the disk of the scene's bounding radius facing
// it (emission_at_infinity.h).
#pragma once

#include <optional>

#include "render/light.h"

namespace fluence::render {

class InfiniteLight : public Light {
public:
    using Light::Light;

    bool atInfinity() const final { return true; }
    std::optional<LightBounds> bounds() const final { return std::nullopt; }
    bool hasEmissionSampling() const final { return true; }
};

}  // namespace fluence::render
