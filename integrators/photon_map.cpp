#include "integrators/photon_map.h"

#include <bit>
#include <cmath>

namespace fluence::integrators {

PhotonMap::PhotonMap(std::vector<Photon> photons, float radius, bool keepIndices)
    : radius_(radius), cellSize_(2.0f * radius) {
    const std::size_t slots = std::bit_ceil(std::max<std::size_t>(photons.size(), 1));
    slotStart_.assign(slots + 1, 0);
    std::vector<std::uint32_t> slotOfPhoton(photons.size());
    for (std::size_t i = 0; i < photons.size(); ++i) {
        slotOfPhoton[i] = slotOf(cellOf(photons[i].position));
        ++slotStart_[slotOfPhoton[i] + 1];
    }
    for (std::size_t s = 0; s < slots; ++s) slotStart_[s + 1] += slotStart_[s];
    photons_.resize(photons.size());
    std::vector<std::uint32_t> next(slotStart_.begin(), slotStart_.end() - 1);
    if (keepIndices) indices_.resize(photons.size());
    for (std::size_t i = 0; i < photons.size(); ++i) {
        const std::uint32_t place = next[slotOfPhoton[i]]++;
        photons_[place] = photons[i];
        if (keepIndices) indices_[place] = std::uint32_t(i);
    }
}

std::array<int, 3> PhotonMap::cellOf(const Vec3f& p) const {
    return {int(std::floor(p.x / cellSize_)), int(std::floor(p.y / cellSize_)), int(std::floor(p.z / cellSize_))};
}

std::uint32_t PhotonMap::slotOf(const std::array<int, 3>& cell) const {
    // Teschner et al.'s three large primes; the table size is a power of two.
    const std::uint32_t h =
        std::uint32_t(cell[0]) * 73856093u ^ std::uint32_t(cell[1]) * 19349663u ^ std::uint32_t(cell[2]) * 83492791u;
    return h & std::uint32_t(slotStart_.size() - 2);
}

}  // namespace fluence::integrators
