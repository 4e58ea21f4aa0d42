#include "scene/prim_predicates.h"

#include <algorithm>
#include <unordered_map>

namespace fluence::usd {

namespace {

// Each typed schema's base (the schemas whose prims Fluence reads, and their bases).
const std::unordered_map<std::string, std::string>& schemaBases() {
    static const std::unordered_map<std::string, std::string> bases = {
        {"Imageable", "Typed"},
        {"Scope", "Imageable"},
        {"Xformable", "Imageable"},
        {"Xform", "Xformable"},
        {"Camera", "Xformable"},
        {"Boundable", "Xformable"},
        {"Gprim", "Boundable"},
        {"PointInstancer", "Boundable"},
        {"SkelRoot", "Boundable"},
        {"Skeleton", "Boundable"},
        {"Cube", "Gprim"},
        {"Sphere", "Gprim"},
        {"Cylinder", "Gprim"},
        {"Cylinder_1", "Gprim"},
        {"Cone", "Gprim"},
        {"Capsule", "Gprim"},
        {"Capsule_1", "Gprim"},
        {"Plane", "Gprim"},
        {"Volume", "Gprim"},
        {"PointBased", "Gprim"},
        {"Mesh", "PointBased"},
        {"TetMesh", "PointBased"},
        {"Points", "PointBased"},
        {"NurbsPatch", "PointBased"},
        {"Curves", "PointBased"},
        {"BasisCurves", "Curves"},
        {"NurbsCurves", "Curves"},
        {"HermiteCurves", "Curves"},
        {"BoundableLightBase", "Boundable"},
        {"NonboundableLightBase", "Xformable"},
        {"RectLight", "BoundableLightBase"},
        {"DiskLight", "BoundableLightBase"},
        {"SphereLight", "BoundableLightBase"},
        {"CylinderLight", "BoundableLightBase"},
        {"PortalLight", "BoundableLightBase"},
        {"DistantLight", "NonboundableLightBase"},
        {"DomeLight", "NonboundableLightBase"},
        {"DomeLight_1", "NonboundableLightBase"},
        {"GeometryLight", "NonboundableLightBase"},
        {"PluginLight", "Xformable"},
        {"FieldBase", "Xformable"},
        {"FieldAsset", "FieldBase"},
        {"OpenVDBAsset", "FieldAsset"},
        {"Field3DAsset", "FieldAsset"},
        {"NodeGraph", "Typed"},
        {"Material", "NodeGraph"},
        {"Shader", "Typed"},
        {"SkelAnimation", "Typed"},
        {"BlendShape", "Typed"},
        {"GeomSubset", "Typed"},
        {"RenderSettingsBase", "Typed"},
        {"RenderSettings", "RenderSettingsBase"},
        {"RenderProduct", "RenderSettingsBase"},
        {"RenderVar", "Typed"},
    };
    return bases;
}

// The kinds of the kind registry and their bases.
const std::unordered_map<std::string, std::string>& kindBases() {
    static const std::unordered_map<std::string, std::string> bases = {
        {"group", "model"}, {"assembly", "group"}, {"component", "model"}};
    return bases;
}

// Whether `name` is `base` or (unless `strict`) derives from it in `bases`.
bool derives(std::string name, const std::string& base, bool strict,
             const std::unordered_map<std::string, std::string>& bases) {
    if (name == base) return true;
    if (strict) return false;
    for (auto found = bases.find(name); found != bases.end(); found = bases.find(name)) {
        name = found->second;
        if (name == base) return true;
    }
    return false;
}

bool parseBool(const std::string& text, const std::string& function) {
    if (text == "true" || text == "1") return true;
    if (text == "false" || text == "0") return false;
    throw PredicateError("predicate '" + function + "': '" + text + "' is not true or false");
}

// The one optional boolean argument of abstract, defined, model and group (true when absent).
bool flag(const PredicateCall& call) {
    if (call.args.size() > 1 || !call.keywords.empty())
        throw PredicateError("predicate '" + call.name + "' takes at most one argument, true or false");
    return call.args.empty() || parseBool(call.args[0], call.name);
}

bool strictOf(const PredicateCall& call) {
    auto found = call.keywords.find("strict");
    return found != call.keywords.end() && parseBool(found->second, call.name);
}

std::string kindOf(const PrimSpec& prim) {
    const MetadataEntry* e = findMetadata(prim.metadata, "kind");
    return e && !e->value.strings.empty() ? e->value.strings[0] : std::string();
}

std::vector<std::string> appliedSchemas(const PrimSpec& prim) {
    const MetadataEntry* e = findMetadata(prim.metadata, "apiSchemas");
    return e && e->op != ListOpKind::Delete ? e->value.strings : std::vector<std::string>{};
}

// Whether some prim on the path from `path` up to the root satisfies `test`.
template <class Test>
bool anyAncestorOrSelf(const Stage& stage, std::string path, Test test) {
    for (; path != "/"; path = parentPrimPath(path))
        if (const PrimSpec* prim = stage.prim(path); prim && test(*prim)) return true;
    return false;
}

bool anyOfArgs(const PredicateCall& call, auto test) { return std::any_of(call.args.begin(), call.args.end(), test); }

}  // namespace

void checkPredicate(const PredicateCall& call) {
    const std::string& f = call.name;
    if (f == "abstract" || f == "defined" || f == "model" || f == "group") {
        flag(call);
        return;
    }
    if (f == "kind" || f == "isa" || f == "specifier" || f == "hasAPI") {
        if (call.args.empty()) throw PredicateError("predicate '" + f + "' needs at least one argument");
        for (const auto& [key, value] : call.keywords) {
            const bool known =
                (key == "strict" && (f == "kind" || f == "isa")) || (key == "instanceName" && f == "hasAPI");
            if (!known) throw PredicateError("predicate '" + f + "' has no argument '" + key + "'");
            if (key == "strict") parseBool(value, f);
        }
        if (f == "specifier")
            for (const std::string& s : call.args)
                if (s != "def" && s != "over" && s != "class")
                    throw PredicateError("predicate 'specifier': '" + s + "' is not def, over or class");
        return;
    }
    throw PredicateError("unknown predicate '" + f +
                         "' (known: abstract, defined, model, group, kind, specifier, isa, hasAPI)");
}

bool evaluatePredicate(const PredicateCall& call, const Stage& stage, const std::string& path) {
    const PrimSpec* prim = stage.prim(path);
    if (!prim) return false;
    const std::string& f = call.name;
    if (f == "abstract")
        return anyAncestorOrSelf(stage, path, [](const PrimSpec& p) { return p.specifier == Specifier::Class; }) ==
               flag(call);
    if (f == "defined")
        return !anyAncestorOrSelf(stage, path, [](const PrimSpec& p) { return p.specifier == Specifier::Over; }) ==
               flag(call);
    if (f == "model") return derives(kindOf(*prim), "model", false, kindBases()) == flag(call);
    if (f == "group") return derives(kindOf(*prim), "group", false, kindBases()) == flag(call);
    if (f == "kind")
        return anyOfArgs(call,
                         [&](const std::string& k) { return derives(kindOf(*prim), k, strictOf(call), kindBases()); });
    if (f == "isa")
        return anyOfArgs(
            call, [&](const std::string& t) { return derives(prim->typeName, t, strictOf(call), schemaBases()); });
    if (f == "specifier") {
        static const char* names[] = {"def", "over", "class"};
        return anyOfArgs(call, [&](const std::string& s) { return s == names[int(prim->specifier)]; });
    }
    if (f == "hasAPI") {
        const std::vector<std::string> applied = appliedSchemas(*prim);
        auto instance = call.keywords.find("instanceName");
        return anyOfArgs(call, [&](const std::string& api) {
            return std::any_of(applied.begin(), applied.end(), [&](const std::string& a) {
                if (instance != call.keywords.end()) return a == api + ":" + instance->second;
                return a == api || a.starts_with(api + ":");
            });
        });
    }
    checkPredicate(call);  // throws for an unknown function
    return false;
}

}  // namespace fluence::usd
