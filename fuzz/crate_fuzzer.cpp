// libFuzzer target for the USD crate reader: bytes -> usd::readCrateBytes -> usd::Stage.
//
// A finding is anything but a clean read or a usd::FileError naming the input: another exception
// type, a crash, an AddressSanitizer or UndefinedBehaviorSanitizer report, a timeout or running out
// of memory. When the bytes read, every spec of the layer is walked (metadata, attribute defaults
// and time samples, relationship targets, variants) and each value printed with toString and its
// numbers read (decoding the arrays the reader defers; a damaged one may throw FileError), then the
// layer is composed by a Stage and every attribute of the traversal resolved at the default time.
//
// Seeds: the crate files of tests/scene/data/crate and ../shared/usd_corpus. Built by
// fuzz/CMakeLists.txt with clang -fsanitize=fuzzer,address,undefined:
//   build/fuzz/crate_fuzzer -max_total_time=60 -timeout=10 -rss_limit_mb=2048 SEED_DIR
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "scene/crate_reader.h"
#include "scene/stage.h"
#include "scene/usda_parser.h"

namespace {

using namespace fluence::usd;

// A folder that does not exist, so arcs the fuzzed layer names resolve to nothing.
const std::string kIdentifier = "/nonexistent-fluence-fuzz/input.usdc";

volatile std::size_t gSink = 0;

void touch(const Value& value) {
    gSink = gSink + value.toString().size() + value.size();
    for (double x : value.numbers) gSink = gSink + (x == x);
}

void touch(const Metadata& metadata) {
    for (const MetadataEntry& entry : metadata) touch(entry.value);
}

template <class Body>
void touchBody(const Body& body, int depth);

void touchPrim(const PrimSpec& prim, int depth) {
    gSink = gSink + prim.path.size() + prim.typeName.size();
    touchBody(prim, depth);
}

template <class Body>
void touchBody(const Body& body, int depth) {
    if (depth > 64) return;
    touch(body.metadata);
    for (const AttributeSpec& attribute : body.attributes) {
        if (attribute.hasDefault) touch(attribute.defaultValue);
        for (const auto& [time, value] : attribute.timeSamples) touch(value);
        touch(attribute.metadata);
    }
    for (const RelationshipSpec& relationship : body.relationships) {
        for (const std::string& target : relationship.targets) gSink = gSink + target.size();
        touch(relationship.metadata);
    }
    for (const auto& child : body.children) touchPrim(*child, depth + 1);
    for (const VariantSetSpec& set : body.variantSets)
        for (const VariantSpec& variant : set.variants) touchBody(variant, depth + 1);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::vector<char> bytes(data, data + size);
    std::unique_ptr<Layer> layer;
    try {
        layer = readCrateBytes(std::move(bytes), kIdentifier);
        // Large arrays are decoded here, when first read: a damaged one throws FileError then.
        touch(layer->metadata);
        for (const auto& prim : layer->rootPrims) touchPrim(*prim, 0);
    } catch (const FileError& error) {
        // The expected outcome for most inputs; the message must name the input.
        if (std::string_view(error.what()).find(kIdentifier) == std::string_view::npos) std::abort();
        return 0;
    }
    try {
        Stage stage(std::move(layer));
        stage.traverse([&](const PrimSpec& prim) {
            for (const AttributeSpec& attribute : prim.attributes)
                if (auto value = Stage::resolve(attribute, kDefaultTime)) touch(*value);
            return true;
        });
    } catch (const ParseError&) {
    } catch (const FileError&) {
        // Composing may read other layers (an absolute asset path can name any file).
    }
    return 0;
}
