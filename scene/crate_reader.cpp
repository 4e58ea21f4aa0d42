#include "scene/crate_reader.h"

#include <unordered_map>
#include <unordered_set>
#include <utility>

#include "scene/crate_file.h"
#include "scene/crate_values.h"
#include "scene/namespace_remap.h"
#include "scene/usda_metadata_fields.h"
#include "scene/usda_parser.h"

namespace fluence::usd {

namespace {

using detail::CrateFile;
using detail::CrateFormatError;
using detail::CrateListOp;
using detail::CrateSpec;
using detail::CrateSpecType;
using detail::CrateValues;
using detail::ValueRep;

constexpr int kMaxNesting = 1000;  // prims and variants below the pseudo-root

using Fields = std::vector<std::pair<std::string, ValueRep>>;

// A metadata value in the text reader's untyped form: no type name, tokens as strings, an empty
// array as an empty List.
Value untyped(Value value) {
    if (value.kind == ValueKind::Dictionary) return value;
    if (value.typeName == "token" || value.typeName == "token[]") value.kind = ValueKind::String;
    value.typeName.clear();
    if (value.isArray && value.size() == 0 && value.kind != ValueKind::List) return Value::list({});
    return value;
}

std::string metadataKey(const std::string& field) {
    if (field == "documentation") return "doc";
    if (field == "variantSetNames") return "variantSets";
    if (field == "variantSelection") return "variants";
    if (field == "layerRelocates") return "relocates";
    return field;
}

bool isStructural(const std::string& field) {
    for (const char* name : {"primChildren", "properties", "variantSetChildren", "variantChildren", "targetChildren",
                             "connectionChildren", "specifier", "typeName"})
        if (field == name) return true;
    return false;
}

// Where the children of a prim or variant go.
struct Body {
    std::string path;
    Metadata* metadata;
    std::vector<AttributeSpec>* attributes;
    std::vector<RelationshipSpec>* relationships;
    std::vector<std::unique_ptr<PrimSpec>>* children;
    std::vector<VariantSetSpec>* variantSets;
};

class LayerBuilder {
public:
    LayerBuilder(const CrateFile& file, Layer& layer) : file_(file), values_(file), layer_(layer) {
        for (std::size_t i = 0; i < file.specs().size(); ++i) {
            const std::string& path = file.path(file.specs()[i].path);
            if (path.empty()) throw CrateFormatError("a spec has an empty path");
            if (!specAt_.emplace(path, i).second) throw CrateFormatError("two specs at <" + path + ">");
        }
    }

    void build() {
        auto root = specAt_.find("/");
        if (root == specAt_.end()) return;
        const CrateSpec& spec = file_.specs()[root->second];
        if (spec.type != CrateSpecType::PseudoRoot) throw CrateFormatError("the spec at </> is not the pseudo-root");
        Fields fields = fieldsOf(spec);
        Value subLayers, offsets;
        std::vector<std::string> rootPrims;
        for (const auto& [name, rep] : fields) {
            if (name == "primChildren")
                rootPrims = names(rep, "/");
            else if (name == "subLayers")
                subLayers = values_.value(rep);
            else if (name == "subLayerOffsets")
                offsets = values_.value(rep);
            else if (name == "primOrder")
                reorder(layer_.metadata, "rootPrims", rep);
            else
                addMetadata(layer_.metadata, name, rep);
        }
        if (!subLayers.strings.empty())
            layer_.metadata.push_back(
                {"subLayers", ListOpKind::Explicit, joinSubLayers(subLayers, offsets), location()});
        for (const std::string& name : rootPrims)
            layer_.rootPrims.push_back(prim(detail::childPrimPath("/", name), name, 1));
    }

private:
    SourceLocation location() const { return {layer_.identifier, 0, 0}; }

    const CrateSpec& specAt(const std::string& path, CrateSpecType type, const char* what) const {
        auto it = specAt_.find(path);
        if (it == specAt_.end()) throw CrateFormatError("no " + std::string(what) + " spec at <" + path + ">");
        const CrateSpec& spec = file_.specs()[it->second];
        if (spec.type != type) throw CrateFormatError("the spec at <" + path + "> is not a " + what);
        return spec;
    }

    Fields fieldsOf(const CrateSpec& spec) const {
        Fields fields;
        for (const detail::CrateField* field : file_.fieldsOf(spec))
            fields.emplace_back(file_.token(field->token), field->value);
        return fields;
    }

    // A token vector of child names, each a single path element: no path syntax (variant names
    // may start with '.').
    std::vector<std::string> names(ValueRep rep, const std::string& owner, const char* forbidden = "/.{}[]=") const {
        Value list = values_.value(rep);
        if (list.kind != ValueKind::Token && list.kind != ValueKind::String)
            throw CrateFormatError("the children of <" + owner + "> are not a list of names");
        std::unordered_set<std::string> seen;
        for (const std::string& name : list.strings) {
            if (name.empty() || name.find_first_of(forbidden) != std::string::npos)
                throw CrateFormatError("invalid child name '" + name + "' under <" + owner + ">");
            // Each child spec is read once: a repeated name could otherwise multiply the work.
            if (!seen.insert(name).second)
                throw CrateFormatError("child '" + name + "' listed twice under <" + owner + ">");
        }
        return list.strings;
    }

    Value joinSubLayers(const Value& assets, const Value& offsets) const {
        Value list = Value::list({});
        for (std::size_t i = 0; i < assets.strings.size(); ++i) {
            Value item;
            item.kind = ValueKind::Reference;
            item.strings = {assets.strings[i], ""};
            if (i < offsets.items.size()) item.numbers = offsets.items[i].numbers;
            if (item.numbers.size() == 2 && item.numbers[0] == 0.0 && item.numbers[1] == 1.0) item.numbers = {};
            list.items.push_back(std::move(item));
        }
        return list;
    }

    void reorder(Metadata& out, const char* key, ValueRep rep) const {
        Value order = values_.value(rep);
        out.push_back(
            {key, ListOpKind::Reorder, Value::string("", ValueKind::String, order.strings, true), location()});
    }

    void addMetadata(Metadata& out, const std::string& field, ValueRep authored) {
        std::string key = metadataKey(field);
        const ValueRep rep = values_.unwrapUnregistered(authored);
        if (!detail::isRegisteredMetadataField(key))
            layer_.warnings.push_back(
                {location(), "unregistered metadata field '" + key + "'; kept, but nothing reads it"});
        if (CrateValues::isListOp(rep)) {
            CrateListOp op = values_.listOp(rep);
            if (op.isExplicit && op.lists.empty())
                out.push_back(
                    {key, ListOpKind::Explicit, untyped(Value::string("", ValueKind::String, {}, true)), location()});
            for (auto& [kind, items] : op.lists) {
                if (op.isExplicit && kind != ListOpKind::Explicit)
                    continue;  // Sdf ignores edits of an explicit list op
                out.push_back({key, kind, untyped(std::move(items)), location()});
            }
            return;
        }
        if (CrateValues::isTimeSamples(rep))
            throw CrateFormatError("time samples as metadata '" + key + "' are not supported");
        Value value = values_.value(rep);
        if (key == "variants" || key == "permission") {
            out.push_back({key, ListOpKind::Explicit, std::move(value), location()});
            return;
        }
        // A single payload (crate files before 0.8.0) with neither asset nor prim is `payload = None`.
        if (value.kind == ValueKind::Reference && value.strings[0].empty() && value.strings[1].empty()) value = Value{};
        out.push_back({key, ListOpKind::Explicit, untyped(std::move(value)), location()});
    }

    std::unique_ptr<PrimSpec> prim(const std::string& path, const std::string& name, int depth) {
        if (depth > kMaxNesting)
            throw CrateFormatError("prims nested more than " + std::to_string(kMaxNesting) + " deep");
        const CrateSpec& spec = specAt(path, CrateSpecType::Prim, "prim");
        auto out = std::make_unique<PrimSpec>();
        out->name = name;
        out->path = path;
        out->location = location();
        Fields fields = fieldsOf(spec);
        for (const auto& [field, rep] : fields) {
            if (field == "specifier") {
                std::string specifier = values_.value(rep).asString().value_or("");
                out->specifier = specifier == "over"    ? Specifier::Over
                                 : specifier == "class" ? Specifier::Class
                                                        : Specifier::Def;
            } else if (field == "typeName") {
                out->typeName = values_.value(rep).asString().value_or("");
            }
        }
        fillBody({path, &out->metadata, &out->attributes, &out->relationships, &out->children, &out->variantSets},
                 fields, depth);
        return out;
    }

    void fillBody(const Body& body, const Fields& fields, int depth) {
        std::vector<std::string> children, properties, variantSets;
        for (const auto& [field, rep] : fields) {
            if (field == "primChildren")
                children = names(rep, body.path);
            else if (field == "properties")
                properties = names(rep, body.path);
            else if (field == "variantSetChildren")
                variantSets = names(rep, body.path);
            else if (field == "primOrder")
                reorder(*body.metadata, "nameChildren", rep);
            else if (field == "propertyOrder")
                reorder(*body.metadata, "properties", rep);
            else if (!isStructural(field))
                addMetadata(*body.metadata, field, rep);
        }
        for (const std::string& name : properties) property(body, name);
        for (const std::string& name : children)
            body.children->push_back(prim(detail::childPrimPath(body.path, name), name, depth + 1));
        for (const std::string& name : variantSets) body.variantSets->push_back(variantSet(body.path, name, depth));
    }

    VariantSetSpec variantSet(const std::string& owner, const std::string& name, int depth) {
        std::string path = owner + "{" + name + "=}";
        const CrateSpec& spec = specAt(path, CrateSpecType::VariantSet, "variant set");
        VariantSetSpec set;
        set.name = name;
        set.location = location();
        for (const auto& [field, rep] : fieldsOf(spec)) {
            if (field != "variantChildren")
                throw CrateFormatError("unexpected field '" + field + "' on variant set <" + path + ">");
            for (const std::string& variantName : names(rep, path, "/{}[]=")) {
                std::string variantPath = owner + "{" + name + "=" + variantName + "}";
                const CrateSpec& variantSpec = specAt(variantPath, CrateSpecType::Variant, "variant");
                VariantSpec& variant = set.variants.emplace_back();
                variant.name = variantName;
                fillBody({variantPath, &variant.metadata, &variant.attributes, &variant.relationships,
                          &variant.children, &variant.variantSets},
                         fieldsOf(variantSpec), depth + 1);
            }
        }
        return set;
    }

    void property(const Body& body, const std::string& name) {
        std::string path = body.path + "." + name;
        auto it = specAt_.find(path);
        if (it == specAt_.end()) throw CrateFormatError("no property spec at <" + path + ">");
        const CrateSpec& spec = file_.specs()[it->second];
        if (spec.type == CrateSpecType::Attribute)
            body.attributes->push_back(attribute(name, fieldsOf(spec)));
        else if (spec.type == CrateSpecType::Relationship)
            body.relationships->push_back(relationship(name, fieldsOf(spec)));
        else
            throw CrateFormatError("the spec at <" + path + "> is not an attribute or a relationship");
    }

    // Value `v` as a value of the declared attribute type (a value block keeps the type too).
    static Value typed(Value v, const std::string& typeName) {
        if (typeName.empty()) return v;
        if (v.isBlocked()) v.isArray = typeName.ends_with("[]");
        v.typeName = typeName;
        return v;
    }

    // Sets a spec's own op and paths from a target/connection list op; other edits become
    // `key` metadata entries.
    void pathEdits(ValueRep rep, const char* key, ListOpKind& op, std::vector<std::string>& paths, Metadata& metadata) {
        if (!CrateValues::isListOp(rep)) throw CrateFormatError(std::string(key) + " is not a list op");
        CrateListOp edits = values_.listOp(rep);
        if (edits.isExplicit) {
            op = ListOpKind::Explicit;
            for (auto& [kind, items] : edits.lists)
                if (kind == ListOpKind::Explicit) paths = items.strings;
            return;
        }
        const std::pair<ListOpKind, Value>* own = nullptr;
        for (ListOpKind preferred : {ListOpKind::Prepend, ListOpKind::Append, ListOpKind::Add})
            for (const auto& edit : edits.lists)
                if (!own && edit.first == preferred) own = &edit;
        for (const auto& edit : edits.lists) {
            if (&edit == own) {
                op = edit.first;
                paths = edit.second.strings;
            } else {
                metadata.push_back({key, edit.first, untyped(edit.second), location()});
            }
        }
    }

    AttributeSpec attribute(const std::string& name, const Fields& fields) {
        AttributeSpec out;
        out.name = name;
        out.location = location();
        for (const auto& [field, rep] : fields)
            if (field == "typeName") out.typeName = values_.value(rep).asString().value_or("");
        for (const auto& [field, rep] : fields) {
            if (field == "typeName" || field == "connectionChildren") continue;
            if (field == "custom")
                out.custom = values_.value(rep).asDouble().value_or(0.0) != 0.0;
            else if (field == "variability")
                out.uniform = values_.value(rep).asString() == "uniform";
            else if (field == "default") {
                out.defaultValue = typed(values_.value(rep), out.typeName);
                out.hasDefault = true;
            } else if (field == "timeSamples") {
                if (!CrateValues::isTimeSamples(rep))
                    throw CrateFormatError("timeSamples of '" + name + "' are not time samples");
                out.timeSamples = values_.timeSamples(rep);
                for (auto& sample : out.timeSamples) sample.second = typed(std::move(sample.second), out.typeName);
            } else if (field == "connectionPaths") {
                pathEdits(rep, "connectionPaths", out.connectionOp, out.connections, out.metadata);
            } else {
                addMetadata(out.metadata, field, rep);
            }
        }
        return out;
    }

    RelationshipSpec relationship(const std::string& name, const Fields& fields) {
        RelationshipSpec out;
        out.name = name;
        out.location = location();
        for (const auto& [field, rep] : fields) {
            if (field == "targetChildren" || field == "variability") continue;
            if (field == "custom")
                out.custom = values_.value(rep).asDouble().value_or(0.0) != 0.0;
            else if (field == "targetPaths")
                pathEdits(rep, "targetPaths", out.op, out.targets, out.metadata);
            else
                addMetadata(out.metadata, field, rep);
        }
        return out;
    }

    const CrateFile& file_;
    CrateValues values_;
    Layer& layer_;
    std::unordered_map<std::string, std::size_t> specAt_;
};

}  // namespace

bool isCrateHeader(std::string_view firstBytes) { return firstBytes.starts_with("PXR-USDC"); }

std::unique_ptr<Layer> readCrateBytes(SharedBytes bytes, const std::string& identifier) {
    auto layer = std::make_unique<Layer>();
    layer->identifier = identifier;
    layer->header = "#usda 1.0";
    try {
        CrateFile file(std::move(bytes), identifier);
        LayerBuilder(file, *layer).build();
    } catch (const CrateFormatError& e) {
        detail::throwDamagedCrateFile(identifier, e.what());
    } catch (const std::bad_alloc&) {
        throw FileError("'" + identifier + "': USD crate file too large to read");
    }
    return layer;
}

std::unique_ptr<Layer> readCrateBytes(std::vector<char> bytes, const std::string& identifier) {
    return readCrateBytes(holdBytes(std::move(bytes)), identifier);
}

std::unique_ptr<Layer> readCrateFile(const std::string& path) { return readCrateBytes(mapFile(path), path); }

}  // namespace fluence::usd
