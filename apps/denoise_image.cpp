#include "apps/denoise_image.h"

#include <algorithm>

namespace fluence::app {

namespace {

const char* const kRGB[] = {".R", ".G", ".B"};

std::vector<std::string> colourChannels(const std::string& layer) {
    return {layer + kRGB[0], layer + kRGB[1], layer + kRGB[2]};
}

// Sets channels `names` of `image` from `values`, interleaved.
void scatter(Image& image, const std::vector<std::string>& names, const std::vector<float>& values) {
    for (std::size_t n = 0; n < names.size(); ++n) {
        const std::size_t c = std::size_t(image.channelIndex(names[n]));
        for (std::size_t p = 0; p < std::size_t(image.width) * image.height; ++p)
            image.pixels[p * image.channelCount() + c] = values[p * names.size() + n];
    }
}

// A colour denoised: its channels, and those of the noisy copy kept beside it.
struct DenoisedColour {
    std::vector<std::string> channels, noisy;
};

// Writes each colour's denoised values over it, keeping its noisy values first in the noisy copy's
// channels unless the image already has them (an image denoised before). The channels missing
// are added at once, so the image is copied once whatever the number of layers.
void replaceColours(Image& image, const std::vector<DenoisedColour>& colours,
                    const std::vector<const std::vector<float>*>& denoised) {
    Image added(image.width, image.height, {});
    std::vector<bool> keep;
    for (const DenoisedColour& colour : colours) {
        keep.push_back(image.channelIndex(colour.noisy.front()) < 0);
        if (keep.back()) added.channels.insert(added.channels.end(), colour.noisy.begin(), colour.noisy.end());
    }
    if (!added.channels.empty()) {
        added.pixels.assign(std::size_t(image.width) * image.height * added.channels.size(), 0.0f);
        image = withChannels(image, added);
    }
    const std::size_t pixels = std::size_t(image.width) * image.height, stride = image.channelCount();
    for (std::size_t i = 0; i < colours.size(); ++i)
        for (std::size_t c = 0; c < 3 && keep[i]; ++c) {
            const std::size_t from = std::size_t(image.channelIndex(colours[i].channels[c])),
                              to = std::size_t(image.channelIndex(colours[i].noisy[c]));
            for (std::size_t p = 0; p < pixels; ++p) image.pixels[p * stride + to] = image.pixels[p * stride + from];
        }
    for (std::size_t i = 0; i < colours.size(); ++i) scatter(image, colours[i].channels, *denoised[i]);
}

}  // namespace

std::vector<std::string> denoiseInputChannels(const std::vector<std::string>& layers) {
    std::vector<std::string> names{"R", "G", "B", "Z"};
    for (const char* layer : {"half0", "half1", "variance", "albedo"})
        for (const std::string& name : colourChannels(layer)) names.push_back(name);
    names.insert(names.end(), {"N.X", "N.Y", "N.Z"});
    for (const std::string& layer : layers)
        for (const std::string& name : colourChannels(layer)) names.push_back(name);
    return names;
}

std::vector<std::string> lightPathLayersOf(const Image& image) {
    static const std::vector<std::string> kBuffers{"albedo",   "albedoVariance", "half0", "half1",
                                                   "variance", "noisy",          "N"};
    std::vector<std::string> layers;
    for (const std::string& channel : image.channels) {
        if (!channel.ends_with(".R")) continue;
        const std::string layer = channel.substr(0, channel.size() - 2);
        if (std::find(kBuffers.begin(), kBuffers.end(), layer) != kBuffers.end() || layer.ends_with("_noisy") ||
            layer.starts_with("Crypto") || image.channelIndex(layer + ".G") < 0 || image.channelIndex(layer + ".B") < 0)
            continue;
        layers.push_back(layer);
    }
    return layers;
}

void denoiseImage(Image& image, const std::vector<std::string>& layers, int threads) {
    std::string missing;
    for (const std::string& name : denoiseInputChannels(layers))
        if (image.channelIndex(name) < 0) missing += (missing.empty() ? "" : ", ") + name;
    if (!missing.empty())
        throw DenoiseInputError("the image has no " + missing +
                                " channel(s): render it with --denoise or --denoise-buffers to keep the "
                                "denoiser's buffers");
    denoise::DenoiseBuffers buffers;
    buffers.width = image.width;
    buffers.height = image.height;
    buffers.halves[0] = gather(image, colourChannels("half0"));
    buffers.halves[1] = gather(image, colourChannels("half1"));
    buffers.variance = gather(image, colourChannels("variance"));
    buffers.albedo = gather(image, colourChannels("albedo"));
    buffers.normal = gather(image, {"N.X", "N.Y", "N.Z"});
    buffers.depth = gather(image, {"Z"});
    // The features' variance, when the render kept it (images rendered before it was, denoise
    // without it: their features are taken as noise-free).
    const std::vector<std::string> albedoVariance = colourChannels("albedoVariance"),
                                   normalVariance{"NVariance.X", "NVariance.Y", "NVariance.Z"};
    auto present = [&](const std::vector<std::string>& names) {
        return std::all_of(names.begin(), names.end(),
                           [&](const std::string& n) { return image.channelIndex(n) >= 0; });
    };
    if (present(albedoVariance) && present(normalVariance)) {
        buffers.albedoVariance = gather(image, albedoVariance);
        buffers.normalVariance = gather(image, normalVariance);
    }
    for (const std::string& layer : layers) buffers.layers.push_back(gather(image, colourChannels(layer)));
    denoise::DenoiseSettings settings;
    settings.threads = threads;
    const denoise::Denoised denoised = denoise::denoise(buffers, settings);
    std::vector<DenoisedColour> colours{{{"R", "G", "B"}, colourChannels("noisy")}};
    std::vector<const std::vector<float>*> values{&denoised.beauty};
    for (std::size_t l = 0; l < layers.size(); ++l) {
        colours.push_back({colourChannels(layers[l]), colourChannels(layers[l] + "_noisy")});
        values.push_back(&denoised.layers[l]);
    }
    replaceColours(image, colours, values);
}

std::vector<float> gather(const Image& image, const std::vector<std::string>& names) {
    std::vector<int> index;
    for (const std::string& name : names) index.push_back(image.channelIndex(name));
    std::vector<float> out(std::size_t(image.width) * image.height * names.size());
    for (std::size_t p = 0, o = 0; p < std::size_t(image.width) * image.height; ++p)
        for (int i : index) out[o++] = image.pixels[p * image.channelCount() + std::size_t(i)];
    return out;
}

Image withChannels(const Image& image, const Image& extra) {
    std::vector<std::string> names = image.channels;
    names.insert(names.end(), extra.channels.begin(), extra.channels.end());
    Image out(image.width, image.height, names);
    for (std::size_t p = 0, o = 0; p < std::size_t(image.width) * image.height; ++p) {
        for (std::size_t c = 0; c < image.channelCount(); ++c)
            out.pixels[o++] = image.pixels[p * image.channelCount() + c];
        for (std::size_t c = 0; c < extra.channelCount(); ++c)
            out.pixels[o++] = extra.pixels[p * extra.channelCount() + c];
    }
    return out;
}

}  // namespace fluence::app
