// The mean of an image and its standard error, for checking that two estimators of the same image
// agree (embree_throughput_bench --minimal).
//
// Each pixel's value is the mean of its n samples; its variance is estimated by the sample variance
// of their luminance over n (so at least two samples per pixel are needed, else the error is
// infinite). The image mean is the mean over pixels, and its variance the sum of the pixels'
// variances over the pixel count squared (pixels' samples are independent). Two independent
// estimates are then `standardErrorsApart` standard errors of their difference apart.
#pragma once

#include <cmath>
#include <cstddef>

#include "core/film.h"
#include "core/rgb.h"

namespace fluence::bench {

struct ImageMean {
    RGB rgb{0.0f};               // mean radiance
    double luminance = 0.0;      // mean luminance
    double standardError = 0.0;  // of `luminance`
};

// Adds pixels, in the order given (so a sum made in a fixed order is the same at any thread count).
class ImageMeanSum {
public:
    // A pixel of mean radiance `mean`, mean luminance `luminance` and variance of that mean `variance`.
    void addPixel(const RGB& mean, double luminance, double variance) {
        for (int c = 0; c < 3; ++c) rgb_[c] += mean[c];
        luminance_ += luminance;
        variance_ += variance;
        ++pixels_;
    }
    void add(const ImageMeanSum& o) {
        for (int c = 0; c < 3; ++c) rgb_[c] += o.rgb_[c];
        luminance_ += o.luminance_;
        variance_ += o.variance_;
        pixels_ += o.pixels_;
    }
    ImageMean mean() const {
        const double n = double(pixels_);
        return {RGB(float(rgb_[0] / n), float(rgb_[1] / n), float(rgb_[2] / n)), luminance_ / n,
                std::sqrt(variance_) / n};
    }

private:
    double rgb_[3] = {0.0, 0.0, 0.0};
    double luminance_ = 0.0, variance_ = 0.0;
    std::size_t pixels_ = 0;
};

// The mean of a film's beauty (R G B), with each pixel's variance from its luminance sums: the
// standard error of the pixel's mean is Film::relativeError times (|mean luminance| + the floor).
inline ImageMean filmMean(const Film& film) {
    const Image image = film.resolve();
    const int r = image.channelIndex("R"), g = image.channelIndex("G"), b = image.channelIndex("B");
    ImageMeanSum sum;
    for (int y = 0; y < film.height(); ++y)
        for (int x = 0; x < film.width(); ++x) {
            const float* p =
                &image.pixels[(std::size_t(y) * std::size_t(film.width()) + std::size_t(x)) * image.channelCount()];
            const RGB mean(p[r], p[g], p[b]);
            const double l = luminance(mean);
            const double error = film.relativeError(x, y) * (std::abs(l) + Film::kRelativeErrorFloor);
            sum.addPixel(mean, l, error * error);
        }
    return sum.mean();
}

// How many standard errors of their difference two independent estimates' luminances are apart.
inline double standardErrorsApart(const ImageMean& a, const ImageMean& b) {
    return (a.luminance - b.luminance) /
           std::sqrt(a.standardError * a.standardError + b.standardError * b.standardError);
}

}  // namespace fluence::bench
