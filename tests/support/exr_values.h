// The values of some channels of an EXR read back by tests/support/cli.h's readExr, to compare
// images channel by channel.
#pragma once

#include <string>
#include <vector>

#include "tests/support/cli.h"

namespace fluence::test {

// Channels `names` of every pixel of `image`, interleaved, row by row.
inline std::vector<float> channelValues(const ExrImage& image, const std::vector<std::string>& names) {
    std::vector<float> out;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            for (const std::string& name : names) out.push_back(image.at(x, y, name));
    return out;
}

}  // namespace fluence::test
