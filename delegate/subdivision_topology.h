// Internal to delegate/subdivision: checks a SubdivisionTopology and turns it into an OpenSubdiv
// Far::TopologyRefiner (USD tokens to Sdc options, creases, corners, holes, face-varying
// channels). The token table and the rules it enforces are written at the top of subdivision.h.
// Only subdivision*.cpp include this header (it brings in OpenSubdiv).
#pragma once

#include <memory>
#include <vector>

#include <opensubdiv/far/topologyRefiner.h>
#include <opensubdiv/sdc/options.h>
#include <opensubdiv/sdc/types.h>

#include "delegate/subdivision.h"

namespace fluence::delegate::subdivision_detail {

OpenSubdiv::Sdc::SchemeType sdcScheme(SubdivisionTopology::Scheme scheme);

// The Sdc options for the topology's USD tokens. Throws std::invalid_argument naming the attribute
// and the token when a token is not one USD defines.
OpenSubdiv::Sdc::Options sdcOptions(const SubdivisionTopology& topology);

// Throws std::invalid_argument, naming the attribute and the element, unless every face has 3 or
// more points (exactly 3 for Loop) and no point twice in a row, every index is in range, crease
// chains run along mesh edges with as many sharpnesses as USD allows, corner arrays match and no
// sharpness is NaN.
void validateTopology(const SubdivisionTopology& topology);

// Checks each face-varying channel against the topology (components, value count, index range)
// and gives a channel without indices one value per face-vertex (identity indices).
void normalizeFaceVarying(const SubdivisionTopology& topology, std::vector<FaceVaryingData>& channels);

// The refiner for a validated topology and normalized channels (not refined: Bfr works on the base
// level). Throws std::invalid_argument if OpenSubdiv still rejects the topology.
std::unique_ptr<OpenSubdiv::Far::TopologyRefiner> createRefiner(const SubdivisionTopology& topology,
                                                                const std::vector<FaceVaryingData>& channels);

}  // namespace fluence::delegate::subdivision_detail
