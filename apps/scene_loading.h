// Opening a USD stage for a command, with the errors mapped to the documented exit codes.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "apps/warning_log.h"
#include "scene/stage.h"

namespace fluence::app {

// Exit codes (documented in `fluence --help` and the README).
enum ExitCode : int {
    kExitOk = 0,
    kExitInternal = 1,
    kExitUsage = 2,
    kExitScene = 3,
    kExitMissingInput = 4,
    kExitOutput = 5,
    kExitColorConfig = 6,
    kExitInterrupted = 7,  // SIGTERM or SIGINT stopped the render; nothing was written
};

void printError(const std::string& message);

// What a missing asset (a layer an arc names, a texture, a VDB file, a clip) is.
enum class MissingAssets {
    Warn,  // a warning each (fluence info, fluence render --allow-missing)
    Fail,  // an error each for what the render reads (layers, textures, VDBs), and kExitMissingInput
           // (fluence render); other asset-valued attributes still only warn
};

// Opens and composes the stage (variant selections and payload load rules in `options`);
// composition warnings go to `warnings`. On failure prints the error and returns a non-zero exit
// code (missing file: kExitMissingInput; syntax: kExitScene).
int composeStage(const std::string& path, const usd::StageOptions& options, WarningLog& warnings,
                 std::unique_ptr<usd::Stage>& stage);

// The stage's asset paths that cannot be used: missing files, and arcs to layers in a format that
// needs a plugin Fluence does not have. `frames`: the time codes rendered (usd::kDefaultTime: no
// frame, each attribute read at its earliest sample as the delegate reads it); an asset-valued
// attribute's asset is read when the value the attribute gives at one of them names it (its
// default, or the time sample held there), and one only other time samples name is not. Empty:
// every asset authored is read. With MissingAssets::Fail a missing asset the render reads is an
// error naming it (kExitMissingInput); the others are warnings.
int checkAssets(const usd::Stage& stage, WarningLog& warnings, MissingAssets missing,
                const std::vector<double>& frames = {});

// composeStage, then checkAssets with MissingAssets::Warn: every missing asset a warning.
int openStage(const std::string& path, const usd::StageOptions& options, WarningLog& warnings,
              std::unique_ptr<usd::Stage>& stage);

}  // namespace fluence::app
