// The composition tests' helpers: the layers under tests/scene/composition/, composed prims and
// values read back, warnings searched, source locations found in the layer files.
#pragma once

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "scene/stage.h"

namespace fluence::usd::test {

namespace fs = std::filesystem;

inline const fs::path kLayers = fs::path(FLUENCE_SOURCE_DIR "/tests/scene/composition").lexically_normal();

inline std::string layer(const std::string& relative) { return (kLayers / relative).generic_string(); }

inline std::unique_ptr<Stage> open(const std::string& relative, const StageOptions& options = {}) {
    return Stage::open(layer(relative), options);
}

inline const PrimSpec& at(const Stage& stage, const std::string& path) {
    const PrimSpec* prim = stage.prim(path);
    if (!prim) throw std::runtime_error("no composed prim at " + path);
    return *prim;
}

inline const AttributeSpec& attribute(const PrimSpec& prim, const std::string& name) {
    const AttributeSpec* a = prim.attribute(name);
    if (!a) throw std::runtime_error("no attribute " + name + " on " + prim.path);
    return *a;
}

inline double number(const PrimSpec& prim, const std::string& name) {
    auto value = Stage::resolve(attribute(prim, name), kDefaultTime);
    if (!value || !value->asDouble()) throw std::runtime_error(name + " on " + prim.path + " has no number");
    return *value->asDouble();
}

inline std::vector<double> numbers(const PrimSpec& prim, const std::string& name) {
    auto value = Stage::resolve(attribute(prim, name), kDefaultTime);
    if (!value) throw std::runtime_error(name + " on " + prim.path + " has no value");
    return value->numbers;
}

inline std::string text(const PrimSpec& prim, const std::string& name) {
    auto value = Stage::resolve(attribute(prim, name), kDefaultTime);
    if (!value || !value->asString()) throw std::runtime_error(name + " on " + prim.path + " has no string");
    return *value->asString();
}

// (time, value) of a scalar attribute's time samples.
inline std::vector<std::pair<double, double>> samples(const PrimSpec& prim, const std::string& name) {
    std::vector<std::pair<double, double>> out;
    for (const auto& [time, value] : attribute(prim, name).timeSamples) out.emplace_back(time, *value.asDouble());
    return out;
}

inline std::vector<std::string> childNames(const PrimSpec& prim) {
    std::vector<std::string> names;
    for (const auto& child : prim.children) names.push_back(child->name);
    return names;
}

inline std::vector<std::string> metadataStrings(const PrimSpec& prim, const std::string& key) {
    const MetadataEntry* entry = findMetadata(prim.metadata, key);
    return entry ? entry->value.strings : std::vector<std::string>{};
}

// Where `needle` starts in a layer file, as "file:line:column".
inline std::string locate(const std::string& relative, const std::string& needle) {
    std::ifstream file(layer(relative));
    std::stringstream contents;
    contents << file.rdbuf();
    std::string all = contents.str();
    std::size_t at = all.find(needle);
    if (at == std::string::npos) throw std::runtime_error("'" + needle + "' not in " + relative);
    int line = 1 + static_cast<int>(std::count(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(at), '\n'));
    std::size_t lineStart = all.rfind('\n', at);
    int column = static_cast<int>(at - (lineStart == std::string::npos ? 0 : lineStart + 1)) + 1;
    return SourceLocation{layer(relative), line, column}.str();
}

// The warnings whose message contains `part`.
inline std::vector<CompositionWarning> warningsWith(const Stage& stage, const std::string& part) {
    std::vector<CompositionWarning> found;
    for (const CompositionWarning& w : stage.warnings())
        if (w.message.find(part) != std::string::npos) found.push_back(w);
    return found;
}

inline std::string allWarnings(const Stage& stage) {
    std::string all;
    for (const CompositionWarning& w : stage.warnings())
        all += w.location.str() + " " + w.primPath + ": " + w.message + "\n";
    return all;
}

inline std::vector<std::string> traversed(const Stage& stage) {
    std::vector<std::string> paths;
    stage.traverse([&](const PrimSpec& prim) {
        paths.push_back(prim.path);
        return true;
    });
    return paths;
}

}  // namespace fluence::usd::test
