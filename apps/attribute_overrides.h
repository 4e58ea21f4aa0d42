// `fluence render --set`: attribute values given on the command line, applied to the composed
// stage as if authored in a session layer stronger than every layer of the scene.
//
// Syntax: `/Prim/Path.attribute=VALUE`, VALUE in USDA syntax for the attribute's type (as it is
// authored on the prim): `--set /World/Key.inputs:intensity=5`, `--set '/World/Ball.primvars:displayColor=[(1, 0, 0)]'`.
// An attribute the prim does not have needs its type first: `--set 'float3 /World/Ball.myColour=(1, 0.5, 0)'`.
// The override is the attribute's default value; its time samples no longer apply (so it holds on
// every frame).
#pragma once

#include <string>
#include <vector>

#include "scene/stage.h"

namespace fluence::app {

struct AttributeOverride {
    std::string text;      // as given, for messages
    std::string typeName;  // "" = the type of the attribute authored on the prim
    std::string primPath;
    std::string attribute;
    std::string value;  // USDA text
};

// Parses one --set argument. Throws UsageError naming what is wrong.
AttributeOverride parseAttributeOverride(const std::string& text);

// Applies the overrides to the stage in order. Throws UsageError for a value that does not parse
// as its type (with the column), delegate::SceneError naming the prim when the prim does not exist
// or the attribute is not authored there and no type was given.
void applyAttributeOverrides(usd::Stage& stage, const std::vector<AttributeOverride>& overrides);

}  // namespace fluence::app
