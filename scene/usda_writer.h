// The USDA text writer: any usd::Layer (a parsed text or crate layer, or the stage's flattened
// layer) as USD text that Fluence's reader (scene/usda_parser.h) reads back into the same Layer.
//
// The text follows the layout OpenUSD writes (`usdcat`): the "#usda 1.0" header, the layer
// metadata block, then prims with their metadata blocks, `{` on its own line, four-space
// indentation, one statement a line, values in USD's syntax (scene/usda_value_writer.h).
//
// The Layer keeps some statements as data of other specs (usda_parser.cpp explains why); the writer
// turns them back into statements, in an order that gives the same Layer when read:
//   - `reorder rootPrims` (layer metadata), `reorder nameChildren` and `reorder properties`
//     (prim and variant metadata, op Reorder) become reorder statements;
//   - a relationship's "targetPaths" and an attribute's "connectionPaths" entries (list edits
//     beside the spec's own op and paths) become `delete rel x = ...` and
//     `reorder float y.connect = ...` statements, and a relationship's "timeSamples" dictionary
//     `rel x.timeSamples = {...}`. (The text reader keeps only the last prepend, append or add
//     statement of a property, so a crate property with two such edits reads back with one.)
//   - an attribute's default value, time samples and connections are separate statements on one
//     declaration, and the property's metadata blocks sit on declarations placed so that every
//     metadata entry keeps its position among the special entries above.
// Authored order is kept everywhere (metadata, properties, children, variants), as are list ops.
// What the Layer does not hold (comments, the order of attributes relative to relationships,
// `rel x = []` versus `rel x`) is not written. Source locations are not part of the text.
//
// Throws std::invalid_argument for a value USD text cannot hold (a dictionary entry of no USD
// type), which only layers built in memory can contain.
#pragma once

#include <string>

#include "scene/layer.h"

namespace fluence::usd {

std::string writeUsda(const Layer& layer);

}  // namespace fluence::usd
