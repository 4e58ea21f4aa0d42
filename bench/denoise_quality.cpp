// The denoiser's quality against a reference: `denoise_quality REF.exr IMAGE.exr...` prints, for
// each image, the relMSE of its RGB (the denoised beauty after --denoise) and of its noisy.R/G/B
// against the reference's RGB, over the whole image and over its textured region (the pixels
// whose albedo differs from a neighbour's by more than 0.05). relMSE = mean of (x - ref)² /
// (ref² + 0.01) over pixels and channels. Results: bench/results/2026-12-05-denoise.md.
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
// `texturedOnly` selects; -1 when the image lacks them.
double relMse(const Image& reference, const Image& image, const std::string& first, bool texturedOnly) {
    const int c0 = image.channelIndex(first), r0 = reference.channelIndex("R");
    if (c0 < 0 || r0 < 0) return -1.0;
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
    return count > 0 ? sum / count : -1.0;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(stderr, "usage: denoise_quality REF.exr IMAGE.exr...\n");
        return 2;
    }
    try {
        const Image reference = fluence::output::readImageChannels(argv[1]);
        std::printf("%-40s %12s %12s %8s %14s %14s\n", "image", "relMSE", "noisy", "gain", "textured",
                    "textured noisy");
        for (int i = 2; i < argc; ++i) {
            const Image image = fluence::output::readImageChannels(argv[i]);
            if (image.width != reference.width || image.height != reference.height) {
                std::fprintf(stderr, "%s: not the reference's size\n", argv[i]);
                return 3;
            }
            const double denoised = relMse(reference, image, "R", false),
                         noisy = relMse(reference, image, "noisy.R", false);
            std::printf("%-40s %12.6f %12.6f %8.2f %14.6f %14.6f\n", argv[i], denoised, noisy,
                        denoised > 0 && noisy > 0 ? noisy / denoised : 0.0, relMse(reference, image, "R", true),
                        relMse(reference, image, "noisy.R", true));
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "denoise_quality: %s\n", e.what());
        return 4;
    }
    return 0;
}
