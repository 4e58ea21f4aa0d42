#include "volumes/blackbody_radiance.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "core/blackbody.h"

namespace fluence::volumes {

namespace {

constexpr float kLowest = 100.0f, kHighest = 20000.0f, kStep = 5.0f;
constexpr double kStefanBoltzmann = 5.670374419e-8;  // W m^-2 K^-4
constexpr double kScale = 1e-6;                      // Cycles' scale (see MODEL)

const std::vector<RGB>& colourTable() {
    static const std::vector<RGB> table = [] {
        std::vector<RGB> t;
        for (float kelvin = kLowest; kelvin <= kHighest; kelvin += kStep) t.push_back(blackbodyRgb(kelvin));
        return t;
    }();
    return table;
}

}  // namespace

RGB blackbodyRadiance(float kelvin) {
    if (!(kelvin >= kLowest)) return RGB(0.0f);
    RGB colour;
    if (kelvin < kHighest) {
        const std::vector<RGB>& table = colourTable();
        float x = (kelvin - kLowest) / kStep;
        std::size_t i = std::min(std::size_t(x), table.size() - 2);
        float f = x - float(i);
        colour = table[i] * (1.0f - f) + table[i + 1] * f;
    } else {
        colour = blackbodyRgb(kelvin);
    }
    double t2 = double(kelvin) * kelvin;
    return colour * float(kStefanBoltzmann / std::numbers::pi * kScale * t2 * t2);
}

}  // namespace fluence::volumes
