// Payload load rules, as USD's UsdStageLoadRules: which prims' payloads a stage includes.
//
// Rules name prim paths and govern the prim and its descendants; the most specific rule (the
// longest path that is the prim's own or an ancestor's) decides, and where none applies the
// stage-wide rule does: load everything (the default, UsdStage::Open's LoadAll) or nothing
// (loadNone). A prim governed by an unload rule is still loaded when a load rule sits on a prim
// below it with no other rule in between (UsdStageLoadRules::GetEffectiveRuleForPath: the ancestors
// of a loaded prim load too, so that the prim can exist). As with UsdStageLoadRules, load and
// unload replace the rules at and below their prim, so later calls win.
#pragma once

#include <map>
#include <string>

namespace fluence::usd {

class LoadRules {
public:
    static LoadRules loadAll() { return {}; }
    static LoadRules loadNone();

    // Load (unload) the payloads of the prim at the absolute path `primPath` and its descendants.
    void load(const std::string& primPath) { setRule(primPath, true); }
    void unload(const std::string& primPath) { setRule(primPath, false); }

    bool isLoaded(const std::string& primPath) const;

private:
    void setRule(const std::string& primPath, bool load);

    std::map<std::string, bool> rules_;  // prim path ("/" for the stage-wide rule) -> load
};

}  // namespace fluence::usd
