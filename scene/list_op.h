// USD list-op composition (internal to the scene library): how the opinions of several specs on
// one list-valued field (references, inherits, apiSchemas, relationship targets, ...) combine.
//
// Each spec contributes edits: an explicit list (replaces everything weaker), or `delete`, `add`,
// `prepend`, `append` and `reorder` edits applied to the weaker result. Composition starts from
// the strongest explicit list (or an empty list) and applies the edits of every stronger spec,
// weakest first; within one spec the edits apply in Sdf's order: delete, add, prepend, append,
// reorder. A spec with an explicit list is explicit: its other edits are ignored.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

#include "scene/layer.h"

namespace fluence::usd::detail {

template <class T>
struct ListEdit {
    ListOpKind op = ListOpKind::Explicit;
    std::vector<T> items;
};

// Sdf's ordering rule (reorder list ops, `reorder nameChildren`): the items named in `order` take
// that order; every other item keeps following the named item it followed (items before the
// first named one stay in front).
template <class T, class Same>
std::vector<T> applyOrdering(const std::vector<T>& list, const std::vector<T>& order, Same same) {
    auto named = [&](const T& x) {
        return std::find_if(order.begin(), order.end(), [&](const T& o) { return same(x, o); });
    };
    std::vector<T> leading;
    std::vector<std::vector<T>> groups(order.size());
    std::vector<T>* current = &leading;
    for (const T& x : list) {
        auto at = named(x);
        if (at != order.end() && groups[static_cast<std::size_t>(at - order.begin())].empty())
            current = &groups[static_cast<std::size_t>(at - order.begin())];
        current->push_back(x);
    }
    for (auto& group : groups) leading.insert(leading.end(), group.begin(), group.end());
    return leading;
}

// One spec's edits of the field, in authored order.
template <class T>
using SpecListEdits = std::vector<ListEdit<T>>;

// Composes the edits of several specs, strongest spec first. `same(a, b)` says whether two items
// are the same list element.
template <class T, class Same>
std::vector<T> composeListEdits(const std::vector<SpecListEdits<T>>& strongestFirst, Same same) {
    auto explicitEdit = [](const SpecListEdits<T>& edits) -> const ListEdit<T>* {
        const ListEdit<T>* found = nullptr;
        for (const ListEdit<T>& edit : edits)
            if (edit.op == ListOpKind::Explicit) found = &edit;
        return found;
    };
    auto contains = [&](const std::vector<T>& list, const T& item) {
        return std::any_of(list.begin(), list.end(), [&](const T& x) { return same(x, item); });
    };
    auto removeAll = [&](std::vector<T>& list, const std::vector<T>& items) {
        std::erase_if(list, [&](const T& x) { return contains(items, x); });
    };

    std::vector<T> result;
    std::size_t start = strongestFirst.size();
    for (std::size_t i = 0; i < strongestFirst.size(); ++i) {
        if (const ListEdit<T>* edit = explicitEdit(strongestFirst[i])) {
            result = edit->items;
            start = i;
            break;
        }
    }
    for (std::size_t i = start; i-- > 0;) {
        const SpecListEdits<T>& edits = strongestFirst[i];
        for (ListOpKind op :
             {ListOpKind::Delete, ListOpKind::Add, ListOpKind::Prepend, ListOpKind::Append, ListOpKind::Reorder}) {
            for (const ListEdit<T>& edit : edits) {
                if (edit.op != op) continue;
                switch (op) {
                    case ListOpKind::Delete: removeAll(result, edit.items); break;
                    case ListOpKind::Add:
                        for (const T& item : edit.items)
                            if (!contains(result, item)) result.push_back(item);
                        break;
                    case ListOpKind::Prepend:
                        removeAll(result, edit.items);
                        result.insert(result.begin(), edit.items.begin(), edit.items.end());
                        break;
                    case ListOpKind::Append:
                        removeAll(result, edit.items);
                        result.insert(result.end(), edit.items.begin(), edit.items.end());
                        break;
                    default: result = applyOrdering(result, edit.items, same);
                }
            }
        }
    }
    return result;
}

}  // namespace fluence::usd::detail
