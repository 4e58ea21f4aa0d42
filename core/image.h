// A resolved image: named float channels, interleaved, row 0 at the top.
//
// The film resolves its per-pixel sums into an Image (beauty R,G,B plus AOV channels with
// Nuke-style layer names such as "albedo.R", "N.X", "Z"); output/ writes Images to files.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace fluence {

struct Image {
    int width = 0;
    int height = 0;
    std::vector<std::string> channels;  // e.g. {"R","G","B","albedo.R",...}
    std::vector<float> pixels;          // width*height*channels.size(), interleaved, row-major

    Image() = default;
    Image(int w, int h, std::vector<std::string> names)
        : width(w),
          height(h),
          channels(std::move(names)),
          pixels(static_cast<std::size_t>(w) * h * channels.size(), 0.0f) {}

    std::size_t channelCount() const { return channels.size(); }
    // Index of a channel by name, or -1.
    int channelIndex(const std::string& name) const {
        for (std::size_t i = 0; i < channels.size(); ++i)
            if (channels[i] == name) return static_cast<int>(i);
        return -1;
    }
    float* pixel(int x, int y) { return pixels.data() + (static_cast<std::size_t>(y) * width + x) * channels.size(); }
    const float* pixel(int x, int y) const {
        return pixels.data() + (static_cast<std::size_t>(y) * width + x) * channels.size();
    }
};

}  // namespace fluence
