// The names of the subsurface methods (render::SubsurfaceMethod), as the CLI's --subsurface and a
// material's subsurface_type spell them.
#pragma once

#include <optional>
#include <string_view>

#include "render/scene_description.h"

namespace fluence::render {

inline constexpr std::string_view kSubsurfaceMethodNames = "randomwalk, randomwalk_guided or diffusion";

inline std::optional<SubsurfaceMethod> subsurfaceMethodNamed(std::string_view name) {
    if (name == "randomwalk") return SubsurfaceMethod::RandomWalk;
    if (name == "randomwalk_guided") return SubsurfaceMethod::RandomWalkGuided;
    if (name == "diffusion") return SubsurfaceMethod::Diffusion;
    return std::nullopt;
}

}  // namespace fluence::render
