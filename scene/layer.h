// The specs of one USD layer, as authored: the parser's output, and (built by scene/flatten.h) the
// stage's composed, flattened layer.
//
// A Layer is plain data: layer metadata, root prim specs, and under each prim its metadata,
// properties (attributes and relationships) in authored order, child prims and variant sets.
// Every spec remembers where it was authored (file:line:column) so semantic errors found later
// can point at the text.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "scene/time_samples.h"
#include "scene/value.h"

namespace fluence::usd {

struct SourceLocation {
    std::string file;
    int line = 0;             // 1-based
    int column = 0;           // 1-based, in bytes
    std::string str() const;  // "file:line:column"
};

enum class Specifier { Def, Over, Class };
enum class ListOpKind { Explicit, Prepend, Append, Delete, Add, Reorder };

// One metadata entry: `kind = "component"`, `prepend apiSchemas = ["X"]`, `doc = """..."""`.
struct MetadataEntry {
    std::string key;
    ListOpKind op = ListOpKind::Explicit;
    Value value;
    SourceLocation location;
};
using Metadata = std::vector<MetadataEntry>;

// Finds the last explicit-or-list-op entry for `key` (nullptr if none).
const MetadataEntry* findMetadata(const Metadata& metadata, const std::string& key);

struct AttributeSpec {
    std::string name;      // full namespaced name: "xformOp:translate", "inputs:diffuseColor"
    std::string typeName;  // "double3", "point3f[]", ...
    bool custom = false;
    bool uniform = false;  // `uniform` variability
    bool hasDefault = false;
    Value defaultValue;                    // valid when hasDefault
    TimeSamples timeSamples;               // sorted by time, from `name.timeSamples`
    std::vector<std::string> connections;  // from `name.connect`, prim/property paths
    ListOpKind connectionOp = ListOpKind::Explicit;
    Metadata metadata;  // interpolation, elementSize, colorSpace, ...
    SourceLocation location;
};

struct RelationshipSpec {
    std::string name;
    bool custom = false;
    ListOpKind op = ListOpKind::Explicit;
    std::vector<std::string> targets;  // paths without <>
    bool blocked = false;              // `rel x = None`
    Metadata metadata;
    SourceLocation location;
};

struct PrimSpec;
struct VariantSetSpec;

struct VariantSpec {
    std::string name;
    Metadata metadata;
    std::vector<AttributeSpec> attributes;
    std::vector<RelationshipSpec> relationships;
    std::vector<std::unique_ptr<PrimSpec>> children;
    std::vector<VariantSetSpec> variantSets;  // variant sets nested inside this variant
};

struct VariantSetSpec {
    std::string name;
    std::vector<VariantSpec> variants;
    SourceLocation location;
};

struct PrimSpec {
    Specifier specifier = Specifier::Def;
    std::string typeName;  // "Mesh", "Xform", ... (empty for untyped prims)
    std::string name;
    std::string path;                             // absolute prim path, "/World/Box"
    Metadata metadata;                            // kind, apiSchemas, references, variants, instanceable, active, ...
    std::vector<AttributeSpec> attributes;        // authored order
    std::vector<RelationshipSpec> relationships;  // authored order
    std::vector<std::unique_ptr<PrimSpec>> children;
    std::vector<VariantSetSpec> variantSets;
    SourceLocation location;

    const AttributeSpec* attribute(const std::string& name) const;
    const RelationshipSpec* relationship(const std::string& name) const;
    const PrimSpec* child(const std::string& name) const;
};

// Something the reader accepted that USD would flag: an unregistered metadata field, an unknown
// value type. The stage reports these with its composition warnings.
struct ParseWarning {
    SourceLocation location;
    std::string message;
};

struct Layer {
    std::vector<ParseWarning> warnings;
    std::string identifier;  // the file path it was read from (or a name for in-memory text)
    std::string header;      // "#usda 1.0" (or "#sdf 1.4.32")
    Metadata metadata;       // defaultPrim, upAxis, metersPerUnit, subLayers, doc, ...
    std::vector<std::unique_ptr<PrimSpec>> rootPrims;

    // Prim spec at an absolute path such as "/World/Box" (nullptr if absent).
    const PrimSpec* primAtPath(const std::string& path) const;
};

}  // namespace fluence::usd
