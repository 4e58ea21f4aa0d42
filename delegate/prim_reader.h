// Typed reads of a prim's attributes at the render time, with USD fallbacks.
//
// The delegate's one way to read authored data: every getter takes the schema's fallback value,
// resolves the attribute at the delegate's time code, and raises SceneError (naming the prim and
// attribute) when an authored value has the wrong type or size.
//
// A render with no frame (time usd::kDefaultTime: no --frame and no startTimeCode) reads the stage
// as Hydra does then, at usd::kEarliestTime: an attribute with only time samples (an animated
// xformOp) gives its earliest sample instead of no value, one with only a default its default.
#pragma once

#include <cmath>
#include <initializer_list>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/matrix.h"
#include "core/rgb.h"
#include "scene/layer.h"
#include "scene/stage.h"

namespace fluence::delegate {

// A semantic error in the scene: names the prim path (and, where known, the file location).
class SceneError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A file the scene needs to render and cannot do without (an OpenVDB grid file) is missing: names
// the prim and the file. The CLI exits with its missing-input code.
class MissingAssetError : public SceneError {
public:
    using SceneError::SceneError;
};

class PrimReader {
public:
    PrimReader(const usd::PrimSpec& prim, double time) : prim_(prim), time_(usd::renderReadTime(time)) {}

    const usd::PrimSpec& prim() const { return prim_; }
    const std::string& path() const { return prim_.path; }

    // The resolved value of `name` (nullopt when unauthored or blocked).
    std::optional<usd::Value> value(const std::string& name) const;
    // Same, trying `name` then each alias in order (for schema renames such as "inputs:intensity"
    // vs. the pre-2021 "intensity").
    std::optional<usd::Value> value(std::initializer_list<const char*> names) const;

    double number(std::initializer_list<const char*> names, double fallback) const;
    bool boolean(std::initializer_list<const char*> names, bool fallback) const;
    std::string token(std::initializer_list<const char*> names, const std::string& fallback) const;
    Vec3d vec3(std::initializer_list<const char*> names, const Vec3d& fallback) const;
    // Arrays: the flattened numbers, checked to have `components` per element.
    std::optional<std::vector<double>> numbers(const std::string& name, int components) const;
    std::optional<std::vector<std::string>> strings(const std::string& name) const;
    // Attribute metadata (e.g. "interpolation"), as a string.
    std::optional<std::string> attributeMetadata(const std::string& attribute, const std::string& key) const;

    [[noreturn]] void fail(const std::string& message) const;

private:
    const usd::PrimSpec& prim_;
    double time_;
};

}  // namespace fluence::delegate
