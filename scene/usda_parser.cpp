// The USDA reader: the header check, then a recursive-descent parser over the lexer's tokens.
//
// Grammar (sep is ';' or a line break; every statement ends with one):
//   layer          := header [metadataBlock sep] (rootStatement sep)*
//   header         := ('#usda' | '#sdf') version             (the whole first line)
//   rootStatement  := prim | 'reorder' 'rootPrims' '=' nameList
//   prim           := ('def' | 'over' | 'class') [typeName ('.' typeName)*] string
//                         [metadataBlock] '{' body '}'
//   body           := (bodyStatement sep)*
//   bodyStatement  := prim | variantSet | reorder | attribute | relationship
//   variantSet     := 'variantSet' string '=' '{' (string [metadataBlock] '{' body '}')* '}'
//   reorder        := 'reorder' ('nameChildren' | 'properties') '=' nameList
//   attribute      := [listOp] ['custom'] ['uniform' | 'config'] typeName ['[' ']'] name
//                         ( ['=' typedValue] [metadataBlock]
//                         | '.' 'connect' '=' targets
//                         | '.' 'timeSamples' '=' '{' (time ':' typedValue),* '}' )
//                     ('custom' only without a field, a list op only with '.connect'; names
//                     are identifiers joined by ':', never '::')
//   relationship   := [listOp] ['custom'] ['varying'] 'rel' name
//                         ( ['=' targets] [metadataBlock]              (metadata without listOp)
//                         | '.' 'default' '=' path                 (no list op)
//                         | '.' 'timeSamples' '=' '{' (time ':' (path | 'None')),* '}' )
//   targets        := 'None' | path | '[' path,* ']'
//   time           := number | 'inf' | 'nan'                   (a sample at nan is left out)
//   metadataBlock  := '(' (metadataEntry sep)* ')'
//   metadataEntry  := string                                     (the doc string)
//                   | [listOp] identifier '=' metadataValue
//   listOp         := 'prepend' | 'append' | 'delete' | 'add' | 'reorder'
// Values (typedValue, metadataValue, dictionaries, layer offsets) are described in
// usda_value_parser.h. A value starts on the line of its '='. Metadata values are generic except
// for keys with a fixed shape: references/payload (references with layer offsets),
// inherits/specializes (prim paths), subLayers (assets with layer offsets), relocates (a path
// map), variants (string selections), the dictionaries (customData, customLayerData, assetInfo,
// sdrMetadata), bools (active, hidden, instanceable, noLoadHint: read as bool values, stored as
// 0 or 1), kind (a string, on prims and variants), permission
// (public or private) and displayUnit (a unit name of Sdf's registry). Other keys take a list op
// only with a [...] list value.
//
// Where the Layer structs have no field, statements are kept as metadata entries:
// `reorder rootPrims` on the layer; `delete`/`reorder` of relationship targets and connections
// as "targetPaths"/"connectionPaths" on the property (other list ops set the spec's own op and
// paths; the last such statement wins); relationship time samples as a "timeSamples" dictionary
// keyed by the time's text. Variant sets nested inside a variant are kept in that variant's
// `variantSets`.
#include "scene/usda_parser.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <unordered_map>
#include <unordered_set>
#include <utility>

#include "scene/usda_lexer.h"
#include "scene/usda_metadata_fields.h"
#include "scene/usda_names.h"
#include "scene/usda_value_parser.h"

namespace fluence::usd {

ParseError::ParseError(SourceLocation location, const std::string& message)
    : std::runtime_error(location.str() + ": " + message), location_(std::move(location)), message_(message) {}

namespace {

using detail::describe;
using detail::Lexer;
using detail::NestingGuard;
using detail::PathRules;
using detail::Token;
using detail::TokenKind;

struct Header {
    std::string text;     // "#usda 1.0"
    std::size_t end = 0;  // offset of the second line
    int nextLine = 2;
};

Header readHeader(std::string_view text, const std::string& file) {
    auto fail = [&](const std::string& message) { throw ParseError({file, 1, 1}, message); };
    if (text.substr(0, 8) == "PXR-USDC") fail("a binary USD crate file, not USDA text (usd::readLayerFile reads both)");
    if (text.empty()) fail("empty file: expected a '#usda 1.0' header");
    std::size_t newline = text.find('\n');
    std::string_view line = text.substr(0, newline);
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '\t')) {
        line.remove_suffix(1);
    }
    std::string_view version;
    if (line.substr(0, 6) == "#usda ")
        version = line.substr(6);
    else if (line.substr(0, 5) == "#sdf ")
        version = line.substr(5);
    bool valid = !version.empty() && version.find_first_not_of("0123456789.") == std::string_view::npos;
    if (!valid) {
        std::string shown(line.substr(0, 40));
        for (char& c : shown) {
            if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
        }
        fail("expected a '#usda 1.0' header on the first line, found \"" + shown + "\"");
    }
    if (newline == std::string_view::npos) return {std::string(line), text.size(), 1};
    return {std::string(line), newline + 1, 2};
}

std::optional<ListOpKind> listOpOf(const Token& token) {
    if (token.isWord("prepend")) return ListOpKind::Prepend;
    if (token.isWord("append")) return ListOpKind::Append;
    if (token.isWord("delete")) return ListOpKind::Delete;
    if (token.isWord("add")) return ListOpKind::Add;
    if (token.isWord("reorder")) return ListOpKind::Reorder;
    return std::nullopt;
}

std::string listOpName(ListOpKind op) {
    switch (op) {
        case ListOpKind::Prepend: return "prepend";
        case ListOpKind::Append: return "append";
        case ListOpKind::Delete: return "delete";
        case ListOpKind::Add: return "add";
        case ListOpKind::Reorder: return "reorder";
        default: return "explicit";
    }
}

bool isOneOf(std::string_view key, std::initializer_list<std::string_view> keys) {
    return std::find(keys.begin(), keys.end(), key) != keys.end();
}

std::string lineColumn(const SourceLocation& location) {
    return std::to_string(location.line) + ":" + std::to_string(location.column);
}

// "/World" + "Box" -> "/World/Box"; inside a variant "/World{v=a}" + "Box" -> "/World{v=a}Box".
std::string childPath(const std::string& parent, const std::string& name) {
    if (parent.empty()) return "/" + name;
    if (parent.back() == '}') return parent + name;
    return parent + "/" + name;
}

Value pathArray(std::vector<std::string> paths) { return Value::string("", ValueKind::Path, std::move(paths), true); }

// The prim a spec belongs to, for relative paths: its path and its number of prim names.
struct Anchor {
    std::string path;
    int depth = 0;
};

// A prim (or variant, or the layer root) whose statements are being parsed.
struct Body {
    Anchor anchor;
    Metadata* metadata = nullptr;
    std::vector<AttributeSpec>* attributes = nullptr;  // null at the layer root
    std::vector<RelationshipSpec>* relationships = nullptr;
    std::vector<std::unique_ptr<PrimSpec>>* children = nullptr;
    std::vector<VariantSetSpec>* variantSets = nullptr;
    std::unordered_map<std::string, SourceLocation> childNames;
    std::unordered_map<std::string, std::size_t> attributeIndex;
    std::unordered_map<std::string, std::size_t> relationshipIndex;
};

// Whose metadata a block is: Sdf's schema registers different fields per spec type (variants
// take a prim's).
enum class SpecKind { Layer, Prim, Property };

struct Targets {
    std::vector<std::string> paths;
    bool blocked = false;    // None
    bool bracketed = false;  // written as a [...] list
    Token start;             // the first token of the value
};

class Parser {
public:
    Parser(std::string_view text, const std::string& identifier)
        : identifier_(identifier),
          header_(readHeader(text, identifier)),
          lexer_(text, identifier, header_.end, header_.nextLine),
          values_(lexer_) {}

    std::unique_ptr<Layer> parse();

private:
    void parsePrim(Body& parent);
    void parseBody(Body& body, const Token& open, const std::string& what, const SourceLocation& openedAt);
    void parseBodyStatement(Body& body);
    void parseReorder(Body& body);
    void parseVariantSet(Body& body);
    void parseProperty(Body& body);
    void parseAttribute(Body& body, const Token& first, ListOpKind op, const std::optional<Token>& custom,
                        bool uniform);
    void parseRelationship(Body& body, const Token& first, ListOpKind op, bool custom);
    AttributeSpec& attributeFor(Body& body, const Token& name, const std::string& typeName, bool custom, bool uniform,
                                const Token& first);
    RelationshipSpec& relationshipFor(Body& body, const Token& name, bool custom, const Token& first);
    std::vector<std::pair<double, Value>> parseTimeSamples(std::string_view type, bool isArray);
    Value parseRelationshipTimeSamples(const Anchor& anchor);
    std::optional<double> parseTime();
    Targets parseTargets(const PathRules& rules, const Anchor& anchor, const std::string& context,
                         bool forbidDuplicates);
    void checkListOp(ListOpKind op, const Targets& targets);

    void parseMetadataBlock(Metadata& out, const Anchor& anchor, const std::string& owner, SpecKind spec);
    void parseMetadataEntry(Metadata& out, const Anchor& anchor, SpecKind spec);
    Value parseMetadataValue(const std::string& key, ListOpKind op, const Anchor& anchor, SpecKind spec);
    Value parseArcs(const Anchor& anchor);
    Value parseReference(const Anchor& anchor);
    Value parseSubLayers();
    Value parseRelocates(const Anchor& anchor);
    Value parseVariantSelections();

    void checkPath(const Token& path, const PathRules& rules, const Anchor& anchor);
    void checkPropertyName(const Token& name, const std::string& what);
    Token expect(char punct, const std::string& after);
    void expectValueOnSameLine();
    void endStatement(const std::string& what);
    SourceLocation locate(const Token& token) const { return {identifier_, token.line, token.column}; }

    void warn(const Token& at, std::string message) { warnings_.push_back({locate(at), std::move(message)}); }

    std::string identifier_;
    Header header_;
    Lexer lexer_;
    detail::ValueParser values_;
    std::vector<ParseWarning> warnings_;
};

std::unique_ptr<Layer> Parser::parse() {
    auto layer = std::make_unique<Layer>();
    layer->identifier = identifier_;
    layer->header = header_.text;
    Body root;
    root.metadata = &layer->metadata;
    root.children = &layer->rootPrims;
    if (lexer_.peek().is('(')) {
        parseMetadataBlock(layer->metadata, root.anchor, "the layer", SpecKind::Layer);
        endStatement("the layer metadata");
    }
    while (lexer_.peek().kind != TokenKind::End) {
        const Token& token = lexer_.peek();
        if (token.isWord("def") || token.isWord("over") || token.isWord("class")) {
            parsePrim(root);
        } else if (token.isWord("reorder") && lexer_.peek(1).isWord("rootPrims")) {
            parseReorder(root);
        } else {
            lexer_.fail(token, "expected 'def', 'over' or 'class' to start a prim, found " + describe(token));
        }
    }
    layer->warnings = std::move(warnings_);
    return layer;
}

// ---- Structure: prims, bodies, variant sets --------------------------------------------------

void Parser::parsePrim(Body& parent) {
    Token specifier = lexer_.take();
    auto prim = std::make_unique<PrimSpec>();
    prim->specifier = specifier.isWord("def")    ? Specifier::Def
                      : specifier.isWord("over") ? Specifier::Over
                                                 : Specifier::Class;
    prim->location = locate(specifier);
    std::string written(specifier.text);
    if (lexer_.peek().kind == TokenKind::Identifier && !lexer_.peek().newlineBefore) {
        // Sdf's prim_type_name: identifiers joined by '.' (a Python-qualified name).
        prim->typeName = lexer_.take().text;
        while (lexer_.peek().is('.') && !lexer_.peek().newlineBefore && lexer_.peek(1).kind == TokenKind::Identifier &&
               !lexer_.peek(1).newlineBefore) {
            lexer_.skip();
            prim->typeName += "." + std::string(lexer_.take().text);
        }
        written += " " + prim->typeName;
    }
    Token name = lexer_.take();
    if (name.kind != TokenKind::String || name.newlineBefore) {
        lexer_.fail(name, "expected a prim name (a quoted string) after '" + written + "', found " + describe(name));
    }
    if (std::string problem = detail::identifierProblem(name.value); !problem.empty()) {
        lexer_.fail(name, "invalid prim name \"" + name.value + "\": " + problem +
                              " (a name is a letter or '_', then letters, digits or '_': Unicode "
                              "XID_Start, then XID_Continue)");
    }
    auto [previous, unique] = parent.childNames.emplace(name.value, locate(name));
    if (!unique) {
        lexer_.fail(name,
                    "duplicate prim \"" + name.value + "\" (already defined at " + lineColumn(previous->second) + ")");
    }
    prim->name = name.value;
    prim->path = childPath(parent.anchor.path, prim->name);
    std::string what = "prim \"" + prim->name + "\"";

    Body body;
    body.anchor = {prim->path, parent.anchor.depth + 1};
    if (lexer_.peek().is('(')) parseMetadataBlock(prim->metadata, body.anchor, what, SpecKind::Prim);
    Token open = lexer_.take();
    if (!open.is('{')) {
        lexer_.fail(open, "expected '{' to open the body of " + what + ", found " + describe(open));
    }
    body.metadata = &prim->metadata;
    body.attributes = &prim->attributes;
    body.relationships = &prim->relationships;
    body.children = &prim->children;
    body.variantSets = &prim->variantSets;
    parseBody(body, open, what, prim->location);
    parent.children->push_back(std::move(prim));
    endStatement(what);
}

void Parser::parseBody(Body& body, const Token& open, const std::string& what, const SourceLocation& openedAt) {
    NestingGuard guard(lexer_, open);
    while (!lexer_.peek().is('}')) {
        const Token& token = lexer_.peek();
        if (token.kind == TokenKind::End) {
            lexer_.fail(token,
                        "unexpected end of file, expected '}' to close " + what + " opened at " + lineColumn(openedAt));
        }
        parseBodyStatement(body);
    }
    lexer_.skip();
}

void Parser::parseBodyStatement(Body& body) {
    const Token& token = lexer_.peek();
    if (token.kind != TokenKind::Identifier) {
        lexer_.fail(token, "expected a prim, a property, 'variantSet' or '}', found " + describe(token));
    }
    if (token.isWord("def") || token.isWord("over") || token.isWord("class")) {
        parsePrim(body);
    } else if (token.isWord("variantSet")) {
        parseVariantSet(body);
    } else if (token.isWord("reorder") &&
               (lexer_.peek(1).isWord("nameChildren") || lexer_.peek(1).isWord("properties")) &&
               lexer_.peek(2).is('=')) {
        parseReorder(body);
    } else {
        parseProperty(body);
    }
}

void Parser::parseReorder(Body& body) {
    Token keyword = lexer_.take();
    Token what = lexer_.take();
    std::string key(what.text);
    expect('=', "'reorder " + key + "'");
    expectValueOnSameLine();
    Value names = values_.parseNameList("'reorder " + key + "'");
    body.metadata->push_back({key, ListOpKind::Reorder, std::move(names), locate(keyword)});
    endStatement("'reorder " + key + "'");
}

void Parser::parseVariantSet(Body& body) {
    Token keyword = lexer_.take();
    Token name = lexer_.take();
    if (name.kind != TokenKind::String || name.newlineBefore) {
        lexer_.fail(name, "expected a variant set name (a quoted string) after 'variantSet', found " + describe(name));
    }
    std::string what = "variantSet \"" + name.value + "\"";
    expect('=', what);
    Token open = expect('{', what + " =");
    NestingGuard guard(lexer_, open);
    VariantSetSpec set;
    set.name = name.value;
    set.location = locate(keyword);
    while (true) {
        Token variantName = lexer_.take();
        if (variantName.is('}')) break;
        if (variantName.kind == TokenKind::End) {
            lexer_.fail(variantName, "unexpected end of file, expected '}' to close " + what + " opened at " +
                                         lineColumn(set.location));
        }
        if (variantName.kind != TokenKind::String) {
            lexer_.fail(variantName,
                        "expected a variant name (a quoted string) in " + what + ", found " + describe(variantName));
        }
        if (!detail::isVariantName(variantName.value)) {
            lexer_.fail(variantName, "invalid variant name \"" + variantName.value + "\"");
        }
        VariantSpec variant;
        variant.name = variantName.value;
        std::string variantWhat = "variant \"" + variant.name + "\" of " + what;
        Body variantBody;
        variantBody.anchor = {body.anchor.path + "{" + set.name + "=" + variant.name + "}", body.anchor.depth};
        if (lexer_.peek().is('(')) {
            parseMetadataBlock(variant.metadata, variantBody.anchor, variantWhat, SpecKind::Prim);
        }
        Token bodyOpen = lexer_.take();
        if (!bodyOpen.is('{')) {
            lexer_.fail(bodyOpen, "expected '{' to open the body of " + variantWhat + ", found " + describe(bodyOpen));
        }
        variantBody.metadata = &variant.metadata;
        variantBody.attributes = &variant.attributes;
        variantBody.relationships = &variant.relationships;
        variantBody.children = &variant.children;
        variantBody.variantSets = &variant.variantSets;
        parseBody(variantBody, bodyOpen, variantWhat, locate(variantName));
        set.variants.push_back(std::move(variant));
    }
    body.variantSets->push_back(std::move(set));
    endStatement(what);
}

// ---- Properties --------------------------------------------------------------------------------

void Parser::parseProperty(Body& body) {
    Token first = lexer_.peek();
    ListOpKind op = ListOpKind::Explicit;
    if (auto listOp = listOpOf(first)) {
        op = *listOp;
        lexer_.skip();
    }
    std::optional<Token> custom;
    if (lexer_.peek().isWord("custom")) custom = lexer_.take();
    std::optional<Token> variability;
    const Token& next = lexer_.peek();
    if (next.isWord("uniform") || next.isWord("varying") || next.isWord("config")) {
        variability = lexer_.take();
    }
    if (lexer_.peek().isWord("rel")) {
        if (variability && !variability->isWord("varying")) {
            lexer_.fail(*variability, "relationships cannot be '" + std::string(variability->text) + "'");
        }
        parseRelationship(body, first, op, custom.has_value());
    } else {
        // Sdf's prim_attr_variability: 'uniform' or the legacy 'config' (read as uniform);
        // attributes are varying unless declared uniform, and 'varying' is not written.
        if (variability && variability->isWord("varying")) {
            lexer_.fail(*variability,
                        "attributes cannot be declared 'varying' (only "
                        "relationships; an attribute is varying unless 'uniform')");
        }
        parseAttribute(body, first, op, custom, variability.has_value());
    }
}

void Parser::parseAttribute(Body& body, const Token& first, ListOpKind op, const std::optional<Token>& custom,
                            bool uniform) {
    Token type = lexer_.take();
    if (type.kind != TokenKind::Identifier) {
        lexer_.fail(type, "expected a property type name or 'rel', found " + describe(type));
    }
    bool isArray = lexer_.peek().is('[');
    if (isArray) {
        lexer_.skip();
        expect(']', "'[' in type '" + std::string(type.text) + "'");
    }
    std::string typeName = std::string(type.text) + (isArray ? "[]" : "");
    Token name = lexer_.take();
    if (name.kind != TokenKind::Identifier || name.newlineBefore) {
        lexer_.fail(name, "expected an attribute name after type '" + typeName + "', found " + describe(name));
    }
    checkPropertyName(name, "attribute");
    std::string field;
    if (lexer_.peek().is('.') && !lexer_.peek().newlineBefore) {
        lexer_.skip();
        Token fieldToken = lexer_.take();
        field = fieldToken.text;
        if (fieldToken.kind != TokenKind::Identifier || (field != "connect" && field != "timeSamples")) {
            lexer_.fail(fieldToken, field == "spline"
                                        ? "attribute splines ('.spline') are not supported"
                                        : "expected 'connect' or 'timeSamples' after '" + std::string(name.text) +
                                              ".', found " + describe(fieldToken));
        }
    }
    if (custom && !field.empty()) {
        lexer_.fail(*custom, "'custom' cannot be used with '" + std::string(name.text) + "." + field +
                                 "' (declare the attribute custom in its own statement)");
    }
    if (field != "connect" && op != ListOpKind::Explicit) {
        lexer_.fail(first,
                    "'" + listOpName(op) + "' can only edit connections (name.connect) and relationship targets");
    }
    if (!detail::findValueType(type.text))
        warn(type, "unknown value type '" + std::string(type.text) + "' for attribute '" + std::string(name.text) +
                       "'; its value is kept untyped");
    AttributeSpec& attribute = attributeFor(body, name, typeName, custom.has_value(), uniform, first);
    std::string what = "attribute '" + attribute.name + "'";
    if (field == "connect") {
        expect('=', "'" + attribute.name + ".connect'");
        expectValueOnSameLine();
        Targets targets = parseTargets({}, body.anchor, "the connections of " + what, true);
        checkListOp(op, targets);
        if (op == ListOpKind::Delete || op == ListOpKind::Reorder) {
            attribute.metadata.push_back({"connectionPaths", op, pathArray(std::move(targets.paths)), locate(first)});
        } else {
            attribute.connections = std::move(targets.paths);
            attribute.connectionOp = op;
        }
    } else if (field == "timeSamples") {
        expect('=', "'" + attribute.name + ".timeSamples'");
        expectValueOnSameLine();
        attribute.timeSamples = parseTimeSamples(type.text, isArray);
    } else {
        const Token& next = lexer_.peek();
        if (next.is('=')) {
            lexer_.skip();
            expectValueOnSameLine();
            attribute.defaultValue = values_.parseTyped(type.text, isArray);
            attribute.hasDefault = true;
        } else if (!next.is('(') && !next.is(';') && !next.newlineBefore && next.kind != TokenKind::End) {
            lexer_.fail(next, "expected '=' after attribute name '" + attribute.name + "', found " + describe(next));
        }
        if (lexer_.peek().is('(') && !lexer_.peek().newlineBefore) {
            parseMetadataBlock(attribute.metadata, body.anchor, what, SpecKind::Property);
        }
    }
    endStatement(what);
}

void Parser::parseRelationship(Body& body, const Token& first, ListOpKind op, bool custom) {
    lexer_.skip();  // rel
    Token name = lexer_.take();
    if (name.kind != TokenKind::Identifier || name.newlineBefore) {
        lexer_.fail(name, "expected a relationship name after 'rel', found " + describe(name));
    }
    checkPropertyName(name, "relationship");
    std::string field;
    if (lexer_.peek().is('.') && !lexer_.peek().newlineBefore) {
        lexer_.skip();
        Token fieldToken = lexer_.take();
        field = fieldToken.text;
        if (fieldToken.kind != TokenKind::Identifier || (field != "default" && field != "timeSamples")) {
            lexer_.fail(fieldToken, "expected 'default' or 'timeSamples' after '" + std::string(name.text) +
                                        ".', found " + describe(fieldToken));
        }
    }
    RelationshipSpec& relationship = relationshipFor(body, name, custom, first);
    std::string what = "relationship '" + relationship.name + "'";
    if (field == "timeSamples") {
        if (op != ListOpKind::Explicit) {
            lexer_.fail(first, "'" + listOpName(op) + "' cannot be used with time samples");
        }
        expect('=', "'" + relationship.name + ".timeSamples'");
        expectValueOnSameLine();
        relationship.metadata.push_back(
            {"timeSamples", ListOpKind::Explicit, parseRelationshipTimeSamples(body.anchor), locate(first)});
        endStatement(what);
        return;
    }
    bool assigned = field == "default";
    if (assigned) {
        // Sdf's prim_relationship_default: one path, no list op, no metadata.
        if (op != ListOpKind::Explicit) {
            lexer_.fail(first, "'" + listOpName(op) + "' cannot be used with '" + relationship.name + ".default'");
        }
        expect('=', "'" + relationship.name + ".default'");
        const Token& value = lexer_.peek();
        if (value.kind != TokenKind::Path && !value.newlineBefore) {
            lexer_.fail(value,
                        "expected a path <...> for '" + relationship.name + ".default', found " + describe(value));
        }
    } else if (lexer_.peek().is('=')) {
        lexer_.skip();
        assigned = true;
    } else {
        const Token& next = lexer_.peek();
        if (!next.is('(') && !next.is(';') && !next.newlineBefore && next.kind != TokenKind::End) {
            lexer_.fail(next,
                        "expected '=' after relationship name '" + relationship.name + "', found " + describe(next));
        }
    }
    if (assigned) {
        expectValueOnSameLine();
        Targets targets = parseTargets({}, body.anchor, "the targets of " + what, true);
        checkListOp(op, targets);
        if (op == ListOpKind::Delete || op == ListOpKind::Reorder) {
            relationship.metadata.push_back({"targetPaths", op, pathArray(std::move(targets.paths)), locate(first)});
        } else {
            relationship.op = op;
            relationship.targets = std::move(targets.paths);
            relationship.blocked = targets.blocked;
        }
    }
    if (field != "default" && lexer_.peek().is('(') && !lexer_.peek().newlineBefore) {
        // Sdf's prim_relationship: only the explicit statement takes relationship_metadata_list_opt.
        if (op != ListOpKind::Explicit) {
            lexer_.fail(lexer_.peek(), "metadata cannot follow '" + listOpName(op) + "' on " + what +
                                           " (give it in its own statement: rel " + relationship.name + " (...))");
        }
        parseMetadataBlock(relationship.metadata, body.anchor, what, SpecKind::Property);
    }
    endStatement(what);
}

AttributeSpec& Parser::attributeFor(Body& body, const Token& name, const std::string& typeName, bool custom,
                                    bool uniform, const Token& first) {
    std::string attributeName(name.text);
    auto [slot, added] = body.attributeIndex.emplace(attributeName, body.attributes->size());
    if (added) {
        AttributeSpec& attribute = body.attributes->emplace_back();
        attribute.name = std::move(attributeName);
        attribute.typeName = typeName;
        attribute.custom = custom;
        attribute.uniform = uniform;
        attribute.location = locate(first);
        return attribute;
    }
    AttributeSpec& attribute = (*body.attributes)[slot->second];
    if (attribute.typeName != typeName) {
        lexer_.fail(name, "attribute '" + attribute.name + "' redeclared with type '" + typeName + "' (declared '" +
                              attribute.typeName + "' at " + lineColumn(attribute.location) + ")");
    }
    if (attribute.uniform != uniform) {
        lexer_.fail(name, "attribute '" + attribute.name + "' redeclared with a different variability (declared at " +
                              lineColumn(attribute.location) + ")");
    }
    attribute.custom = attribute.custom || custom;
    return attribute;
}

RelationshipSpec& Parser::relationshipFor(Body& body, const Token& name, bool custom, const Token& first) {
    std::string relationshipName(name.text);
    auto [slot, added] = body.relationshipIndex.emplace(relationshipName, body.relationships->size());
    if (added) {
        RelationshipSpec& relationship = body.relationships->emplace_back();
        relationship.name = std::move(relationshipName);
        relationship.custom = custom;
        relationship.location = locate(first);
        return relationship;
    }
    RelationshipSpec& relationship = (*body.relationships)[slot->second];
    relationship.custom = relationship.custom || custom;
    return relationship;
}

std::vector<std::pair<double, Value>> Parser::parseTimeSamples(std::string_view type, bool isArray) {
    Token open = lexer_.take();
    if (!open.is('{')) lexer_.fail(open, "expected '{' to start time samples, found " + describe(open));
    NestingGuard guard(lexer_, open);
    std::vector<std::pair<double, Value>> samples;
    values_.parseSeparated(open, '}', "the time samples", [&] {
        std::optional<double> time = parseTime();
        Value value = values_.parseTyped(type, isArray);
        if (time) samples.emplace_back(*time, std::move(value));
    });
    // Sorted by time; a time authored twice keeps its last value.
    std::stable_sort(samples.begin(), samples.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<std::pair<double, Value>> unique;
    unique.reserve(samples.size());
    for (auto& sample : samples) {
        if (!unique.empty() && unique.back().first == sample.first)
            unique.back() = std::move(sample);
        else
            unique.push_back(std::move(sample));
    }
    return unique;
}

// A sample's time and its ':'. Sdf's extended_number: a number (-inf included), or a word read
// as a double, which only inf and nan are. A sample at nan has no place on the time line (Sdf's
// std::map cannot order it): it is read, warned about and left out (nullopt).
std::optional<double> Parser::parseTime() {
    Token time = lexer_.take();
    double value = time.number;
    if (time.isWord("inf")) {
        value = std::numeric_limits<double>::infinity();
    } else if (time.isWord("nan")) {
        value = std::numeric_limits<double>::quiet_NaN();
    } else if (time.kind != TokenKind::Number) {
        lexer_.fail(time, "expected a time code (a number, inf or nan) in time samples, found " + describe(time));
    }
    expect(':', "time code " + std::string(time.text));
    if (std::isnan(value)) {
        warn(time, "a time sample at nan cannot be ordered in time; it is left out");
        return std::nullopt;
    }
    return value;
}

Value Parser::parseRelationshipTimeSamples(const Anchor& anchor) {
    Token open = lexer_.take();
    if (!open.is('{')) lexer_.fail(open, "expected '{' to start time samples, found " + describe(open));
    auto samples = std::make_shared<Dictionary>();
    values_.parseSeparated(open, '}', "the time samples", [&] {
        const Token& timeToken = lexer_.peek();
        std::string text(timeToken.text);
        std::optional<double> time = parseTime();
        Token target = lexer_.take();
        Value value;
        if (target.kind == TokenKind::Path) {
            checkPath(target, {}, anchor);
            value = Value::string("", ValueKind::Path, {target.value}, false);
        } else if (!target.isWord("None")) {
            lexer_.fail(target, "expected a path <...> or None, found " + describe(target));
        }
        if (time) samples->emplace_back(std::move(text), std::move(value));
    });
    Value dictionary;
    dictionary.kind = ValueKind::Dictionary;
    dictionary.dictionary = std::move(samples);
    return dictionary;
}

Targets Parser::parseTargets(const PathRules& rules, const Anchor& anchor, const std::string& context,
                             bool forbidDuplicates) {
    Targets targets;
    targets.start = lexer_.take();
    const Token& start = targets.start;
    if (start.isWord("None")) {
        targets.blocked = true;
    } else if (start.kind == TokenKind::Path) {
        checkPath(start, rules, anchor);
        targets.paths.push_back(start.value);
    } else if (start.is('[')) {
        targets.bracketed = true;
        std::unordered_set<std::string> seen;
        values_.parseSeparated(start, ']', context, [&] {
            Token path = lexer_.take();
            if (path.kind != TokenKind::Path) {
                lexer_.fail(path, "expected a path <...> in " + context + ", found " + describe(path));
            }
            checkPath(path, rules, anchor);
            if (forbidDuplicates && !seen.insert(path.value).second) {
                lexer_.fail(path, "duplicate path <" + path.value + "> in " + context);
            }
            targets.paths.push_back(std::move(path.value));
        });
    } else {
        lexer_.fail(start,
                    "expected a path <...>, a list of paths or None for " + context + ", found " + describe(start));
    }
    return targets;
}

void Parser::checkListOp(ListOpKind op, const Targets& targets) {
    if (op == ListOpKind::Explicit) return;
    if (targets.blocked) {
        lexer_.fail(targets.start, "'None' cannot be used with '" + listOpName(op) + "'");
    }
    if (targets.paths.empty()) {
        lexer_.fail(targets.start, "an empty list cannot be used with '" + listOpName(op) + "'");
    }
}

// ---- Metadata ---------------------------------------------------------------------------------

void Parser::parseMetadataBlock(Metadata& out, const Anchor& anchor, const std::string& owner, SpecKind spec) {
    Token open = lexer_.take();
    while (!lexer_.peek().is(')')) {
        if (lexer_.peek().kind == TokenKind::End) {
            lexer_.fail(lexer_.peek(), "unexpected end of file, expected ')' to close the metadata of " + owner +
                                           " opened at " + lineColumn(locate(open)));
        }
        parseMetadataEntry(out, anchor, spec);
        const Token& next = lexer_.peek();
        if (next.is(';')) {
            lexer_.skip();
        } else if (!next.is(')') && !next.newlineBefore && next.kind != TokenKind::End) {
            lexer_.fail(next, "expected a line break or ';' between metadata entries, found " + describe(next));
        }
    }
    lexer_.skip();
}

void Parser::parseMetadataEntry(Metadata& out, const Anchor& anchor, SpecKind spec) {
    Token first = lexer_.peek();
    if (first.kind == TokenKind::String) {
        lexer_.skip();
        out.push_back(
            {"doc", ListOpKind::Explicit, Value::string("", ValueKind::String, {first.value}, false), locate(first)});
        return;
    }
    ListOpKind op = ListOpKind::Explicit;
    if (auto listOp = listOpOf(first); listOp && lexer_.peek(1).kind == TokenKind::Identifier) {
        op = *listOp;
        lexer_.skip();
    }
    Token key = lexer_.take();
    if (key.kind != TokenKind::Identifier) {
        lexer_.fail(key, "expected a metadata key, found " + describe(key));
    }
    std::string name(key.text);
    if (!detail::isRegisteredMetadataField(name))
        warn(key, "unregistered metadata field '" + name + "'; kept, but nothing reads it");
    expect('=', "metadata key '" + name + "'");
    Value value;
    const Token& next = lexer_.peek();
    bool emptyValue = next.is(')') || next.is(';') || next.newlineBefore;
    if (name == "symmetryFunction" && emptyValue) {
        value = Value::string("", ValueKind::Token, {""}, false);
    } else {
        expectValueOnSameLine();
        value = parseMetadataValue(name, op, anchor, spec);
    }
    out.push_back({std::move(name), op, std::move(value), locate(first)});
}

Value Parser::parseMetadataValue(const std::string& key, ListOpKind op, const Anchor& anchor, SpecKind spec) {
    Token start = lexer_.peek();
    auto failExpecting = [&](const std::string& expected) {
        lexer_.fail(start, "expected " + expected + " for '" + key + "', found " + describe(start));
    };
    if (op != ListOpKind::Explicit && start.isWord("None")) {
        lexer_.fail(start, "'None' cannot be used with '" + listOpName(op) + "'");
    }
    // Sdf's _PrimSet*ListItems: a list op needs arcs to edit with (None is refused above).
    auto failEmptyListOp = [&] {
        lexer_.fail(start, "an empty list cannot be used with '" + listOpName(op) + " " + key + "'");
    };
    if (isOneOf(key, {"references", "payload", "payloads"})) {
        Value arcs = parseArcs(anchor);
        if (op != ListOpKind::Explicit && arcs.kind == ValueKind::List && arcs.items.empty()) failEmptyListOp();
        return arcs;
    }
    if (isOneOf(key, {"inherits", "specializes"})) {
        PathRules primPaths;
        primPaths.primOnly = true;
        Targets targets = parseTargets(primPaths, anchor, "'" + key + "'", false);
        if (op != ListOpKind::Explicit && targets.paths.empty()) failEmptyListOp();
        if (targets.blocked) return Value{};
        return Value::string("", ValueKind::Path, std::move(targets.paths), targets.bracketed);
    }
    if (spec == SpecKind::Layer && key == "subLayers") return parseSubLayers();
    if (key == "relocates") return parseRelocates(anchor);
    if (key == "variants") return parseVariantSelections();
    if (isOneOf(key, {"customData", "customLayerData", "assetInfo", "sdrMetadata"})) {
        if (!start.is('{')) failExpecting("a dictionary {...}");
        return values_.parseDictionary();
    }
    if (op != ListOpKind::Explicit && key != "variantSets" && !start.is('[')) {
        lexer_.fail(start, "'" + listOpName(op) + " " + key + "' needs a list value [...], found " + describe(start));
    }
    if (isOneOf(key, {"active", "hidden", "instanceable", "noLoadHint"})) {
        std::optional<bool> flag = detail::boolFromToken(start);
        if (!flag) failExpecting("a bool (a number, true, false, yes or no)");
        lexer_.skip();
        return Value::numeric("", {*flag ? 1.0 : 0.0}, 1, false);
    }
    if (key == "permission" && !start.isWord("public") && !start.isWord("private")) {
        failExpecting("public or private");
    }
    // Sdf's prim_metadata reads kind as TOK_KIND '=' TOK_STRING; on a layer or a property kind is
    // no field of the spec, so any value is kept unregistered.
    const bool quotedKind = key == "kind" && spec == SpecKind::Prim;
    if ((quotedKind || key == "colorSpace") && start.kind != TokenKind::String) {
        failExpecting("a quoted string");
    }
    if (key == "colorConfiguration" && start.kind != TokenKind::Asset) {
        failExpecting("an asset path @...@");
    }
    if (key == "displayUnit") {
        if (start.kind != TokenKind::Identifier) failExpecting("a unit name");
        if (!detail::isDisplayUnit(start.text)) {
            lexer_.fail(start, "'" + std::string(start.text) + "' is not a valid display unit (one of " +
                                   detail::displayUnitNames() + ")");
        }
    }
    Value value = values_.parseGeneric(true);
    if (key == "variantSets" && value.kind != ValueKind::String &&
        !(value.kind == ValueKind::List && value.items.empty())) {
        failExpecting("a variant set name or a list of names");
    }
    return value;
}

Value Parser::parseArcs(const Anchor& anchor) {
    if (lexer_.peek().isWord("None")) {
        lexer_.skip();
        return Value{};
    }
    if (!lexer_.peek().is('[')) return parseReference(anchor);
    Token open = lexer_.take();
    Value list = Value::list({});
    values_.parseSeparated(open, ']', "the reference list", [&] { list.items.push_back(parseReference(anchor)); });
    return list;
}

Value Parser::parseReference(const Anchor& anchor) {
    Token token = lexer_.take();
    PathRules primPath;
    primPath.primOnly = true;
    primPath.absoluteOnly = true;
    Value reference;
    reference.kind = ValueKind::Reference;
    reference.strings = {"", ""};
    if (token.kind == TokenKind::Asset) {
        if (token.value.empty()) {
            lexer_.fail(token,
                        "empty asset path in a reference (an internal reference is a "
                        "path alone: </Prim>)");
        }
        reference.strings[0] = token.value;
        if (lexer_.peek().kind == TokenKind::Path && !lexer_.peek().newlineBefore) {
            Token path = lexer_.take();
            checkPath(path, primPath, anchor);
            reference.strings[1] = path.value;
        }
    } else if (token.kind == TokenKind::Path) {
        PathRules internal = primPath;
        internal.allowEmpty = true;  // <> alone: the layer's default prim
        checkPath(token, internal, anchor);
        reference.strings[1] = token.value;
    } else {
        lexer_.fail(token, "expected a reference (@asset@, @asset@</prim> or </prim>), found " + describe(token));
    }
    if (lexer_.peek().is('(') && !lexer_.peek().newlineBefore) values_.parseLayerOffset(reference, true);
    return reference;
}

Value Parser::parseSubLayers() {
    Token open = lexer_.take();
    if (!open.is('[')) {
        lexer_.fail(open, "expected a list of asset paths [...] for 'subLayers', found " + describe(open));
    }
    Value list = Value::list({});
    values_.parseSeparated(open, ']', "'subLayers'", [&] {
        Token asset = lexer_.take();
        if (asset.kind != TokenKind::Asset) {
            lexer_.fail(asset, "expected an asset path @...@ in 'subLayers', found " + describe(asset));
        }
        if (asset.value.empty()) lexer_.fail(asset, "empty asset path in 'subLayers'");
        Value subLayer;
        subLayer.kind = ValueKind::Reference;
        subLayer.strings = {std::move(asset.value), ""};
        if (lexer_.peek().is('(') && !lexer_.peek().newlineBefore) {
            values_.parseLayerOffset(subLayer, false);
        }
        list.items.push_back(std::move(subLayer));
    });
    return list;
}

Value Parser::parseRelocates(const Anchor& anchor) {
    Token open = lexer_.take();
    if (!open.is('{')) {
        lexer_.fail(open, "expected a map {<source>: <target>, ...} for 'relocates', found " + describe(open));
    }
    auto entries = std::make_shared<Dictionary>();
    values_.parseSeparated(open, '}', "the 'relocates' map", [&] {
        Token source = lexer_.take();
        if (source.kind != TokenKind::Path) {
            lexer_.fail(source, "expected a source path <...> in 'relocates', found " + describe(source));
        }
        checkPath(source, {}, anchor);
        if (source.value == "/") lexer_.fail(source, "the root path </> cannot be relocated");
        expect(':', "relocates source <" + source.value + ">");
        Token target = lexer_.take();
        if (target.kind != TokenKind::Path) {
            lexer_.fail(target, "expected a target path <...> in 'relocates', found " + describe(target));
        }
        PathRules targetRules;
        targetRules.allowEmpty = true;
        checkPath(target, targetRules, anchor);
        entries->emplace_back(std::move(source.value),
                              Value::string("", ValueKind::Path, {std::move(target.value)}, false));
    });
    Value map;
    map.kind = ValueKind::Dictionary;
    map.dictionary = std::move(entries);
    return map;
}

Value Parser::parseVariantSelections() {
    Token open = lexer_.peek();
    if (!open.is('{')) {
        lexer_.fail(open,
                    "expected variant selections {string set = \"variant\" ...} for "
                    "'variants', found " +
                        describe(open));
    }
    Value selections = values_.parseDictionary();
    for (const auto& [set, selection] : *selections.dictionary) {
        if (selection.typeName != "string") {
            lexer_.fail(open, "the selection for variant set '" + set + "' must be a string, found a '" +
                                  selection.typeName + "' value");
        }
        if (!detail::isVariantSelection(*selection.asString())) {
            lexer_.fail(open,
                        "invalid variant selection \"" + *selection.asString() + "\" for variant set '" + set + "'");
        }
    }
    return selections;
}

// ---- Helpers ----------------------------------------------------------------------------------

void Parser::checkPath(const Token& path, const PathRules& rules, const Anchor& anchor) {
    std::string problem = detail::pathProblem(path.value, rules, anchor.depth);
    if (!problem.empty()) lexer_.fail(path, problem);
}

// A property name is identifiers joined by ':' (Sdf's namespaced_name); the lexer also reads the
// '::' of C++ type names into one identifier, which only type names may hold.
void Parser::checkPropertyName(const Token& name, const std::string& what) {
    if (name.text.find("::") != std::string_view::npos) {
        lexer_.fail(name, "invalid " + what + " name '" + std::string(name.text) +
                              "': '::' may join the parts of a type name, not of a property "
                              "name (namespaces are joined by ':')");
    }
}

Token Parser::expect(char punct, const std::string& after) {
    Token token = lexer_.take();
    if (!token.is(punct)) {
        lexer_.fail(token, std::string("expected '") + punct + "' after " + after + ", found " + describe(token));
    }
    return token;
}

void Parser::expectValueOnSameLine() {
    const Token& token = lexer_.peek();
    if (token.newlineBefore) {
        lexer_.fail(token, "expected a value after '=' on the same line, found " + describe(token));
    }
}

void Parser::endStatement(const std::string& what) {
    const Token& next = lexer_.peek();
    if (next.is(';')) {
        while (lexer_.peek().is(';')) lexer_.take();
        return;
    }
    if (next.newlineBefore || next.kind == TokenKind::End) return;
    lexer_.fail(next, "expected a line break or ';' after " + what + ", found " + describe(next));
}

}  // namespace

std::unique_ptr<Layer> parseUsdaString(std::string_view text, const std::string& identifier) {
    return Parser(text, identifier).parse();
}

std::unique_ptr<Layer> parseUsdaFile(const std::string& path) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error)) {
        throw FileError("cannot open '" + path + "': not a readable file");
    }
    std::ifstream file(path, std::ios::binary | std::ios::ate);
    if (!file) throw FileError("cannot open '" + path + "'");
    std::streamoff size = file.tellg();
    if (size < 0) throw FileError("cannot read '" + path + "'");
    std::string contents(static_cast<std::size_t>(size), '\0');
    file.seekg(0);
    if (!file.read(contents.data(), size)) throw FileError("cannot read '" + path + "'");
    return parseUsdaString(contents, path);
}

}  // namespace fluence::usd
