#include "apps/frame_denoise.h"

#include "apps/denoise_image.h"
#include "apps/stopwatch.h"

#include <algorithm>
#include <cstdio>
#include <ctime>

namespace fluence::app {

bool keepsDenoiseBuffers(const RenderOptions& opt) { return opt.denoise || opt.denoiseBuffers; }

namespace {

// The channels of `resolved` among the denoiser's features (denoiseInputChannels) that `image` lacks.
Image missingFeatures(const Image& resolved, const Image& image) {
    const std::vector<std::string> buffers = Film::denoiseBufferChannelNames();
    std::vector<std::string> names;
    for (const std::string& name : denoiseInputChannels({}))
        if (image.channelIndex(name) < 0 && resolved.channelIndex(name) >= 0 &&
            std::find(buffers.begin(), buffers.end(), name) == buffers.end())
            names.push_back(name);
    Image features(image.width, image.height, names);
    features.pixels = gather(resolved, names);
    return features;
}

// The channel a noisy copy keeps (noisy.X: X; NAME_noisy.X: NAME.X), or "" for another channel.
std::string copiedChannel(const std::string& name) {
    if (name.starts_with("noisy.")) return name.substr(6);
    const std::size_t at = name.find("_noisy.");
    return at == std::string::npos ? std::string() : name.substr(0, at) + name.substr(at + 6);
}

// The header's channel types (when it sets them) for the channels `image` gained after the first
// `before`: 32-bit float, but a noisy copy the type of the channel it copies.
void typeAddedChannels(const Image& image, std::size_t before, output::ExrHeader& header) {
    if (header.channelTypes.empty()) return;
    for (std::size_t c = before; c < image.channelCount(); ++c) {
        const std::string copied = copiedChannel(image.channels[c]);
        const int source = copied.empty() ? -1 : image.channelIndex(copied);
        header.channelTypes.push_back(source >= 0 && std::size_t(source) < before
                                          ? header.channelTypes[std::size_t(source)]
                                          : output::PixelType::Float);
    }
}

}  // namespace

void addDenoiseOutputs(const RenderOptions& opt, const Film& film, const Image& resolved, Image& image,
                       output::ExrHeader& header, WarningLog& warnings, const std::string& path) {
    if (!keepsDenoiseBuffers(opt)) return;
    const std::size_t before = image.channelCount();
    const Image features = missingFeatures(resolved, image);
    for (const std::string& name : features.channels)
        if (name.starts_with("N.") || name == "Z") header.dataChannels.push_back(name);
    image = withChannels(withChannels(image, film.resolveDenoiseBuffers()), features);
    if (opt.denoise && opt.tileCount) {
        warnings(path,
                 "a tile is not denoised (its neighbours are in other tiles): denoise the assembled image "
                 "with 'fluence denoise'");
    } else if (opt.denoise) {
        try {
            const Stopwatch clock;
            const std::clock_t cpuStart = std::clock();
            denoiseImage(image, opt.denoiseLayers ? film.lightPathLayers() : std::vector<std::string>{}, opt.threads);
            const double seconds = clock.seconds(), cpu = double(std::clock() - cpuStart) / CLOCKS_PER_SEC;
            header.floats.push_back({"fluence/denoiseSeconds", float(seconds)});
            std::printf("fluence: denoised %s in %.2f s (%.2f s CPU)\n", path.c_str(), seconds, cpu);
        } catch (const DenoiseInputError& e) {
            warnings(path, std::string("not denoised: ") + e.what());
        }
    }
    typeAddedChannels(image, before, header);
}

}  // namespace fluence::app
