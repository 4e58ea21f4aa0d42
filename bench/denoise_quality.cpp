// The denoiser's quality against a reference: `denoise_quality REF.exr IMAGE.exr...` prints a CSV
// header and, for each image (rendered with --denoise), one row: its relMSE, denoised (its RGB) and
// noisy (its noisy.R/G/B), over the whole image and over its textured region (the pixels whose
// albedo differs from a neighbour's by more than 0.05); the reference's own share of those
// figures; and the relative bias of each image's mean with its standard error. Results:
// bench/results/2026-12-05-denoise-3.md.
//
// relMSE = mean over pixels and channels of (x - ref)² / (ref² + 0.01). The reference's noise adds
// its variance Vref to each pixel's expected (x - ref)²: the column ref_noise is the mean of
// Vref / (ref² + 0.01), Vref from the reference's variance channel (rendered with
// --denoise-buffers). It is not taken off: that channel, from the difference of the halves (each a
// Sobol net), still over-states the error of the whole net under the default (Owen-scrambled Sobol)
// sampler (by up to about 8 where the integrand is smooth: tests/core/film_half_buffers_test.cpp),
// so the difference would not estimate the error against the true image.
//
// Bias: (mean of x - mean of ref) / mean of ref, means over pixels and R G B. Its standard error:
// the pixels are independent, so the variance of a mean of n values is the sum of their variances
// over n²; the noisy image's pixel variance is its variance channel, the reference's its own (both
// over-stated under Sobol, less since the halves split nets, so the error is a generous one). The denoised image is given the noisy
// one's: each of its pixels is a weighted mean, with weights summing to one, of the noisy pixels
// around it, so over the whole image it sums nearly the same noise (an approximation: it
// underestimates where the weights pile onto a few pixels).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "core/image.h"
#include "output/exr_channels.h"

namespace {

using fluence::Image;

bool textured(const Image& image, int x, int y) {
    const int albedo = image.channelIndex("albedo.R");
    if (albedo < 0) return false;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            const int xx = std::clamp(x + dx, 0, image.width - 1), yy = std::clamp(y + dy, 0, image.height - 1);
            for (int c = 0; c < 3; ++c)
                if (std::abs(image.pixel(xx, yy)[albedo + c] - image.pixel(x, y)[albedo + c]) > 0.05f) return true;
        }
    return false;
}

// relMSE of channels `first`.. (R G B) of `image` against the reference's R G B, over the pixels
// `texturedOnly` selects; NaN when the image lacks them.
double relMse(const Image& reference, const Image& image, const std::string& first, bool texturedOnly) {
    const int c0 = image.channelIndex(first), r0 = reference.channelIndex("R");
    if (c0 < 0 || r0 < 0) return NAN;
    double sum = 0.0, count = 0.0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            if (texturedOnly && !textured(image, x, y)) continue;
            for (int c = 0; c < 3; ++c) {
                const double ref = reference.pixel(x, y)[r0 + c], v = image.pixel(x, y)[c0 + c];
                sum += (v - ref) * (v - ref) / (ref * ref + 0.01);
                count += 1.0;
            }
        }
    return count > 0 ? sum / count : NAN;
}

// The reference's share of the relMSE: the mean of variance.R/G/B / (R/G/B² + 0.01); NaN without it.
double referenceNoise(const Image& reference) {
    const int r0 = reference.channelIndex("R"), v0 = reference.channelIndex("variance.R");
    if (r0 < 0 || v0 < 0) return NAN;
    double sum = 0.0;
    for (int y = 0; y < reference.height; ++y)
        for (int x = 0; x < reference.width; ++x)
            for (int c = 0; c < 3; ++c) {
                const double ref = reference.pixel(x, y)[r0 + c];
                sum += reference.pixel(x, y)[v0 + c] / (ref * ref + 0.01);
            }
    return sum / (3.0 * reference.width * reference.height);
}

// The mean over pixels and R G B of channels `first`.., and the sum of channels `variance`..
struct ImageMean {
    double mean = 0, varianceSum = 0;
};
ImageMean imageMean(const Image& image, const std::string& first, const std::string& variance) {
    const int c0 = image.channelIndex(first), v0 = image.channelIndex(variance);
    ImageMean m;
    if (c0 < 0) return {NAN, NAN};
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            for (int c = 0; c < 3; ++c) {
                m.mean += image.pixel(x, y)[c0 + c];
                m.varianceSum += v0 < 0 ? 0.0 : image.pixel(x, y)[v0 + c];
            }
    m.mean /= 3.0 * image.width * image.height;
    return m;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(stderr, "usage: denoise_quality REF.exr IMAGE.exr...\n");
        return 2;
    }
    try {
        const Image reference = fluence::output::readImageChannels(argv[1]);
        const ImageMean ref = imageMean(reference, "R", "variance.R");
        std::printf(
            "image,relmse_denoised,relmse_noisy,relmse_textured_denoised,relmse_textured_noisy,"
            "ref_noise,bias_denoised,bias_noisy,bias_standard_error\n");
        for (int i = 2; i < argc; ++i) {
            const Image image = fluence::output::readImageChannels(argv[i]);
            if (image.width != reference.width || image.height != reference.height) {
                std::fprintf(stderr, "%s: not the reference's size\n", argv[i]);
                return 3;
            }
            const ImageMean denoised = imageMean(image, "R", "variance.R"), noisy = imageMean(image, "noisy.R", "");
            const double n = 3.0 * image.width * image.height;
            const double standardError = std::sqrt(denoised.varianceSum + ref.varianceSum) / n / ref.mean;
            std::printf("%s,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g\n", argv[i], relMse(reference, image, "R", false),
                        relMse(reference, image, "noisy.R", false), relMse(reference, image, "R", true),
                        relMse(reference, image, "noisy.R", true), referenceNoise(reference),
                        (denoised.mean - ref.mean) / ref.mean, (noisy.mean - ref.mean) / ref.mean, standardError);
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "denoise_quality: %s\n", e.what());
        return 4;
    }
    return 0;
}
