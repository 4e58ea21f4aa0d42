#include "scene/usda_writer.h"

#include <functional>
#include <vector>

#include "scene/usda_value_writer.h"

namespace fluence::usd {

namespace {

using detail::quoteString;

const char* listOpWord(ListOpKind op) {
    switch (op) {
        case ListOpKind::Prepend: return "prepend ";
        case ListOpKind::Append: return "append ";
        case ListOpKind::Delete: return "delete ";
        case ListOpKind::Add: return "add ";
        case ListOpKind::Reorder: return "reorder ";
        case ListOpKind::Explicit: break;
    }
    return "";
}

const char* specifierWord(Specifier specifier) {
    switch (specifier) {
        case Specifier::Def: return "def";
        case Specifier::Over: return "over";
        case Specifier::Class: return "class";
    }
    return "def";
}

// Metadata fields whose value has a shape of its own, which a list op does not turn into a list.
bool takesListOpAsIs(const std::string& key) {
    for (const char* field : {"references", "payload", "payloads", "inherits", "specializes", "subLayers", "relocates",
                              "variants", "variantSets", "customData", "customLayerData", "assetInfo", "sdrMetadata"})
        if (key == field) return true;
    return false;
}

// What a prim, a variant or the layer root holds, for the body writer.
struct Body {
    const Metadata& metadata;
    const std::vector<AttributeSpec>& attributes;
    const std::vector<RelationshipSpec>& relationships;
    const std::vector<std::unique_ptr<PrimSpec>>& children;
    const std::vector<VariantSetSpec>& variantSets;
};

// The metadata of a spec split at its statement entries: runs[0] comes before statements[0],
// runs[i + 1] after statements[i].
struct MetadataRuns {
    std::vector<const MetadataEntry*> statements;
    std::vector<std::vector<const MetadataEntry*>> runs{1};
};

MetadataRuns splitMetadata(const Metadata& metadata, const std::function<bool(const MetadataEntry&)>& isStatement) {
    MetadataRuns split;
    for (const MetadataEntry& entry : metadata) {
        if (isStatement(entry)) {
            split.statements.push_back(&entry);
            split.runs.emplace_back();
        } else {
            split.runs.back().push_back(&entry);
        }
    }
    return split;
}

class Writer {
public:
    std::string write(const Layer& layer) {
        out_ = "#usda 1.0\n";
        auto isRootReorder = [](const MetadataEntry& e) { return e.key == "rootPrims" && e.op == ListOpKind::Reorder; };
        std::vector<const MetadataEntry*> block;
        for (const MetadataEntry& entry : layer.metadata)
            if (!isRootReorder(entry)) block.push_back(&entry);
        if (!block.empty()) {
            out_ += "(\n";
            for (const MetadataEntry* entry : block) writeMetadataEntry(*entry, 1);
            out_ += ")\n";
        }
        for (const MetadataEntry& entry : layer.metadata)
            if (isRootReorder(entry)) writeReorder(entry, 0);
        for (const auto& prim : layer.rootPrims) {
            out_ += '\n';
            writePrim(*prim, 0);
        }
        return std::move(out_);
    }

private:
    void pad(int indent) { out_.append(static_cast<std::size_t>(indent) * 4, ' '); }

    void writeMetadataEntry(const MetadataEntry& entry, int indent) {
        pad(indent);
        out_ += listOpWord(entry.op) + entry.key + " = ";
        if (entry.op != ListOpKind::Explicit && !entry.value.isArray && !takesListOpAsIs(entry.key) &&
            (entry.value.isStringLike() || entry.value.isNumeric())) {
            Value listed = entry.value;  // a list op edits a list
            listed.isArray = true;
            detail::writeMetadataValue(out_, listed, entry.key, indent);
        } else {
            detail::writeMetadataValue(out_, entry.value, entry.key, indent);
        }
        out_ += '\n';
    }

    // " (\n  entries\n)" after a declaration; nothing for no entries.
    void writeMetadataBlock(const std::vector<const MetadataEntry*>& entries, int indent) {
        if (entries.empty()) return;
        out_ += " (\n";
        for (const MetadataEntry* entry : entries) writeMetadataEntry(*entry, indent + 1);
        pad(indent);
        out_ += ')';
    }

    void writeReorder(const MetadataEntry& entry, int indent) {
        pad(indent);
        out_ += "reorder " + entry.key + " = ";
        Value names = entry.value;
        names.isArray = true;
        detail::writeMetadataValue(out_, names, "", indent);
        out_ += '\n';
    }

    // <path>, or a [...] list with a path a line.
    void writeTargets(const std::vector<std::string>& paths, int indent) {
        if (paths.size() == 1) {
            out_ += "<" + paths.front() + ">";
            return;
        }
        out_ += "[";
        for (std::size_t i = 0; i < paths.size(); ++i) {
            out_ += '\n';
            pad(indent + 1);
            out_ += "<" + paths[i] + ">" + (i + 1 < paths.size() ? "," : "");
        }
        out_ += '\n';
        pad(indent);
        out_ += "]";
    }

    void writePrim(const PrimSpec& prim, int indent) {
        pad(indent);
        out_ += specifierWord(prim.specifier);
        if (!prim.typeName.empty()) out_.append(" ").append(prim.typeName);
        out_.append(" ").append(quoteString(prim.name));
        writeMetadataBlock(blockEntries(prim.metadata), indent);
        out_ += '\n';
        pad(indent);
        out_ += "{\n";
        writeBody({prim.metadata, prim.attributes, prim.relationships, prim.children, prim.variantSets}, indent + 1);
        pad(indent);
        out_ += "}\n";
    }

    static bool isBodyReorder(const MetadataEntry& entry) {
        return entry.op == ListOpKind::Reorder && (entry.key == "nameChildren" || entry.key == "properties");
    }

    static std::vector<const MetadataEntry*> blockEntries(const Metadata& metadata) {
        std::vector<const MetadataEntry*> entries;
        for (const MetadataEntry& entry : metadata)
            if (!isBodyReorder(entry)) entries.push_back(&entry);
        return entries;
    }

    void writeBody(const Body& body, int indent) {
        for (const MetadataEntry& entry : body.metadata)
            if (isBodyReorder(entry)) writeReorder(entry, indent);
        for (const AttributeSpec& attribute : body.attributes) writeAttribute(attribute, indent);
        for (const RelationshipSpec& relationship : body.relationships) writeRelationship(relationship, indent);
        for (const auto& child : body.children) {
            separate();
            writePrim(*child, indent);
        }
        for (const VariantSetSpec& set : body.variantSets) {
            separate();
            writeVariantSet(set, indent);
        }
    }

    // A blank line between a block's statements and the next prim or variant set.
    void separate() {
        if (!out_.ends_with("{\n")) out_ += '\n';
    }

    void writeVariantSet(const VariantSetSpec& set, int indent) {
        pad(indent);
        out_ += "variantSet " + quoteString(set.name) + " = {\n";
        for (const VariantSpec& variant : set.variants) {
            pad(indent + 1);
            out_ += quoteString(variant.name);
            writeMetadataBlock(blockEntries(variant.metadata), indent + 1);
            out_ += " {\n";
            writeBody(
                {variant.metadata, variant.attributes, variant.relationships, variant.children, variant.variantSets},
                indent + 2);
            pad(indent + 1);
            out_ += "}\n";
        }
        pad(indent);
        out_ += "}\n";
    }

    void writeAttribute(const AttributeSpec& attribute, int indent) {
        // 'custom' only on the plain declaration: Sdf's grammar refuses it on .timeSamples and
        // .connect statements, so a custom attribute always gets one.
        const std::string declaration =
            std::string(attribute.uniform ? "uniform " : "") + attribute.typeName + " " + attribute.name;
        MetadataRuns metadata = splitMetadata(attribute.metadata, [](const MetadataEntry& e) {
            return e.key == "connectionPaths" && e.op != ListOpKind::Explicit;
        });
        const bool hasConnections = !attribute.connections.empty();
        const bool declared = attribute.custom || attribute.hasDefault || !metadata.runs[0].empty() ||
                              (attribute.timeSamples.empty() && !hasConnections && metadata.statements.empty());
        if (declared) {
            pad(indent);
            out_ += std::string(attribute.custom ? "custom " : "") + declaration;
            if (attribute.hasDefault) {
                out_ += " = ";
                detail::writeTypedValue(out_, attribute.defaultValue, attribute.typeName, indent);
            }
            writeMetadataBlock(metadata.runs[0], indent);
            out_ += '\n';
        }
        if (!attribute.timeSamples.empty()) {
            pad(indent);
            out_ += declaration + ".timeSamples = {\n";
            for (const auto& [time, value] : attribute.timeSamples) {
                pad(indent + 1);
                out_ += detail::formatNumber(time, "") + ": ";
                detail::writeTypedValue(out_, value, attribute.typeName, indent + 1);
                out_ += ",\n";
            }
            pad(indent);
            out_ += "}\n";
        }
        if (hasConnections) {
            pad(indent);
            out_ += listOpWord(attribute.connectionOp) + declaration + ".connect = ";
            writeTargets(attribute.connections, indent);
            out_ += '\n';
        }
        for (std::size_t i = 0; i < metadata.statements.size(); ++i) {
            const MetadataEntry& edit = *metadata.statements[i];
            pad(indent);
            out_ += listOpWord(edit.op) + declaration + ".connect = ";
            writeTargets(edit.value.strings, indent);
            out_ += '\n';
            writeDeclaration(declaration, metadata.runs[i + 1], indent);
        }
    }

    void writeRelationship(const RelationshipSpec& relationship, int indent) {
        const std::string declaration = std::string(relationship.custom ? "custom " : "") + "rel " + relationship.name;
        MetadataRuns metadata = splitMetadata(relationship.metadata, [](const MetadataEntry& e) {
            return (e.key == "targetPaths" && e.op != ListOpKind::Explicit) ||
                   (e.key == "timeSamples" && e.op == ListOpKind::Explicit && e.value.kind == ValueKind::Dictionary);
        });
        const bool assigned = !relationship.targets.empty() || relationship.blocked;
        // Sdf's grammar takes metadata only on an explicit statement: list-edited targets get
        // their own statement and the metadata a plain declaration after it.
        const bool listEdited = !relationship.targets.empty() && relationship.op != ListOpKind::Explicit;
        if (assigned || !metadata.runs[0].empty() || metadata.statements.empty()) {
            pad(indent);
            if (!relationship.targets.empty()) out_ += listOpWord(relationship.op);
            out_ += declaration;
            if (relationship.blocked) {
                out_ += " = None";
            } else if (!relationship.targets.empty()) {
                out_ += " = ";
                writeTargets(relationship.targets, indent);
            }
            if (!listEdited) writeMetadataBlock(metadata.runs[0], indent);
            out_ += '\n';
            if (listEdited) writeDeclaration(declaration, metadata.runs[0], indent);
        }
        for (std::size_t i = 0; i < metadata.statements.size(); ++i) {
            const MetadataEntry& statement = *metadata.statements[i];
            pad(indent);
            if (statement.key == "timeSamples") {
                out_ += declaration + ".timeSamples = {\n";
                for (const auto& [time, target] :
                     statement.value.dictionary ? *statement.value.dictionary : Dictionary{}) {
                    pad(indent + 1);
                    out_ +=
                        time + ": " + (target.strings.empty() ? "None" : "<" + target.strings.front() + ">") + ",\n";
                }
                pad(indent);
                out_ += "}\n";
            } else {
                out_ += listOpWord(statement.op) + declaration + " = ";
                writeTargets(statement.value.strings, indent);
                out_ += '\n';
            }
            writeDeclaration(declaration, metadata.runs[i + 1], indent);
        }
    }

    // `declaration (metadata)` for metadata entries authored after a statement entry.
    void writeDeclaration(const std::string& declaration, const std::vector<const MetadataEntry*>& entries,
                          int indent) {
        if (entries.empty()) return;
        pad(indent);
        out_ += declaration;
        writeMetadataBlock(entries, indent);
        out_ += '\n';
    }

    std::string out_;
};

}  // namespace

std::string writeUsda(const Layer& layer) { return Writer().write(layer); }

}  // namespace fluence::usd
