// BsdfArena: storage for the BSDFs of one shading point, with no heap allocation.
//
// An integrator keeps one arena per path (on the stack), calls reset() at each hit and builds
// that hit's BSDF in it:
//
//     BsdfArena arena;                                 // once per path
//     ...
//     arena.reset();                                   // at every hit
//     const Bsdf& base = arena.make<LambertianBsdf>(albedo);
//     const Bsdf& bsdf = arena.make<CoatedBsdf>(base, 1.5f, 0.1f);
//
// make() constructs in place in a fixed buffer (kCapacity bytes, enough for a layered BSDF and
// its base several times over) and throws std::length_error if it is full, which is a
// programming error (a material that builds too many BSDFs), not a runtime condition. reset()
// forgets everything made so far and invalidates every reference make() returned. Only
// trivially destructible types are accepted, so forgetting them needs no destructor calls;
// every model in render/bsdfs/ is one (bsdf.h gives Bsdf a trivial destructor for this).
#pragma once

#include <cstddef>
#include <new>
#include <stdexcept>
#include <type_traits>
#include <utility>

namespace fluence::render {

class BsdfArena {
public:
    static constexpr std::size_t kCapacity = 2048;

    BsdfArena() = default;
    BsdfArena(const BsdfArena&) = delete;
    BsdfArena& operator=(const BsdfArena&) = delete;

    template <typename T, typename... Args>
    T& make(Args&&... args) {
        static_assert(std::is_trivially_destructible_v<T>, "BsdfArena never runs destructors");
        static_assert(alignof(T) <= alignof(std::max_align_t), "over-aligned types are not supported");
        std::size_t start = (used_ + alignof(T) - 1) / alignof(T) * alignof(T);
        if (start + sizeof(T) > kCapacity) throw std::length_error("BsdfArena: capacity exceeded");
        used_ = start + sizeof(T);
        return *::new (static_cast<void*>(buffer_ + start)) T(std::forward<Args>(args)...);
    }

    void reset() { used_ = 0; }

private:
    alignas(std::max_align_t) std::byte buffer_[kCapacity];
    std::size_t used_ = 0;
};

}  // namespace fluence::render
