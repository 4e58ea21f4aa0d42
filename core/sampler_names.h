// The names of the samplers (core/random.h) on the command line and in USD render settings.
#pragma once

#include <array>
#include <optional>
#include <string_view>

#include "core/enum_names.h"
#include "core/random.h"

namespace fluence {

constexpr std::string_view kSamplerNames = "sobol, independent";

inline constexpr std::array<EnumName<SamplerKind>, 2> kSamplerTable{
    {{SamplerKind::Sobol, "sobol"}, {SamplerKind::Independent, "independent"}}};

constexpr std::string_view samplerName(SamplerKind kind) { return nameIn(kSamplerTable, kind); }

// The sampler called `name`, nullopt for none.
constexpr std::optional<SamplerKind> samplerNamed(std::string_view name) { return valueNamed(kSamplerTable, name); }

}  // namespace fluence
