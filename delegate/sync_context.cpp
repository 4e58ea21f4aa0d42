#include "delegate/sync_context.h"

namespace fluence::delegate {

std::string malformedWarning(const std::string& consequence, const std::string& reason) {
    return consequence + ": " + reason + " (--strict makes this an error)";
}

MalformedPrim skipMalformed(const SyncContext& context, const std::string& path, const SceneError& error,
                            const std::string& consequence) {
    if (context.strict) throw error;
    context.warn(path, malformedWarning(consequence, error.what()));
    return {path, error.what()};
}

}  // namespace fluence::delegate
