#include "scene/stage.h"

#include <algorithm>

#include "scene/usda_parser.h"

namespace fluence::usd {

Stage::Stage(std::unique_ptr<Layer> rootLayer) : layer_(std::move(rootLayer)) {}

std::unique_ptr<Stage> Stage::open(const std::string& path) { return std::make_unique<Stage>(parseUsdaFile(path)); }

namespace {

std::optional<std::string> stringMetadata(const Layer& layer, const char* key) {
    const MetadataEntry* e = findMetadata(layer.metadata, key);
    return e ? e->value.asString() : std::nullopt;
}

std::optional<double> numberMetadata(const Layer& layer, const char* key) {
    const MetadataEntry* e = findMetadata(layer.metadata, key);
    return e ? e->value.asDouble() : std::nullopt;
}

bool isActive(const PrimSpec& prim) {
    const MetadataEntry* e = findMetadata(prim.metadata, "active");
    if (!e) return true;
    if (auto b = e->value.asDouble()) return *b != 0.0;
    return e->value.asString().value_or("true") != "false";
}

void visitPrim(const PrimSpec& prim, const std::function<bool(const PrimSpec&)>& visit) {
    if (prim.specifier != Specifier::Def || !isActive(prim)) return;
    if (visit(prim))
        for (const auto& child : prim.children) visitPrim(*child, visit);
}

}  // namespace

std::string Stage::defaultPrim() const { return stringMetadata(*layer_, "defaultPrim").value_or(""); }

char Stage::upAxis() const { return stringMetadata(*layer_, "upAxis").value_or("Y") == "Z" ? 'Z' : 'Y'; }

double Stage::metersPerUnit() const { return numberMetadata(*layer_, "metersPerUnit").value_or(0.01); }

std::optional<double> Stage::startTimeCode() const { return numberMetadata(*layer_, "startTimeCode"); }

std::optional<double> Stage::endTimeCode() const { return numberMetadata(*layer_, "endTimeCode"); }

void Stage::traverse(const std::function<bool(const PrimSpec&)>& visit) const {
    for (const auto& prim : layer_->rootPrims) visitPrim(*prim, visit);
}

std::optional<Value> Stage::resolve(const AttributeSpec& attribute, double time) {
    auto fromDefault = [&]() -> std::optional<Value> {
        if (!attribute.hasDefault || attribute.defaultValue.isBlocked()) return std::nullopt;
        return attribute.defaultValue;
    };
    const auto& samples = attribute.timeSamples;
    if (std::isnan(time) || samples.empty()) return fromDefault();

    auto after = std::lower_bound(samples.begin(), samples.end(), time,
                                  [](const std::pair<double, Value>& s, double t) { return s.first < t; });
    const Value* v = nullptr;
    if (after == samples.begin())
        v = &after->second;
    else if (after == samples.end())
        v = &samples.back().second;
    else if (after->first == time)
        v = &after->second;
    else {
        const auto& lo = *(after - 1);
        const auto& hi = *after;
        if (lo.second.isNumeric() && hi.second.isNumeric() && lo.second.numbers.size() == hi.second.numbers.size() &&
            lo.second.typeName.find("int") == std::string::npos && lo.second.typeName != "bool") {
            double a = (time - lo.first) / (hi.first - lo.first);
            Value r = lo.second;
            for (std::size_t i = 0; i < r.numbers.size(); ++i)
                r.numbers[i] = lo.second.numbers[i] + a * (hi.second.numbers[i] - lo.second.numbers[i]);
            return r;
        }
        v = &lo.second;  // held
    }
    if (v->isBlocked()) return std::nullopt;
    return *v;
}

}  // namespace fluence::usd
