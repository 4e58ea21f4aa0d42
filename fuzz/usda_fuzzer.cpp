// libFuzzer target for the USDA reader: bytes -> usd::parseUsdaString -> usd::Stage.
//
// A finding is anything but a clean parse or a usd::ParseError: another exception type, a crash,
// an AddressSanitizer or UndefinedBehaviorSanitizer report, a timeout or running out of memory.
// When the text parses, the layer is wrapped in a Stage and every part of it is read back: the
// stage's layer-metadata queries, the traversal, prim lookup by path, and every attribute of every
// prim spec (including over/class prims and prims inside variants, which the traversal skips)
// resolved through Stage::resolve at the default time and at times around each authored sample.
// Each resolved Value is read in full (numbers summed, strings measured, toString), so a bad
// payload shows up as a sanitizer report here rather than in the delegate later. Every
// pathExpression value of the composed stage is parsed as a collection's membershipExpression and
// matched against its prims (scene/path_expression.h): only a PathExpressionError may come out.
//
// Built by fuzz/CMakeLists.txt with clang -fsanitize=fuzzer,address,undefined; run by
// scripts/fuzz_smoke.sh. See fuzz/README.md.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <limits>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "scene/path_expression.h"
#include "scene/stage.h"
#include "scene/usda_parser.h"

namespace {

using namespace fluence::usd;

// The layer's identifier: a file in a folder that does not exist, so that once the Stage composes
// external arcs (sublayers, references, payloads), the relative asset paths a fuzzed layer names
// resolve to nothing instead of to files of the current directory.
const std::string kIdentifier = "/nonexistent-fluence-fuzz/input.usda";

// Keeps reads from being optimised away.
volatile double gSink = 0.0;

void touch(const Value& value, int depth = 0) {
    double sum = static_cast<double>(value.size()) + value.components + value.typeName.size();
    for (double x : value.numbers) sum += std::isfinite(x) ? x : 1.0;
    for (const std::string& s : value.strings) sum += static_cast<double>(s.size());
    if (auto d = value.asDouble()) sum += std::isfinite(*d) ? *d : 1.0;
    if (auto s = value.asString()) sum += static_cast<double>(s->size());
    if (depth < 64) {
        for (const Value& item : value.items) touch(item, depth + 1);
        if (value.dictionary) {
            for (const auto& [key, entry] : *value.dictionary) {
                sum += static_cast<double>(key.size());
                touch(entry, depth + 1);
            }
            if (!value.dictionary->empty()) {
                const Value* first = value.find(value.dictionary->front().first);
                if (first) sum += first->size();
            }
        }
        if (depth == 0) sum += static_cast<double>(value.toString().size());
    }
    gSink = gSink + sum;
}

void touch(const Metadata& metadata) {
    for (const MetadataEntry& entry : metadata) {
        touch(entry.value);
        if (const MetadataEntry* last = findMetadata(metadata, entry.key)) touch(last->value);
        gSink = gSink + entry.location.line + static_cast<double>(entry.location.str().size());
    }
}

// The times at which an attribute is resolved: the default time, far before and after, every
// authored sample time, and midpoints between neighbouring samples (interpolation).
std::vector<double> timesFor(const AttributeSpec& attribute) {
    std::vector<double> times = {kDefaultTime,
                                 -1e9,
                                 0.0,
                                 1.0,
                                 1e9,
                                 -std::numeric_limits<double>::infinity(),
                                 std::numeric_limits<double>::infinity()};
    const auto& samples = attribute.timeSamples;
    for (std::size_t i = 0; i < samples.size() && i < 64; ++i) {
        times.push_back(samples[i].first);
        if (i + 1 < samples.size()) times.push_back(0.5 * (samples[i].first + samples[i + 1].first));
    }
    return times;
}

void touch(const AttributeSpec& attribute) {
    gSink =
        gSink + static_cast<double>(attribute.name.size() + attribute.typeName.size() + attribute.connections.size());
    if (attribute.hasDefault) touch(attribute.defaultValue);
    for (const auto& [time, value] : attribute.timeSamples) {
        gSink = gSink + (std::isfinite(time) ? time : 1.0);
        touch(value);
    }
    touch(attribute.metadata);
    for (double time : timesFor(attribute)) {
        if (auto value = Stage::resolve(attribute, time)) touch(*value);
    }
}

void touch(const RelationshipSpec& relationship) {
    for (const std::string& target : relationship.targets) gSink = gSink + target.size();
    touch(relationship.metadata);
}

void touchPrim(const Layer& layer, const PrimSpec& prim, int depth);

// Variant sets, and the sets nested inside their variants where VariantSpec keeps them (the
// `requires` test lets this build against a Layer with or without that field).
template <class Set>
void touchVariantSets(const Layer& layer, const std::vector<Set>& sets, int depth);

template <class Variant>
void touchVariant(const Layer& layer, const Variant& variant, int depth);

void touchBody(const Layer& layer, const std::vector<AttributeSpec>& attributes,
               const std::vector<RelationshipSpec>& relationships,
               const std::vector<std::unique_ptr<PrimSpec>>& children, int depth) {
    for (const AttributeSpec& attribute : attributes) touch(attribute);
    for (const RelationshipSpec& relationship : relationships) touch(relationship);
    for (const auto& child : children) touchPrim(layer, *child, depth + 1);
}

template <class Set>
void touchVariantSets(const Layer& layer, const std::vector<Set>& sets, int depth) {
    for (const Set& set : sets) {
        gSink = gSink + static_cast<double>(set.name.size());
        for (const auto& variant : set.variants) touchVariant(layer, variant, depth + 1);
    }
}

void touchPrim(const Layer& layer, const PrimSpec& prim, int depth) {
    touch(prim.metadata);
    // Lookups by name and by path must find what the parser built.
    for (const AttributeSpec& attribute : prim.attributes) {
        if (prim.attribute(attribute.name) == nullptr) std::abort();
    }
    for (const RelationshipSpec& relationship : prim.relationships) {
        if (prim.relationship(relationship.name) == nullptr) std::abort();
    }
    for (const auto& child : prim.children) {
        if (prim.child(child->name) == nullptr) std::abort();
    }
    const PrimSpec* found = layer.primAtPath(prim.path);
    gSink = gSink + (found != nullptr) + static_cast<double>(prim.location.str().size());
    touchBody(layer, prim.attributes, prim.relationships, prim.children, depth);
    touchVariantSets(layer, prim.variantSets, depth);
}

template <class Variant>
void touchVariant(const Layer& layer, const Variant& variant, int depth) {
    touch(variant.metadata);
    touchBody(layer, variant.attributes, variant.relationships, variant.children, depth);
    if constexpr (requires { variant.variantSets; }) {
        touchVariantSets(layer, variant.variantSets, depth);
    }
}

// Every composed prim's path, and every pathExpression value with the prim that holds it.
void collectExpressions(const PrimSpec& prim, std::vector<std::string>& paths,
                        std::vector<std::pair<std::string, std::string>>& expressions) {
    paths.push_back(prim.path);
    for (const AttributeSpec& attribute : prim.attributes)
        if (attribute.hasDefault && attribute.defaultValue.typeName == "pathExpression")
            for (const std::string& text : attribute.defaultValue.strings) expressions.emplace_back(prim.path, text);
    for (const auto& child : prim.children) collectExpressions(*child, paths, expressions);
}

// Each pathExpression parsed (anchored at its prim) and, when it parses, matched against the
// first prims of the stage, as a collection's membershipExpression is (scene/path_expression.h).
template <class S>
void touchExpressions(const S& stage) {
    if constexpr (requires { stage.composedLayer(); }) {
        std::vector<std::string> paths;
        std::vector<std::pair<std::string, std::string>> expressions;
        for (const auto& prim : stage.composedLayer().rootPrims) collectExpressions(*prim, paths, expressions);
        for (const auto& [anchor, text] : expressions) {
            try {
                PathExpression expression(text, anchor);
                for (std::size_t i = 0; i < paths.size() && i < 64; ++i)
                    gSink = gSink + expression.matches(paths[i], stage, [](const auto&, const auto&) { return true; });
            } catch (const PathExpressionError& error) {
                if (!std::string_view(error.what()).starts_with("column ")) std::abort();
            }
        }
    }
}

// Once the Stage composes (composedLayer, warnings, asset references), the composed result is
// read back the same way; the `requires` tests keep this building against a Stage without them.
template <class S>
void touchComposition(const S& stage) {
    if constexpr (requires { stage.composedLayer(); }) {
        const Layer& composed = stage.composedLayer();
        for (const auto& prim : composed.rootPrims) touchPrim(composed, *prim, 0);
        touch(composed.metadata);
    }
    if constexpr (requires { stage.warnings(); }) {
        for (const auto& warning : stage.warnings()) {
            gSink = gSink + static_cast<double>(warning.message.size() + warning.primPath.size());
        }
    }
    if constexpr (requires { stage.assetReferences(); }) {
        for (const auto& asset : stage.assetReferences()) {
            gSink = gSink + static_cast<double>(asset.authored.size() + asset.resolved.size());
        }
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    // The bytes are copied into an exactly sized heap buffer so that any read past the end of the
    // text is an AddressSanitizer report (a std::string would hide it behind its terminator).
    std::unique_ptr<char[]> buffer(new char[size ? size : 1]);
    if (size) std::memcpy(buffer.get(), data, size);
    std::string_view text(buffer.get(), size);

    std::unique_ptr<Layer> layer;
    try {
        layer = parseUsdaString(text, kIdentifier);
    } catch (const ParseError& error) {
        // The expected outcome for most inputs; the message must still be readable.
        gSink = gSink + static_cast<double>(std::string_view(error.what()).size()) + error.location().line;
        if (error.location().line < 1 || error.location().column < 1) std::abort();
        return 0;
    }
    // Anything else thrown above escapes to libFuzzer, which reports it as a crash (uncaught
    // exception -> std::terminate -> abort).

    for (const auto& prim : layer->rootPrims) touchPrim(*layer, *prim, 0);
    touch(layer->metadata);

    // Composing may read other layers (an absolute asset path can name any file), and a syntax
    // error in one of those is a ParseError too, as Stage::open documents.
    try {
        Stage stage(std::move(layer));
        gSink = gSink + static_cast<double>(stage.defaultPrim().size()) + stage.upAxis() + stage.metersPerUnit() +
                stage.startTimeCode().value_or(0.0) + stage.endTimeCode().value_or(0.0);
        touchComposition(stage);
        touchExpressions(stage);
        stage.traverse([&](const PrimSpec& prim) {
            if (stage.prim(prim.path) == nullptr && prim.path.find('{') == std::string::npos) {
                // A traversed prim must be reachable by its path.
                std::fprintf(stderr, "traversed prim %s not found by path\n", prim.path.c_str());
                std::abort();
            }
            for (const AttributeSpec& attribute : prim.attributes) {
                if (auto value = Stage::resolve(attribute, kDefaultTime)) touch(*value);
                if (auto start = stage.startTimeCode()) {
                    if (auto value = Stage::resolve(attribute, *start)) touch(*value);
                }
            }
            return true;
        });
    } catch (const ParseError& error) {
        gSink = gSink + static_cast<double>(std::string_view(error.what()).size());
    }
    return 0;
}
