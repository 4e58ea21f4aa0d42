#include "apps/light_path_aovs.h"

#include <algorithm>
#include <array>

#include "apps/cli_options.h"
#include "core/film.h"
#include "core/name_table.h"
#include "delegate/prim_reader.h"

namespace fluence::app {

namespace {

constexpr std::array<const char*, 8> kFilmLayers{"R", "G", "B", "A", "albedo", "N", "Z", "sampleCount"};

// Why `name` cannot be a layer name, or "" when it can.
std::string layerNameProblem(const std::string& name) {
    const auto identifierChar = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
    if (name.empty() || std::isdigit(static_cast<unsigned char>(name.front())) ||
        !std::all_of(name.begin(), name.end(), identifierChar))
        return "the layer name '" + name + "' is not an identifier (letters, digits, _)";
    if (std::find(kFilmLayers.begin(), kFilmLayers.end(), name) != kFilmLayers.end())
        return "the layer name '" + name + "' is taken by the image's own channels";
    return "";
}

}  // namespace

LightPathOption parseLightPathOption(const std::string& text) {
    const std::size_t eq = text.find('=');
    if (eq == std::string::npos) throw UsageError("--lpe expects NAME=EXPRESSION, got '" + text + "'");
    LightPathOption option{text.substr(0, eq), text.substr(eq + 1)};
    if (std::string problem = layerNameProblem(option.name); !problem.empty()) throw UsageError("--lpe: " + problem);
    try {
        integrators::LightPathExpression check(option.expression);
    } catch (const integrators::LpeSyntaxError& e) {
        throw UsageError("--lpe " + option.name + "='" + option.expression + "': " + e.what());
    }
    return option;
}

std::vector<integrators::LightPathAov> lightPathAovs(const delegate::RenderProductDesc* product,
                                                     const std::vector<LightPathOption>& options) {
    std::vector<integrators::LightPathAov> aovs;
    auto named = [&](const std::string& name) {
        return std::find_if(aovs.begin(), aovs.end(),
                            [&](const integrators::LightPathAov& a) { return a.name == name; });
    };
    if (product)
        for (const delegate::RenderVarDesc& var : product->vars) {
            if (var.sourceType != "lpe") continue;
            const std::string name = primName(var.path);
            if (std::string problem = layerNameProblem(name); !problem.empty())
                throw delegate::SceneError("RenderVar " + var.path + ": " + problem);
            if (named(name) != aovs.end())
                throw delegate::SceneError("RenderVar " + var.path + ": a second layer named '" + name + "'");
            try {
                aovs.push_back({name, integrators::LightPathExpression(var.sourceName)});
            } catch (const integrators::LpeSyntaxError& e) {
                throw delegate::SceneError("RenderVar " + var.path + ": sourceName '" + var.sourceName +
                                           "' is not a light path expression: " + e.what());
            }
        }
    for (const LightPathOption& option : options) {
        integrators::LightPathAov aov{option.name, integrators::LightPathExpression(option.expression)};
        if (auto same = named(option.name); same != aovs.end())
            *same = std::move(aov);
        else
            aovs.push_back(std::move(aov));
    }
    if (aovs.size() > std::size_t(kMaxLightPathLayers))
        throw UsageError("at most " + std::to_string(kMaxLightPathLayers) + " light path expression AOVs (" +
                         std::to_string(aovs.size()) + " requested)");
    return aovs;
}

}  // namespace fluence::app
