// The names of an enumeration's values as the command line and USD render settings spell them: a
// table of (value, name) pairs and its two lookups, so each enumeration lists its names once
// (core/sampler_names.h, render/dome_light_sampling.h).
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string_view>

namespace fluence {

template <class E>
struct EnumName {
    E value;
    std::string_view name;
};

// The name of `value` in `table` (empty if the table lacks it).
template <class E, std::size_t N>
constexpr std::string_view nameIn(const std::array<EnumName<E>, N>& table, E value) {
    for (const EnumName<E>& entry : table)
        if (entry.value == value) return entry.name;
    return {};
}

// The value called `name` in `table`, nullopt for none.
template <class E, std::size_t N>
constexpr std::optional<E> valueNamed(const std::array<EnumName<E>, N>& table, std::string_view name) {
    for (const EnumName<E>& entry : table)
        if (entry.name == name) return entry.value;
    return std::nullopt;
}

}  // namespace fluence
