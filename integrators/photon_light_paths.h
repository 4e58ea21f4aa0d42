// Light path expressions for photons (integrators/sppm.h): what a photon carries so that the eye
// path that gathers it can tell, exactly, which light path expression AOVs the joined path matches.
//
// An expression reads a path from the camera to the light (integrators/light_path_expression.h).
// sppm's path, gathered at a visible point x, is (the eye's events up to x)(x's own event)(the
// photon's events, from its last scattering back to its light). The eye side runs the automaton
// forward as `path` does (LightPathTracker), x's event included (LightPathTracker::gather); the
// photon side cannot, since it is traced from the other end. So each photon carries, per
// expression, the set of automaton states from which its own events, read back to the light,
// reach acceptance:
//     S_0 = { q : accepts(next(q, light's event)) }
//     S_i = { q : next(q, e_i) in S_(i-1) }     for the photon's i-th scattering e_i, light first,
// and the gather accepts the photon from eye state q (after x's event) iff q is in S. With at
// most kMaxPhotonLpeStates states a set is one 64-bit mask; an expression whose minimal automaton
// has more states is refused (photonLightPathProblem).
//
// Lobe kinds: where a photon scatters off a BSDF that mixes kinds, its flux is shared among the
// kinds as `path` shares the throughput (integrators/light_path_tracker.h, by the adjoint BSDF's
// split, which is the radiance BSDF's with the directions swapped: integrators/bdpt_events.h), so a
// photon carries per expression a few histories (a state set and the fraction of its flux that
// went that way), those with the same set merged, those with an empty set (nothing can accept)
// dropped. The fractions of one expression never add up to more than 1, so the layers of a
// disjoint cover of every path still sum to the beauty sample by sample. Nothing here draws a
// random number: the beauty is bit-identical with and without LPE AOVs.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/rgb.h"
#include "integrators/light_path_tracker.h"

namespace fluence::integrators {

// The most automaton states an expression may have for photons to carry it: one bit each.
inline constexpr int kMaxPhotonLpeStates = 64;

// Why photons cannot carry `expression` (its automaton is too large), or "" when they can.
std::string photonLightPathProblem(const LightPathExpression& expression);

// One history of a photon for expression `aov`: the states from which its events reach
// acceptance, and the fraction (per channel) of its flux that went this way.
struct PhotonHistory {
    std::uint64_t states = 0;
    RGB share;
    int aov = 0;
};

// The histories of a photon path as it is traced, from its light on.
class PhotonLightPaths {
public:
    // No AOVs: inactive, every call does nothing.
    PhotonLightPaths(std::span<const LightPathAov> aovs, const PathEvent& light);

    bool active() const { return !aovs_.empty(); }
    // The photon scatters at `vertex` (its events in the radiance view, as bdpt reads a light
    // subpath's vertex) and goes on.
    void scatter(const VertexEvents& vertex);
    std::span<const PhotonHistory> histories() const { return histories_; }

private:
    std::span<const LightPathAov> aovs_;
    std::vector<PhotonHistory> histories_, next_;
};

// The histories of the photons of one map, photon i's by its index i in the order stored.
class PhotonHistoryTable {
public:
    void add(std::span<const PhotonHistory> histories);  // the next photon's
    void append(const PhotonHistoryTable& other);        // other's photons after these
    // The fraction of photon i's flux that expression `aov` accepts from eye state `state`.
    RGB accepted(std::uint32_t photon, int aov, int state) const;
    std::size_t bytes() const {
        return (start_.size() - 1) * sizeof(std::uint32_t) + histories_.size() * sizeof(PhotonHistory);
    }

private:
    std::vector<std::uint32_t> start_{0};  // photon i's histories: [start_[i], start_[i + 1])
    std::vector<PhotonHistory> histories_;
};

}  // namespace fluence::integrators
