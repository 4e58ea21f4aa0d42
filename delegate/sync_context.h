// What a sync of the render index reads (the stage, the render time, ...), and what it does with a
// malformed prim: one bad prim never sinks a render (render_index.h).
#pragma once

#include <string>

#include "delegate/imageable.h"
#include "delegate/material_adapter.h"
#include "delegate/prim_reader.h"
#include "scene/stage.h"

namespace fluence::delegate {

struct SyncContext {
    const usd::Stage& stage;
    double time;
    const ColorConverter& convertColor;
    const Warn& warn;
    const IncludedPurposes& purposes;
    bool strict = false;                       // a malformed prim raises SceneError instead of being skipped
    double velocityFrame = usd::kDefaultTime;  // DelegateOptions::velocityFrame
};

// A prim left out of the render (or a value of it ignored) because it is malformed, and why.
struct MalformedPrim {
    std::string path;
    std::string reason;  // the SceneError's message, naming the prim (or the ancestor at fault)
};

// The warning for a malformed prim without --strict: "<consequence>: <reason> (--strict makes
// this an error)", consequence e.g. "not rendered".
std::string malformedWarning(const std::string& consequence, const std::string& reason);

// Handles `error`, raised reading the prim at `path`: rethrows it when context.strict; else warns
// at `path` (malformedWarning) and returns the record of it.
MalformedPrim skipMalformed(const SyncContext& context, const std::string& path, const SceneError& error,
                            const std::string& consequence = "not rendered");

}  // namespace fluence::delegate
