#include "scene/mtlx_reader.h"

#include <pugixml.hpp>

#include <charconv>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <utility>
#include <vector>

#include "scene/usda_parser.h"

namespace fluence::usd {

namespace {

struct UsdType {
    const char* name;
    ValueKind kind;
    int components;  // for numeric types
};

// The USD type of a MaterialX type, or nullopt for types with no value (shaders, BSDFs, ...).
std::optional<UsdType> usdTypeOf(const std::string& type) {
    static const std::vector<std::pair<std::string, UsdType>> types = {
        {"float", {"float", ValueKind::Numeric, 1}},       {"integer", {"int", ValueKind::Numeric, 1}},
        {"boolean", {"bool", ValueKind::Numeric, 1}},      {"color3", {"color3f", ValueKind::Numeric, 3}},
        {"color4", {"color4f", ValueKind::Numeric, 4}},    {"vector2", {"float2", ValueKind::Numeric, 2}},
        {"vector3", {"vector3f", ValueKind::Numeric, 3}},  {"vector4", {"float4", ValueKind::Numeric, 4}},
        {"matrix33", {"matrix3d", ValueKind::Numeric, 9}}, {"matrix44", {"matrix4d", ValueKind::Numeric, 16}},
        {"string", {"string", ValueKind::String, 1}},      {"filename", {"asset", ValueKind::Asset, 1}},
    };
    for (const auto& [mtlx, usd] : types)
        if (mtlx == type) return usd;
    return std::nullopt;
}

// The USD type name of an attribute of MaterialX type `type` ("token" for types with no value).
const char* usdTypeNameOf(const std::string& type) {
    const std::optional<UsdType> usd = usdTypeOf(type);
    return usd ? usd->name : "token";
}

bool isColorType(const std::string& type) { return type == "color3" || type == "color4"; }

class Reader {
public:
    Reader(const std::string& identifier) : identifier_(identifier) {}

    std::unique_ptr<Layer> read(const std::string& text) {
        pugi::xml_document doc;
        const pugi::xml_parse_result parsed = doc.load_buffer(text.data(), text.size());
        if (!parsed)
            throw ParseError({identifier_, 1, 1}, "not a MaterialX document: XML error at byte " +
                                                      std::to_string(parsed.offset) + ": " + parsed.description());
        root_ = doc.child("materialx");
        if (!root_) throw ParseError({identifier_, 1, 1}, "not a MaterialX document: no <materialx> element");
        layer_ = std::make_unique<Layer>();
        layer_->identifier = identifier_;
        layer_->header = "#usda 1.0";
        PrimSpec& materialx = addChild(layer_->rootPrims, "", "MaterialX", "Scope");
        PrimSpec& materials = addChild(materialx.children, materialx.path, "Materials", "Scope");
        for (pugi::xml_node element : root_.children()) {
            const std::string kind = element.name();
            if (kind == "surfacematerial")
                addMaterial(materials, element);
            else if (kind != "nodegraph" && !isNode(element) && element.type() == pugi::node_element)
                noteUnsupported(kind);
        }
        return std::move(layer_);
    }

private:
    // Whether a top-level element is a node (anything but the document's structural elements).
    static bool isNode(pugi::xml_node e) {
        static const std::set<std::string> structural = {
            "nodegraph", "nodedef",        "look",           "lookgroup",   "collection", "geominfo",
            "typedef",   "implementation", "materialassign", "propertyset", "variantset", "backdrop",
            "output",    "token",          "unittypedef",    "targetdef",   "member"};
        return e.type() == pugi::node_element && !structural.contains(e.name());
    }

    // A warning about the document (a MaterialX file has no line numbers the reader keeps).
    void warn(std::string message) {
        layer_->warnings.push_back(ParseWarning{SourceLocation{identifier_, 1, 1}, std::move(message)});
    }

    void noteUnsupported(const std::string& kind) {
        if (!reported_.insert(kind).second) return;
        warn("MaterialX <" + kind + "> elements are not read (only materials, their shaders, node graphs and nodes)");
    }

    PrimSpec& addChild(std::vector<std::unique_ptr<PrimSpec>>& siblings, const std::string& parentPath,
                       const std::string& name, const std::string& type) {
        auto prim = std::make_unique<PrimSpec>();
        prim->name = name;
        prim->typeName = type;
        prim->path = parentPath + "/" + name;
        prim->location = {identifier_, 1, 1};
        siblings.push_back(std::move(prim));
        return *siblings.back();
    }

    pugi::xml_node topLevel(const char* name) const { return root_.find_child_by_attribute("name", name); }

    // The colour space in effect at `e`: its own, else its ancestors', else none.
    static std::string colorSpaceAt(pugi::xml_node e) {
        for (; e; e = e.parent())
            if (pugi::xml_attribute a = e.attribute("colorspace")) return a.value();
        return "";
    }

    void addMaterial(PrimSpec& materials, pugi::xml_node material) {
        const std::string name = material.attribute("name").value();
        PrimSpec& prim = addChild(materials.children, materials.path, name, "Material");
        pugi::xml_node surface = material.find_child_by_attribute("input", "name", "surfaceshader");
        pugi::xml_node shader = surface ? topLevel(surface.attribute("nodename").value()) : pugi::xml_node();
        if (!shader) {
            warn("material '" + name + "' has no surfaceshader node");
            return;
        }
        AttributeSpec output;
        output.name = "outputs:mtlx:surface";
        output.typeName = "token";
        output.connections = {prim.path + "/" + shader.attribute("name").value() + ".outputs:out"};
        output.location = prim.location;
        prim.attributes.push_back(std::move(output));
        copied_.clear();
        addNode(prim, shader, "");
    }

    // Adds `node` (a document-level node, or one of `graphPath`'s) as a Shader under `parent`,
    // and, recursively, what its inputs connect to.
    void addNode(PrimSpec& parent, pugi::xml_node node, const std::string& graphPath) {
        const std::string name = node.attribute("name").value();
        if (!copied_.insert(parent.path + "/" + name).second) return;
        PrimSpec& prim = addChild(parent.children, parent.path, name, "Shader");
        AttributeSpec id;
        id.name = "info:id";
        id.typeName = "token";
        id.uniform = true;
        id.hasDefault = true;
        id.defaultValue = Value::string("token", ValueKind::Token, {nodeDefinition(node)}, false);
        id.location = prim.location;
        prim.attributes.push_back(std::move(id));
        const std::string type = node.attribute("type").value();
        for (pugi::xml_node input : node.children("input")) addInput(prim, node, input, graphPath, type);
        AttributeSpec out;
        out.name = "outputs:out";
        out.typeName = usdTypeNameOf(type);
        out.location = prim.location;
        prim.attributes.push_back(std::move(out));
    }

    static std::string nodeDefinition(pugi::xml_node node) {
        if (pugi::xml_attribute nodedef = node.attribute("nodedef")) return nodedef.value();
        const std::string category = node.name(), type = node.attribute("type").value();
        if (category == "normalmap") return "ND_normalmap";
        return "ND_" + category + "_" + type;
    }

    void addInput(PrimSpec& prim, pugi::xml_node node, pugi::xml_node input, const std::string& graphPath,
                  const std::string& nodeType) {
        const std::string name = input.attribute("name").value(), type = input.attribute("type").value();
        const std::optional<UsdType> usdType = usdTypeOf(type);
        AttributeSpec a;
        a.name = "inputs:" + name;
        a.typeName = usdTypeNameOf(type);
        a.location = prim.location;
        // The material the node sits in: its prim's parent (a NodeGraph's parent for graph nodes).
        const std::string materialPath = graphPath.empty() ? parentPath(prim.path) : parentPath(graphPath);
        if (pugi::xml_attribute graph = input.attribute("nodegraph")) {
            const std::string output = input.attribute("output").value();
            a.connections = {materialPath + "/" + graph.value() + ".outputs:" + output};
            addGraph(*primAt(materialPath), graph.value());
        } else if (pugi::xml_attribute source = input.attribute("nodename")) {
            const std::string scope = graphPath.empty() ? materialPath : graphPath;
            a.connections = {scope + "/" + source.value() + ".outputs:out"};
            pugi::xml_node sourceNode =
                graphPath.empty() ? topLevel(source.value()) : graphNode(graphPath, source.value());
            if (sourceNode) addNode(*primAt(scope), sourceNode, graphPath);
        } else if (pugi::xml_attribute iface = input.attribute("interfacename")) {
            a.connections = {graphPath + ".inputs:" + iface.value()};
        } else if (usdType) {
            a.hasDefault = true;
            a.defaultValue = valueOf(input.attribute("value").value(), *usdType, input);
        }
        const bool colour = isColorType(type) || (type == "filename" && isColorType(nodeType));
        if (const std::string space = colorSpaceAt(input); colour && !space.empty())
            a.metadata.push_back({"colorSpace", ListOpKind::Explicit,
                                  Value::string("string", ValueKind::String, {space}, false), a.location});
        prim.attributes.push_back(std::move(a));
    }

    // Copies node graph `name` (with its outputs; its nodes as its outputs reach them) into `material`.
    void addGraph(PrimSpec& material, const std::string& name) {
        if (!copied_.insert(material.path + "/" + name).second) return;
        pugi::xml_node graph = root_.find_child_by_attribute("nodegraph", "name", name.c_str());
        PrimSpec& prim = addChild(material.children, material.path, name, "NodeGraph");
        if (!graph) {
            warn("node graph '" + name + "' is not in the document");
            return;
        }
        graphs_[prim.path] = graph;
        for (pugi::xml_node input : graph.children("input")) {
            const std::string type = input.attribute("type").value();
            if (std::optional<UsdType> usdType = usdTypeOf(type)) {
                AttributeSpec a;
                a.name = std::string("inputs:") + input.attribute("name").value();
                a.typeName = usdType->name;
                a.hasDefault = true;
                a.defaultValue = valueOf(input.attribute("value").value(), *usdType, input);
                a.location = prim.location;
                prim.attributes.push_back(std::move(a));
            }
        }
        for (pugi::xml_node output : graph.children("output")) {
            const std::string type = output.attribute("type").value();
            AttributeSpec a;
            a.name = std::string("outputs:") + output.attribute("name").value();
            a.typeName = usdTypeNameOf(type);
            a.location = prim.location;
            const std::string source = output.attribute("nodename").value();
            if (!source.empty()) {
                a.connections = {prim.path + "/" + source + ".outputs:out"};
                if (pugi::xml_node node = graph.find_child_by_attribute("name", source.c_str()))
                    addNode(prim, node, prim.path);
            }
            prim.attributes.push_back(std::move(a));
        }
    }

    pugi::xml_node graphNode(const std::string& graphPath, const std::string& name) const {
        auto graph = graphs_.find(graphPath);
        return graph == graphs_.end() ? pugi::xml_node() : graph->second.find_child_by_attribute("name", name.c_str());
    }

    static std::string parentPath(const std::string& path) { return path.substr(0, path.find_last_of('/')); }

    PrimSpec* primAt(const std::string& path) {
        std::vector<std::unique_ptr<PrimSpec>>* siblings = &layer_->rootPrims;
        PrimSpec* found = nullptr;
        std::stringstream parts(path.substr(1));
        for (std::string name; std::getline(parts, name, '/');) {
            found = nullptr;
            for (auto& p : *siblings)
                if (p->name == name) found = p.get();
            if (!found) return nullptr;
            siblings = &found->children;
        }
        return found;
    }

    Value valueOf(const std::string& text, const UsdType& type, pugi::xml_node input) {
        if (type.kind != ValueKind::Numeric) return Value::string(type.name, type.kind, {text}, false);
        std::vector<double> numbers;
        if (std::string(type.name) == "bool") {
            numbers.push_back(text == "true" ? 1.0 : 0.0);
        } else {
            std::stringstream items(text);
            for (std::string item; std::getline(items, item, ',');) {
                const std::size_t first = item.find_first_not_of(" \t\n"), last = item.find_last_not_of(" \t\n");
                double v = 0.0;
                const char* begin = item.data() + (first == std::string::npos ? item.size() : first);
                const char* end = item.data() + (last == std::string::npos ? 0 : last + 1);
                if (begin >= end || std::from_chars(begin, end, v).ptr != end) {
                    numbers.clear();
                    break;
                }
                numbers.push_back(v);
            }
        }
        if (numbers.size() != std::size_t(type.components)) {
            warn("input '" + std::string(input.attribute("name").value()) + "': value '" + text + "' is not a " +
                 type.name + "; using zero");
            numbers.assign(std::size_t(type.components), 0.0);
        }
        return Value::numeric(type.name, std::move(numbers), type.components, false);
    }

    std::string identifier_;
    pugi::xml_node root_;
    std::unique_ptr<Layer> layer_;
    std::set<std::string> reported_;
    std::set<std::string> copied_;  // prim paths already written in the current material
    std::map<std::string, pugi::xml_node> graphs_;
};

}  // namespace

std::unique_ptr<Layer> readMaterialX(const std::string& text, const std::string& identifier) {
    return Reader(identifier).read(text);
}

std::unique_ptr<Layer> readMaterialXFile(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    if (!file) throw FileError("cannot open '" + path + "'");
    std::stringstream contents;
    contents << file.rdbuf();
    return readMaterialX(contents.str(), path);
}

}  // namespace fluence::usd
