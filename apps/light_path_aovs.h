// The light path expression AOVs a render writes, from the USD render settings and the command line.
//
// USD: every RenderVar of the rendered product with `sourceType = "lpe"` is one; the var prim's
// name is the EXR layer (its channels NAME.R, NAME.G, NAME.B) and `sourceName` the expression
// (integrators/light_path_expression.h), e.g.
//     def RenderVar "diffuse" { uniform string sourceName = "C<RD>.*L"  uniform token sourceType = "lpe" }
// CLI: `--lpe NAME=EXPRESSION` (repeatable) adds one, or replaces the USD var of the same name.
// Layer names are identifiers ([A-Za-z_][A-Za-z0-9_]*), unique, and not one of the film's own
// layers (R G B A albedo N Z sampleCount); at most kMaxLightPathLayers (core/film.h).
#pragma once

#include <string>
#include <vector>

#include "delegate/render_settings_adapter.h"
#include "integrators/light_path_tracker.h"

namespace fluence::app {

// One --lpe NAME=EXPRESSION, as given.
struct LightPathOption {
    std::string name, expression;
};

// Parses "NAME=EXPRESSION", checking the name and the expression. Throws UsageError.
LightPathOption parseLightPathOption(const std::string& text);

// The AOVs of `product`'s lpe RenderVars (none without a product), then the command line's. Throws
// delegate::SceneError naming the RenderVar for a bad USD one, UsageError for a bad CLI one.
std::vector<integrators::LightPathAov> lightPathAovs(const delegate::RenderProductDesc* product,
                                                     const std::vector<LightPathOption>& options);

}  // namespace fluence::app
