#include "apps/attribute_overrides.h"

#include "apps/cli_options.h"
#include "delegate/prim_reader.h"
#include "scene/usda_parser.h"

namespace fluence::app {

AttributeOverride parseAttributeOverride(const std::string& text) {
    AttributeOverride o;
    o.text = text;
    std::string rest = text;
    if (!rest.starts_with("/")) {
        const std::size_t space = rest.find(' ');
        if (space == std::string::npos)
            throw UsageError("--set expects [TYPE ]/Prim/Path.attribute=VALUE, got '" + text + "'");
        o.typeName = rest.substr(0, space);
        const std::size_t path = rest.find_first_not_of(' ', space);
        rest = path == std::string::npos ? "" : rest.substr(path);
    }
    const std::size_t equals = rest.find('=');
    const std::size_t dot = rest.rfind('.', equals);
    if (!rest.starts_with("/") || equals == std::string::npos || dot == std::string::npos || dot + 1 == equals ||
        dot < 2)
        throw UsageError("--set expects [TYPE ]/Prim/Path.attribute=VALUE, got '" + text + "'");
    o.primPath = rest.substr(0, dot);
    o.attribute = rest.substr(dot + 1, equals - dot - 1);
    o.value = rest.substr(equals + 1);
    return o;
}

void applyAttributeOverrides(usd::Stage& stage, const std::vector<AttributeOverride>& overrides) {
    for (const AttributeOverride& o : overrides) {
        const usd::PrimSpec* prim = stage.prim(o.primPath);
        if (!prim) throw delegate::SceneError(o.primPath + ": --set " + o.text + ": the stage has no such prim");
        std::string typeName = o.typeName;
        if (typeName.empty()) {
            const usd::AttributeSpec* authored = prim->attribute(o.attribute);
            if (!authored)
                throw delegate::SceneError(o.primPath + ": --set " + o.text + ": the prim has no attribute '" +
                                           o.attribute + "'; give its type, as in --set 'float " + o.primPath + "." +
                                           o.attribute + "=1'");
            typeName = authored->typeName;
        }
        // The value, read by the USDA parser as the one attribute of a one-prim layer.
        const std::string prefix = "#usda 1.0\nover \"Override\" {\n" + typeName + " value = ";
        std::unique_ptr<usd::Layer> layer;
        try {
            layer = usd::parseUsdaString(prefix + o.value + "\n}\n", "--set");
        } catch (const usd::ParseError& e) {
            throw UsageError("--set " + o.text + ": '" + o.value + "' is not a " + typeName + " value: " + e.what());
        }
        if (!layer->warnings.empty()) throw UsageError("--set " + o.text + ": " + layer->warnings.front().message);
        const usd::AttributeSpec* parsed = layer->rootPrims.front()->attribute("value");
        stage.setAttribute(o.primPath, o.attribute, parsed->defaultValue);
    }
}

}  // namespace fluence::app
