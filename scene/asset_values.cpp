#include "scene/asset_values.h"

#include <algorithm>

namespace fluence::usd {

bool anyAssetValue(const Value& value, FunctionRef<bool(const Value&)> test) {
    switch (value.kind) {
        case ValueKind::Asset: return test(value);
        case ValueKind::List:
            return std::any_of(value.items.begin(), value.items.end(),
                               [&](const Value& item) { return anyAssetValue(item, test); });
        case ValueKind::Dictionary:
            return value.dictionary &&
                   std::any_of(value.dictionary->begin(), value.dictionary->end(),
                               [&](const auto& entry) { return anyAssetValue(entry.second, test); });
        default: return false;
    }
}

}  // namespace fluence::usd
