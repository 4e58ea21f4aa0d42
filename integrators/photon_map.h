// The photon map of photon mapping: the photons one light-tracing pass left on surfaces (or, in
// a second map, at scatterings in media), found again by a fixed-radius range query.
//
// Method: a hashed uniform grid (Teschner et al. 2003's spatial hashing, as in Hachisuka & Jensen
// 2009's SPPM) of cells 2r wide, r the query radius the map is built for. A query ball of radius
// r overlaps 2 cells per axis (3 when rounding puts its ends on two cell boundaries), so a query
// visits 8 cells (27 at most). Cells are hashed into a
// table of the next power of two at or above the photon count, and the photons are sorted by
// table slot (a counting sort), so each slot is one contiguous run: no per-cell allocation, and
// a build is O(n). Slots that two visited cells share are visited once; cells that collide in a
// slot only add candidates, which the exact distance test removes, so forEachWithin() visits
// exactly the photons within r (tests/integrators/sppm_test.cpp checks it against brute force).
//
// Memory: 36 bytes per photon (position, incoming direction, power as floats) plus 4 bytes per
// table slot (at most 2 per photon): at most 44 bytes per photon (48 with the indices kept).
//
// Conventions: `wi` is the unit direction the photon arrived from (pointing away from the
// surface or scattering point, towards the previous vertex of its path: the `wi` of render/bsdf.h
// and media/phase.h), `power` its flux, already divided by the number of photon paths emitted
// for the map.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <type_traits>
#include <vector>

#include "core/rgb.h"
#include "core/vec.h"

namespace fluence::integrators {

struct Photon {
    Vec3f position;
    Vec3f wi;
    RGB power;
};

class PhotonMap {
public:
    // `keepIndices`: the map also keeps each photon's index in `photons` (indexAt), for what is kept
    // beside the photons in that order (integrators/photon_light_paths.h).
    PhotonMap(std::vector<Photon> photons, float radius, bool keepIndices = false);

    float radius() const { return radius_; }
    std::size_t size() const { return photons_.size(); }
    // The index in the constructor's vector of the photon at `position` in the map; only if the map
    // keeps indices.
    std::uint32_t indexAt(std::uint32_t position) const { return indices_[position]; }
    std::size_t bytes() const {
        return photons_.size() * sizeof(Photon) + (slotStart_.size() + indices_.size()) * sizeof(std::uint32_t);
    }

    // Calls visit(photon) for every photon at distance <= radius() from p, or visit(photon,
    // position), position its place in the map (see indexAt).
    template <class Visit>
    void forEachWithin(const Vec3f& p, Visit&& visit) const {
        if (photons_.empty()) return;
        const std::array<int, 3> lo = cellOf(p - Vec3f(radius_)), hi = cellOf(p + Vec3f(radius_));
        std::array<std::uint32_t, 27> slots{};
        int count = 0;
        for (int z = lo[2]; z <= hi[2]; ++z)
            for (int y = lo[1]; y <= hi[1]; ++y)
                for (int x = lo[0]; x <= hi[0]; ++x) slots[count++] = slotOf({x, y, z});
        std::sort(slots.begin(), slots.begin() + count);
        const float r2 = radius_ * radius_;
        for (int i = 0; i < count; ++i) {
            if (i > 0 && slots[i] == slots[i - 1]) continue;
            for (std::uint32_t j = slotStart_[slots[i]]; j < slotStart_[slots[i] + 1]; ++j)
                if (lengthSquared(photons_[j].position - p) <= r2) {
                    if constexpr (std::is_invocable_v<Visit, const Photon&, std::uint32_t>)
                        visit(photons_[j], j);
                    else
                        visit(photons_[j]);
                }
        }
    }

private:
    std::array<int, 3> cellOf(const Vec3f& p) const;
    std::uint32_t slotOf(const std::array<int, 3>& cell) const;

    float radius_, cellSize_;
    std::vector<Photon> photons_;           // sorted by slot
    std::vector<std::uint32_t> slotStart_;  // photons of slot s: [slotStart_[s], slotStart_[s + 1])
    std::vector<std::uint32_t> indices_;    // per photon (if kept): its index in the constructor's vector
};

}  // namespace fluence::integrators
