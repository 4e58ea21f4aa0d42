// A quadrant-symmetric type C candela table for the IES tests, and its value at any direction by
// the LM-63 rules, computed here from the table alone: the horizontal angle folded into 0-90
// degrees by the quadrant symmetry, then bilinear interpolation between the listed angles.
#pragma once

#include <algorithm>
#include <cmath>

#include "texture/ies_file.h"

namespace fluence::test {

// Vertical 0..180 every 15 degrees, horizontal 0, 30, 60, 90: a downlight brighter towards
// horizontal angle 0, times `scale`.
inline texture::IesTable quadrantTable(float scale = 1.0f) {
    texture::IesTable t;
    for (int v = 0; v <= 180; v += 15) t.verticalDegrees.push_back(float(v));
    t.horizontalDegrees = {0.0f, 30.0f, 60.0f, 90.0f};
    for (float h : t.horizontalDegrees)
        for (float v : t.verticalDegrees)
            t.candela.push_back(scale * float(50.0 + 900.0 * std::pow(std::cos(v * M_PI / 360.0), 6.0) *
                                                         (1.0 + 0.6 * std::cos(h * M_PI / 180.0))));
    return t;
}

// The table's candela at vertical angle v and horizontal angle h (degrees, any h).
inline double tableCandela(const texture::IesTable& t, double v, double h) {
    h = std::fmod(std::fmod(h, 360.0) + 360.0, 360.0);
    if (h > 180.0) h = 360.0 - h;
    if (h > 90.0) h = 180.0 - h;
    auto locate = [](const std::vector<float>& grid, double x) {
        std::size_t i = 0;
        while (i + 2 < grid.size() && x > grid[i + 1]) ++i;
        return std::pair{i, std::clamp((x - grid[i]) / (grid[i + 1] - grid[i]), 0.0, 1.0)};
    };
    auto [vi, vt] = locate(t.verticalDegrees, v);
    auto [hi, ht] = locate(t.horizontalDegrees, h);
    auto at = [&](std::size_t a, std::size_t b) { return double(t.at(a, b)); };
    double lo = at(hi, vi) + vt * (at(hi, vi + 1) - at(hi, vi));
    double up = at(hi + 1, vi) + vt * (at(hi + 1, vi + 1) - at(hi + 1, vi));
    return lo + ht * (up - lo);
}

}  // namespace fluence::test
