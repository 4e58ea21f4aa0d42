// A piecewise-constant density over the unit square, one cell per texel of a width x height
// grid of non-negative weights (row 0 at v = 0): the dome light samples its lat-long image with
// it. sample() picks a row from the marginal distribution of the rows' sums, then a column from
// that row's conditional distribution, each by inverting its cumulative distribution, and places
// the point within the cell by the remainder of u; pdf(uv) = weight(cell) / mean weight.
// All-zero weights give the uniform density.
#pragma once

#include <vector>

#include "core/vec.h"

namespace fluence::render {

class ImageDistribution {
public:
    ImageDistribution() = default;
    ImageDistribution(int width, int height, std::vector<float> weights);  // row-major

    struct Sample {
        Vec2f uv;
        float pdf = 0.0f;  // density with respect to area on the unit square
    };
    Sample sample(Vec2f u) const;
    float pdf(Vec2f uv) const;

private:
    int width_ = 0, height_ = 0;
    std::vector<float> weights_;
    float meanWeight_ = 0.0f;
    std::vector<float> rowCdf_;     // height + 1 entries, from 0 to 1
    std::vector<float> columnCdf_;  // height rows of width + 1 entries, each from 0 to 1
};

}  // namespace fluence::render
