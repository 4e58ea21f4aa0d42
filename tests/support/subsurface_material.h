// A random-walk subsurface material for render-core tests (no USD).
#pragma once

#include <string>
#include <utility>

#include "media/subsurface_medium.h"
#include "render/scene_description.h"

namespace fluence::test {

// Standard Surface subsurface = 1 with no specular lobe, its interior from
// media::subsurfaceMedium for `colour` and `meanFreePath`.
inline render::MaterialDesc subsurfaceMaterial(std::string name, const RGB& colour, const RGB& meanFreePath) {
    render::MaterialDesc m;
    m.name = std::move(name);
    m.subsurface = 1.0f;
    m.subsurfaceColor = colour;
    m.specular = 0.0f;
    m.interior = media::subsurfaceMedium(colour, meanFreePath, 0.0f);
    return m;
}

}  // namespace fluence::test
