// FLUENCE_DCHECK(condition): a debug-only assertion for the hot paths (BSDF and light sampling,
// where a check per call is too dear for renders that are measured).
//
//   Active      when FLUENCE_DCHECKS is defined: Debug builds and the sanitizer build
//               (CMake option FLUENCE_SANITIZE, scripts/sanitizer_tests.sh) define it, as does
//               -DFLUENCE_DCHECKS=ON in any build. A failed check prints the condition, file and
//               line to stderr and aborts (a test under ctest fails; the sanitizer pass reports it).
//   Compiled out in Release (the default build, `make render`, the benchmarks): the condition is
//               not evaluated, so it may call functions freely, but it is still compiled (inside
//               sizeof), so it cannot rot.
//
// Check what a caller relies on and a bug would silently break: unit directions, densities >= 0
// and finite, finite sample values. Not for input validation (bad scenes must give an error
// message in every build: throw) and never for something with a side effect.
#pragma once

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "core/vec.h"

namespace fluence {

[[noreturn]] inline void dcheckFailed(const char* condition, const char* file, int line) {
    std::fprintf(stderr, "%s:%d: FLUENCE_DCHECK(%s) failed\n", file, line, condition);
    std::abort();
}

// Whether w is a unit vector, to the rounding of a float normalisation (and then some: directions
// built from products of unit vectors drift by a few ULPs).
inline bool isUnit(const Vec3f& w) { return std::abs(lengthSquared(w) - 1.0f) < 1e-3f; }

// Whether a density is usable: finite and not negative.
inline bool isValidDensity(float pdf) { return pdf >= 0.0f && std::isfinite(pdf); }

}  // namespace fluence

#if defined(FLUENCE_DCHECKS)
#define FLUENCE_DCHECK(condition) \
    ((condition) ? static_cast<void>(0) : ::fluence::dcheckFailed(#condition, __FILE__, __LINE__))
#else
#define FLUENCE_DCHECK(condition) static_cast<void>(sizeof(static_cast<bool>(condition)))
#endif
