// Command-line options of `fluence render`, named after Houdini's husk where husk has the same
// notion, so farm plugins can drive Fluence the way they drive husk.
#pragma once

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace fluence::app {

class UsageError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct RenderOptions {
    std::string scene;
    std::string output;             // -o/--output; default: <scene stem>.exr
    std::string preview;            // --preview FILE.png: an sRGB preview through the OCIO display/view
    std::optional<int> spp;         // --spp N (default 64)
    std::optional<std::pair<int, int>> resolution;  // -r/--res W H
    std::string camera;             // -c/--camera /Prim/Path
    int threads = 0;                // -j/--threads N (0: all cores)
    std::uint64_t seed = 0;         // --seed S
    std::string integrator = "path";  // --integrator NAME
    double timeLimit = 0.0;         // --time-limit SECONDS (0: none)
    int maxDepth = 64;              // --max-depth N
    std::optional<double> frame;    // -f/--frame F (default: the stage's startTimeCode, else USD's default time)
};

inline constexpr int kDefaultSpp = 64;
inline constexpr int kDefaultWidth = 640, kDefaultHeight = 480;

// Parses the arguments after `fluence render`. Throws UsageError with a one-line reason.
RenderOptions parseRenderOptions(const std::vector<std::string>& args);

std::string usageText();

}  // namespace fluence::app
