// A piecewise-constant density over the unit square, one cell per texel of a width x height
// grid of non-negative weights (row 0 at v = 0): the dome light samples its lat-long image with
// it, and the rect light its texture (with luminanceWeights()). sample() picks a row from the
// marginal distribution of the rows' sums, then a column from that row's conditional
// distribution, each by inverting its cumulative distribution (a guide table per distribution
// starts the search next to the answer), and places the point within the cell by the remainder
// of u; pdf(uv) = weight(cell) / mean weight. All-zero weights give the uniform density.
#pragma once

#include <vector>

#include "core/rgb.h"
#include "core/vec.h"

namespace fluence::render {

struct RgbImage;

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
    std::vector<float> rowCdf_;                // height + 1 entries, from 0 to 1
    std::vector<float> columnCdf_;             // height rows of width + 1 entries, each from 0 to 1
    std::vector<int> rowGuide_, columnGuide_;  // where the search for u starts (one per cell)
};

// Weights that sample an emitting image by its luminance: luminance(scale x texel) per texel,
// row-major, with negative channels counted as 0 and a non-finite result as 0, so that every
// texel with some positive channel has a positive weight and ImageDistribution accepts them all.
std::vector<float> luminanceWeights(const RgbImage& image, const RGB& scale);

}  // namespace fluence::render
