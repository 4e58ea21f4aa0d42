#include "integrators/path_classes.h"

namespace fluence::integrators {

std::string describePathClasses(unsigned mask) {
    static const char* const kNames[] = {
        "LE",      "LDE",        "L(D)S+E",     "LD(D|S)*DE", "LS+D...E (caustics)", "caustics from delta lights",
        "volumes", "subsurface", "delta lights"};
    std::string out;
    for (unsigned bit = 0; bit < kPathClassCount; ++bit)
        if (mask & (1u << bit)) out += (out.empty() ? "" : ", ") + std::string(kNames[bit]);
    return out.empty() ? "none" : out;
}

}  // namespace fluence::integrators
