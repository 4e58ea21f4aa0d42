// An existing EXR's channels as an Image, and the same file written again with other channels
// (`fluence denoise`): the header's attributes, data and display windows kept as they are.
#pragma once

#include <stdexcept>
#include <string>

#include "core/image.h"

namespace fluence::output {

// The file cannot be opened or read as an image; the message names it.
class ImageReadError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Every channel of the image at `path`, as floats. Throws ImageReadError.
Image readImageChannels(const std::string& path);

// Writes `image` (of `source`'s size) to `path` as an EXR with `source`'s header attributes and
// windows, every channel 32-bit float, atomically. Throws ImageReadError when `source` cannot be
// read, OutputError when `path` cannot be written.
void writeExrLike(const std::string& source, const std::string& path, const Image& image);

}  // namespace fluence::output
