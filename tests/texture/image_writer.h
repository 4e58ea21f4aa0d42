// Writes small test images through OpenImageIO (the texture and light-adapter tests read them
// back): colour as given, never un-premultiplied by alpha.
#pragma once

#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <string>
#include <vector>

namespace fluence::test {

template <typename T>
void writeImage(const std::string& path, int width, int height, int channels, OIIO::TypeDesc type,
                const std::vector<T>& pixels) {
    auto out = OIIO::ImageOutput::create(path);
    ASSERT_TRUE(out) << OIIO::geterror();
    OIIO::ImageSpec spec(width, height, channels, type);
    spec.attribute("oiio:UnassociatedAlpha", 1);
    ASSERT_TRUE(out->open(path, spec)) << out->geterror();
    ASSERT_TRUE(out->write_image(type, pixels.data())) << out->geterror();
    out->close();
}

// An n x n one-channel float image of one-texel squares, 0 where x + y is even, 1 where odd.
inline void writeTexelChecker(const std::string& path, int n) {
    std::vector<float> pixels(std::size_t(n) * n);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) pixels[std::size_t(y) * n + x] = float((x + y) % 2);
    writeImage<float>(path, n, n, 1, OIIO::TypeDesc::FLOAT, pixels);
}

// A 2 x 1 RGB float image at `path`, returned: left half (s < 1/2) green 0.5, right half white 4
// (exact at the texel centres).
inline std::string writeHalvesTexture(const std::string& path) {
    writeImage<float>(path, 2, 1, 3, OIIO::TypeDesc::FLOAT, {0, 0.5f, 0, 4, 4, 4});
    return path;
}

}  // namespace fluence::test
