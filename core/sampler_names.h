// The names of the samplers (core/random.h) on the command line and in USD render settings.
#pragma once

#include <optional>
#include <string_view>

#include "core/random.h"

namespace fluence {

constexpr std::string_view kSamplerNames = "sobol, independent";

constexpr std::string_view samplerName(SamplerKind kind) {
    return kind == SamplerKind::Sobol ? "sobol" : "independent";
}

// The sampler called `name`, nullopt for none.
constexpr std::optional<SamplerKind> samplerNamed(std::string_view name) {
    for (SamplerKind kind : {SamplerKind::Sobol, SamplerKind::Independent})
        if (samplerName(kind) == name) return kind;
    return std::nullopt;
}

}  // namespace fluence
