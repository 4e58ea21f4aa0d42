// `fluence cat FILE [--flatten] [-o OUT.usda]`: a layer as USDA text, like OpenUSD's usdcat.
//
// Without --flatten the file is read alone (USDA text or binary crate, by its first bytes, through
// the reader the stage uses) and written back as text, every spec and value as authored
// (scene/usda_writer.h). With --flatten the stage is opened and composed as `fluence info` and
// `fluence render` compose it (--variant, --load, --unload and --no-payloads apply) and its
// flattened layer is written: one layer, no composition arcs, which opened again composes to the
// same prims. The text goes to stdout, or with -o to a file, written atomically (a failed write
// leaves nothing at the path). Warnings go to stderr; exit codes are those of apps/scene_loading.h.
#pragma once

#include <string>
#include <vector>

#include "scene/composition_types.h"

namespace fluence::app {

struct CatOptions {
    std::string layer;
    std::string output;  // -o/--output; empty: stdout
    bool flatten = false;
    std::vector<usd::VariantSelection> variants;  // --variant P:SET=SEL (with --flatten)
    usd::LoadRules loadRules;                     // --load, --unload, --no-payloads (with --flatten)
};

// Parses the arguments after `fluence cat`. Throws UsageError with a one-line reason.
CatOptions parseCatOptions(const std::vector<std::string>& args);

// Writes the layer (or the flattened stage) as USDA text; returns an exit code.
int runCat(const CatOptions& options);

}  // namespace fluence::app
