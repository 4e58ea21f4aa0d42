// The CPU reference of the review page's pixels: an EXR's beauty through OCIO's CPU processor for
// a display, view, look, exposure and gamma (color/display_pipeline.h, the pipeline the page's
// shader comes from), clamped to [0, 1] and rounded to 8 bits as WebGL2 stores a float colour.
//   review_reference IMAGE.exr DISPLAY VIEW LOOK EXPOSURE GAMMA > OUT.rgba   (rows from the top)
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "color/display_pipeline.h"

int main(int argc, char** argv) {
    if (argc != 7) {
        std::fputs("usage: review_reference IMAGE.exr DISPLAY VIEW LOOK EXPOSURE GAMMA > OUT.rgba\n", stderr);
        return 2;
    }
    auto in = OIIO::ImageInput::open(argv[1]);
    if (!in) {
        std::fprintf(stderr, "review_reference: cannot read %s: %s\n", argv[1], OIIO::geterror().c_str());
        return 1;
    }
    const OIIO::ImageSpec& spec = in->spec();
    const std::size_t pixels = std::size_t(spec.width) * std::size_t(spec.height);
    std::vector<float> rgba(pixels * 4, 1.0f);
    const int r = spec.channelindex("R");
    for (int c = 0; c < 3; ++c)
        if (!in->read_image(0, 0, r + c, r + c + 1, OIIO::TypeDesc::FLOAT, rgba.data() + c, 4 * sizeof(float))) {
            std::fprintf(stderr, "review_reference: %s: %s\n", argv[1], in->geterror().c_str());
            return 1;
        }
    // The config as the render chose it: $OCIO, else the built-in one.
    const auto pipeline = fluence::color::DisplayPipeline::open();
    fluence::color::DisplaySettings settings{argv[2], argv[3], argv[4], std::stod(argv[5]), std::stod(argv[6])};
    pipeline.applyCpu(pipeline.inputSpace(spec.get_string_attribute("colorSpace")), settings, rgba.data(), pixels);
    std::vector<unsigned char> bytes(pixels * 4);
    for (std::size_t i = 0; i < rgba.size(); ++i) {
        const float v = (i % 4 == 3) ? 1.0f : rgba[i];
        bytes[i] = static_cast<unsigned char>(std::lround(std::clamp(std::isnan(v) ? 0.0f : v, 0.0f, 1.0f) * 255.0f));
    }
    return std::fwrite(bytes.data(), 1, bytes.size(), stdout) == bytes.size() ? 0 : 1;
}
