// A table of names (prim paths) indexed by small integers, each name stored once.
//
// The render scene keeps one per Cryptomatte layer it can be asked for (objects, materials), and
// a hit carries the index of its name (render::SurfaceHit, FilmSample), so samples move four bytes
// instead of a string; the names are only read back when the image is written. Indices are given in
// the order names are first added, so a scene built the same way numbers its names the same way.
// kNoName stands for "nothing named": a ray that hit nothing, or a surface without a material.
#pragma once

#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

namespace fluence {

inline constexpr std::uint32_t kNoName = 0xffffffffu;

// The name of a prim path's last element: "/World/Key" -> "Key" (the whole string when it has no '/').
inline std::string primName(const std::string& path) { return path.substr(path.find_last_of('/') + 1); }

class NameTable {
public:
    // The index of `name`, added at the end when it is new.
    std::uint32_t add(const std::string& name) {
        auto [it, inserted] = index_.try_emplace(name, static_cast<std::uint32_t>(names_.size()));
        if (inserted) names_.push_back(name);
        return it->second;
    }
    const std::string& name(std::uint32_t index) const { return names_[index]; }
    const std::vector<std::string>& names() const { return names_; }
    std::size_t size() const { return names_.size(); }

private:
    std::vector<std::string> names_;
    std::unordered_map<std::string, std::uint32_t> index_;
};

}  // namespace fluence
