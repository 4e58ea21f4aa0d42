// TEST FIXTURE ONLY: a minimal USD crate (.usdc) writer, the inverse of the scene library's crate
// reader (scene/crate_file.h, crate_values.h, crate_integer_coding.h, crate_compression.h) for
// the subset the tests need. It is not a production writer and is never linked into Fluence.
//
// It always picks the simplest valid encoding:
//   - version 0.8.0 (array counts are uint64, references carry a layer offset), or an older one
//     given to the constructor, written as OpenUSD's crateFile.cpp describes it: before 0.7.0
//     array counts are uint32, before 0.5.0 preceded by a uint32 rank of 1; before 0.4.0 the
//     structural sections are plain (see finish()), in 0.0.1 with padded spec records and path
//     headers;
//   - LZ4 framing: chunk-count byte 0, then one block from LZ4_compress_default;
//   - integer coding: common value 0 and every value in the widest code (3), as deltas;
//   - values out of line (the ValueRep payload is the file offset of their data) except tokens,
//     strings, asset paths, specifiers and variability, which are index/enum payloads inlined,
//     and the explicit `inlined(type, bits)` helper for testing OpenUSD's inlined forms;
//   - arrays: a uint64 count, then the raw elements, uncompressed (the compressed bit unset), or
//     with `compressedInts` an int/uint array integer-coded as below (the compressed bit set);
//   - path expressions: out of line, their text's string index (arrays: one string index each);
//   - nested values (dictionary entries, time samples): a relative jump of 8, then the ValueRep;
//   - no value deduplication; the path tree in pre-order with USD's jump coding.
// Layout: 88-byte bootstrap, value data, then sections TOKENS, STRINGS, FIELDS, FIELDSETS, PATHS,
// SPECS, then the table of contents. Before 0.4.0: TOKENS a uint64 count, a uint64 byte size and
// the text; FIELDS a uint64 count and 16-byte records (4 bytes of padding, token, ValueRep);
// FIELDSETS a uint64 count and uint32 indexes; PATHS a uint64 count and one 12-byte header per
// path in pre-order (index, element token, bits 1 child / 2 sibling / 4 property, 3 bytes of
// padding), followed when it has both a child and a sibling by the sibling's int64 file offset;
// SPECS a uint64 count and 12-byte (path, field set, type) records; in 0.0.1 path headers and
// spec records start with 4 more bytes of padding.
#pragma once

#include <cstdint>
#include <cstring>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <lz4.h>

#include "scene/crate_file.h"
#include "scene/crate_values.h"

namespace fluence::test {

namespace crate_type = usd::detail::crate_type;

class CrateWriter {
public:
    using Rep = std::uint64_t;
    using Fields = std::vector<std::pair<std::string, Rep>>;
    using SpecType = usd::detail::CrateSpecType;
    struct Reference {
        std::string asset, primPath;
        double offset = 0.0, scale = 1.0;
    };

    explicit CrateWriter(usd::detail::CrateVersion version = {0, 8, 0}) : version_(version), data_(88, 0) {
        token("");  // token 0 is never a property name, so every property element is negative
        nodes_.push_back({0, {}});
        pathIndex_["/"] = 0;
    }

    // ---- tables -------------------------------------------------------------------------------
    std::uint32_t token(const std::string& s) {
        auto [it, added] = tokenIndex_.emplace(s, static_cast<std::uint32_t>(tokens_.size()));
        if (added) tokens_.push_back(s);
        return it->second;
    }
    std::uint32_t string(const std::string& s) {
        std::uint32_t t = token(s);
        for (std::size_t i = 0; i < strings_.size(); ++i)
            if (strings_[i] == t) return static_cast<std::uint32_t>(i);
        strings_.push_back(t);
        return static_cast<std::uint32_t>(strings_.size() - 1);
    }
    // Registers a path (and its ancestors) in the path tree.
    std::uint32_t path(const std::string& p) {
        if (auto it = pathIndex_.find(p); it != pathIndex_.end()) return it->second;
        std::string parent, element;
        bool property = false;
        if (p.back() == '}') {
            auto at = p.rfind('{');
            parent = p.substr(0, at), element = p.substr(at);
        } else {
            auto at = p.find_last_of("/.}");
            property = p[at] == '.';
            parent = p[at] == '/' && at == 0 ? "/" : p.substr(0, p[at] == '}' ? at + 1 : at);
            element = p.substr(at + 1);
        }
        std::uint32_t parentIndex = path(parent);
        auto tok = static_cast<std::int32_t>(token(element));
        auto index = static_cast<std::uint32_t>(nodes_.size());
        nodes_.push_back({property ? -tok : tok, {}});
        nodes_[parentIndex].children.push_back(index);
        pathIndex_[p] = index;
        return index;
    }

    // ---- values -------------------------------------------------------------------------------
    static Rep rep(int type, std::uint64_t payload, bool array = false, bool inlined = false) {
        return (std::uint64_t(type) << 48) | payload | (array ? 1ull << 63 : 0) | (inlined ? 1ull << 62 : 0);
    }
    static Rep inlined(int type, std::uint32_t bits) { return rep(type, bits, false, true); }

    // A scalar, vector, matrix or quaternion (components in on-disk order: quaternions i, j, k, real).
    template <class T>
    Rep value(int type, std::vector<T> components) {
        std::uint64_t at = data_.size();
        for (const T& c : components) put(c);
        return rep(type, at);
    }
    // An array of `count` elements, `flat` holding every component in on-disk order.
    template <class T>
    Rep array(int type, const std::vector<T>& flat, std::size_t count) {
        std::uint64_t at = data_.size();
        putArraySize(count);
        for (const T& c : flat) put(c);
        return rep(type, at, true);
    }
    // An int or uint array, integer-coded (16 or more elements: the reader takes shorter ones raw;
    // crate 0.5.0 and later).
    Rep compressedInts(int type, const std::vector<std::int32_t>& values) {
        std::uint64_t at = data_.size();
        putArraySize(values.size());
        putInts(values);
        return rep(type, at, true) | (1ull << 61);
    }
    // An SdfPathExpression value: its text (as a string index), out of line.
    Rep pathExpression(const std::string& text) {
        std::uint64_t at = data_.size();
        put(string(text));
        return rep(crate_type::PathExpression, at);
    }
    Rep pathExpressionArray(const std::vector<std::string>& items) {
        return indexList(crate_type::PathExpression, items, true);
    }
    Rep tokenValue(const std::string& s) { return inlined(crate_type::Token, token(s)); }
    Rep stringValue(const std::string& s) { return inlined(crate_type::String, string(s)); }
    Rep assetValue(const std::string& s) { return inlined(crate_type::AssetPath, token(s)); }
    Rep tokenArray(const std::vector<std::string>& items) { return indexList(crate_type::Token, items, true); }
    Rep stringArray(const std::vector<std::string>& items) { return indexList(crate_type::String, items, true); }
    Rep tokenVector(const std::vector<std::string>& items) { return indexList(crate_type::TokenVector, items, false); }

    Rep dictionary(const Fields& entries) {
        std::uint64_t at = data_.size();
        put<std::uint64_t>(entries.size());
        for (const auto& [key, value] : entries) {
            put(string(key));
            put<std::int64_t>(8);
            put(value);
        }
        return rep(crate_type::Dictionary, at);
    }
    Rep tokenListOp(const std::vector<std::string>& prepend, const std::vector<std::string>& append) {
        std::uint64_t at = data_.size();
        put<std::uint8_t>((prepend.empty() ? 0 : 1 << 5) | (append.empty() ? 0 : 1 << 6));
        for (const auto* list : {&prepend, &append}) {
            if (list->empty()) continue;
            put<std::uint64_t>(list->size());
            for (const auto& s : *list) put(token(s));
        }
        return rep(crate_type::TokenListOp, at);
    }
    Rep explicitPathListOp(const std::vector<std::string>& paths) {
        std::uint64_t at = data_.size();
        put<std::uint8_t>(1 | 2);
        put<std::uint64_t>(paths.size());
        for (const auto& p : paths) put(path(p));
        return rep(crate_type::PathListOp, at);
    }
    Rep prependReferenceListOp(const std::vector<Reference>& refs) {
        std::uint64_t at = data_.size();
        put<std::uint8_t>(1 << 5);
        put<std::uint64_t>(refs.size());
        for (const Reference& r : refs) {
            put(string(r.asset));
            put(path(r.primPath));
            put(r.offset);
            put(r.scale);
            put<std::uint64_t>(0);  // empty customData dictionary
        }
        return rep(crate_type::ReferenceListOp, at);
    }
    Rep variantSelection(const std::vector<std::pair<std::string, std::string>>& selections) {
        std::uint64_t at = data_.size();
        put<std::uint64_t>(selections.size());
        for (const auto& [set, name] : selections) put(string(set)), put(string(name));
        return rep(crate_type::VariantSelectionMap, at);
    }
    Rep timeSamples(const std::vector<double>& times, const std::vector<Rep>& values) {
        Rep timesRep = array(crate_type::Double, times, times.size());
        std::uint64_t at = data_.size();
        put<std::int64_t>(8);
        put(timesRep);
        put<std::int64_t>(8);
        put<std::uint64_t>(values.size());
        for (Rep v : values) put(v);
        return rep(crate_type::TimeSamples, at);
    }

    // ---- specs and the file -------------------------------------------------------------------
    void spec(const std::string& p, SpecType type, const Fields& fields) {
        auto fieldSet = static_cast<std::int32_t>(fieldSets_.size());
        for (const auto& [name, value] : fields) {
            fieldSets_.push_back(static_cast<std::int32_t>(fieldTokens_.size()));
            fieldTokens_.push_back(static_cast<std::int32_t>(token(name)));
            fieldReps_.push_back(value);
        }
        fieldSets_.push_back(-1);  // ~0u: the end of the run
        specs_[0].push_back(static_cast<std::int32_t>(path(p)));
        specs_[1].push_back(fieldSet);
        specs_[2].push_back(static_cast<std::int32_t>(type));
    }

    std::vector<char> finish() {
        if (!version_.atLeast(0, 4, 0)) return finishPlain();
        // The path tree first: it may add element tokens.
        std::vector<std::int32_t> pathIndexes, elements, jumps;
        encodeTree({0}, pathIndexes, elements, jumps);

        beginSection("TOKENS");
        std::string text;
        for (const auto& t : tokens_) text += t, text += '\0';
        std::vector<char> packed = compress(text.data(), text.size());
        put<std::uint64_t>(tokens_.size()), put<std::uint64_t>(text.size()), put<std::uint64_t>(packed.size());
        putBytes(packed.data(), packed.size());

        beginSection("STRINGS");
        put<std::uint64_t>(strings_.size());
        for (std::uint32_t s : strings_) put(s);

        beginSection("FIELDS");
        put<std::uint64_t>(fieldTokens_.size());
        putInts(fieldTokens_);
        packed = compress(fieldReps_.data(), fieldReps_.size() * sizeof(Rep));
        put<std::uint64_t>(packed.size());
        putBytes(packed.data(), packed.size());

        beginSection("FIELDSETS");
        put<std::uint64_t>(fieldSets_.size());
        putInts(fieldSets_);

        beginSection("PATHS");
        put<std::uint64_t>(nodes_.size()), put<std::uint64_t>(nodes_.size());
        putInts(pathIndexes), putInts(elements), putInts(jumps);

        beginSection("SPECS");
        put<std::uint64_t>(specs_[1].size());
        for (const auto& column : specs_) putInts(column);
        return finishTableOfContents();
    }

private:
    struct Node {
        std::int32_t element;
        std::vector<std::uint32_t> children;
    };
    struct Section {
        const char* name;
        std::uint64_t start = 0, size = 0;
    };

    // The structural sections of crate versions before 0.4.0, uncompressed.
    std::vector<char> finishPlain() {
        const bool padded = !version_.atLeast(0, 1, 0);
        beginSection("TOKENS");
        std::string text;
        for (const auto& t : tokens_) text += t, text += '\0';
        put<std::uint64_t>(tokens_.size()), put<std::uint64_t>(text.size());
        putBytes(text.data(), text.size());

        beginSection("STRINGS");
        put<std::uint64_t>(strings_.size());
        for (std::uint32_t s : strings_) put(s);

        beginSection("FIELDS");
        put<std::uint64_t>(fieldTokens_.size());
        for (std::size_t i = 0; i < fieldTokens_.size(); ++i)
            put<std::uint32_t>(0), put(fieldTokens_[i]), put(fieldReps_[i]);

        beginSection("FIELDSETS");
        put<std::uint64_t>(fieldSets_.size());
        for (std::int32_t index : fieldSets_) put(index);

        beginSection("PATHS");
        put<std::uint64_t>(nodes_.size());
        writeTree({0}, padded);

        beginSection("SPECS");
        put<std::uint64_t>(specs_[0].size());
        for (std::size_t i = 0; i < specs_[0].size(); ++i) {
            if (padded) put<std::uint32_t>(0);
            put(specs_[0][i]), put(specs_[1][i]), put(specs_[2][i]);
        }
        return finishTableOfContents();
    }

    // The path tree in pre-order, each header followed (with both a child and a sibling) by the
    // file offset of its sibling, filled in once the child subtree is written.
    void writeTree(const std::vector<std::uint32_t>& siblings, bool padded) {
        for (std::size_t i = 0; i < siblings.size(); ++i) {
            const Node& node = nodes_[siblings[i]];
            const bool hasChild = !node.children.empty(), hasSibling = i + 1 < siblings.size();
            if (padded) put<std::uint32_t>(0);
            put(siblings[i]);
            put<std::uint32_t>(static_cast<std::uint32_t>(node.element < 0 ? -node.element : node.element));
            put<std::uint8_t>((hasChild ? 1 : 0) | (hasSibling ? 2 : 0) | (node.element < 0 ? 4 : 0));
            put<std::uint8_t>(0), put<std::uint8_t>(0), put<std::uint8_t>(0);
            if (!hasChild) continue;
            std::size_t siblingOffset = data_.size();
            if (hasSibling) put<std::int64_t>(0);
            writeTree(node.children, padded);
            if (!hasSibling) continue;
            std::int64_t sibling = static_cast<std::int64_t>(data_.size());
            std::memcpy(data_.data() + siblingOffset, &sibling, sizeof sibling);
        }
    }

    std::vector<char> finishTableOfContents() {
        sections_.back().size = data_.size() - sections_.back().start;
        std::uint64_t toc = data_.size();
        put<std::uint64_t>(sections_.size());
        for (const Section& s : sections_) {
            char name[16] = {};
            std::memcpy(name, s.name, std::strlen(s.name));
            putBytes(name, sizeof name);
            put(s.start), put(s.size);
        }
        std::memcpy(data_.data(), "PXR-USDC", 8);
        data_[8] = static_cast<char>(version_.major), data_[9] = static_cast<char>(version_.minor);
        data_[10] = static_cast<char>(version_.patch);
        std::memcpy(data_.data() + 16, &toc, sizeof toc);
        return data_;
    }

    // An array's element count: uint32 before 0.7.0, after a uint32 rank of 1 before 0.5.0.
    void putArraySize(std::size_t count) {
        if (!version_.atLeast(0, 5, 0)) put<std::uint32_t>(1);
        if (version_.atLeast(0, 7, 0))
            put<std::uint64_t>(count);
        else
            put<std::uint32_t>(static_cast<std::uint32_t>(count));
    }
    template <class T>
    void put(const T& v) {
        putBytes(&v, sizeof v);
    }
    void putBytes(const void* p, std::size_t n) {
        const char* c = static_cast<const char*>(p);
        data_.insert(data_.end(), c, c + n);
    }
    Rep indexList(int type, const std::vector<std::string>& items, bool isArray) {
        std::uint64_t at = data_.size();
        if (isArray)
            putArraySize(items.size());
        else
            put<std::uint64_t>(items.size());
        for (const auto& s : items)
            put(type == crate_type::String || type == crate_type::PathExpression ? string(s) : token(s));
        return rep(type, at, isArray);
    }
    static std::vector<char> compress(const void* p, std::size_t n) {
        std::vector<char> out(1 + static_cast<std::size_t>(LZ4_compressBound(static_cast<int>(n))),
                              0);  // out[0]: 0 chunks
        int size = LZ4_compress_default(static_cast<const char*>(p), out.data() + 1, static_cast<int>(n),
                                        static_cast<int>(out.size() - 1));
        out.resize(1 + static_cast<std::size_t>(size));
        return out;
    }
    // Integer coding: common value 0, every delta in the widest code; then LZ4 and a uint64 size.
    void putInts(const std::vector<std::int32_t>& values) {
        std::vector<char> encoded(4 + (values.size() * 2 + 7) / 8, 0);
        std::memset(encoded.data() + 4, 0xFF, encoded.size() - 4);
        std::uint32_t previous = 0;
        for (std::int32_t v : values) {
            std::uint32_t delta = static_cast<std::uint32_t>(v) - previous;
            previous = static_cast<std::uint32_t>(v);
            const char* c = reinterpret_cast<const char*>(&delta);
            encoded.insert(encoded.end(), c, c + 4);
        }
        std::vector<char> packed = compress(encoded.data(), encoded.size());
        put<std::uint64_t>(packed.size());
        putBytes(packed.data(), packed.size());
    }
    void encodeTree(const std::vector<std::uint32_t>& siblings, std::vector<std::int32_t>& indexes,
                    std::vector<std::int32_t>& elements, std::vector<std::int32_t>& jumps) const {
        for (std::size_t i = 0; i < siblings.size(); ++i) {
            std::size_t at = indexes.size();
            const Node& node = nodes_[siblings[i]];
            indexes.push_back(static_cast<std::int32_t>(siblings[i]));
            elements.push_back(node.element);
            jumps.push_back(0);
            bool hasChild = !node.children.empty(), hasSibling = i + 1 < siblings.size();
            if (hasChild) encodeTree(node.children, indexes, elements, jumps);
            jumps[at] = hasChild && hasSibling ? static_cast<std::int32_t>(indexes.size() - at)
                        : hasChild             ? -1
                        : hasSibling           ? 0
                                               : -2;
        }
    }
    void beginSection(const char* name) {
        if (!sections_.empty()) sections_.back().size = data_.size() - sections_.back().start;
        sections_.push_back({name, data_.size(), 0});
    }

    usd::detail::CrateVersion version_;
    std::vector<char> data_;
    std::vector<std::string> tokens_;
    std::map<std::string, std::uint32_t> tokenIndex_;
    std::vector<std::uint32_t> strings_;
    std::vector<Node> nodes_;
    std::map<std::string, std::uint32_t> pathIndex_;
    std::vector<std::int32_t> fieldTokens_;
    std::vector<Rep> fieldReps_;
    std::vector<std::int32_t> fieldSets_;
    std::vector<std::int32_t> specs_[3];  // path, field set, spec type
    std::vector<Section> sections_;
};

}  // namespace fluence::test
