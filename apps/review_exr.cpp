#include "apps/review_exr.h"

#include <OpenImageIO/imageio.h>

#include <map>
#include <memory>

#include "apps/json.h"
#include "apps/review_files.h"

namespace fluence::app {

namespace {

std::unique_ptr<OIIO::ImageInput> openImage(const std::string& path) {
    auto in = OIIO::ImageInput::open(path);
    if (!in) throw ReviewInputError(path + ": cannot read the image: " + OIIO::geterror());
    return in;
}

std::string layerOf(const std::string& channel) {
    const std::size_t dot = channel.rfind('.');
    if (dot != std::string::npos) return channel.substr(0, dot);
    if (channel == "R" || channel == "G" || channel == "B" || channel == "A") return "rgba";
    return channel;
}

ReviewImage describe(const OIIO::ImageSpec& spec) {
    ReviewImage image;
    image.width = spec.width;
    image.height = spec.height;
    std::map<std::string, std::size_t> layerIndex;
    for (int c = 0; c < spec.nchannels; ++c) {
        const std::string& channel = spec.channelnames[std::size_t(c)];
        const std::string name = layerOf(channel);
        auto [it, inserted] = layerIndex.try_emplace(name, image.layers.size());
        if (inserted) image.layers.push_back({name, {}, {}, true});
        ReviewLayer& layer = image.layers[it->second];
        layer.channels.push_back(channel);
        layer.indices.push_back(c);
        layer.half = layer.half && spec.channelformat(c) == OIIO::TypeDesc::HALF;
    }
    for (const OIIO::ParamValue& p : spec.extra_attribs)
        image.attributes.emplace_back(p.name().string(), p.get_string(1 << 20));
    return image;
}

}  // namespace

ReviewImage readReviewImage(const std::string& path) { return describe(openImage(path)->spec()); }

std::string reviewImageJson(const ReviewImage& image) {
    std::string json =
        "{\"width\":" + std::to_string(image.width) + ",\"height\":" + std::to_string(image.height) + ",\"layers\":[";
    for (std::size_t i = 0; i < image.layers.size(); ++i) {
        const ReviewLayer& l = image.layers[i];
        json += (i ? "," : "") + std::string("{\"name\":") + jsonQuoted(l.name) + ",\"format\":\"" +
                (l.half ? "half" : "float") + "\",\"channels\":[";
        for (std::size_t c = 0; c < l.channels.size(); ++c) json += (c ? "," : "") + jsonQuoted(l.channels[c]);
        json += "]}";
    }
    json += "],\"attributes\":{";
    std::map<std::string, std::map<std::string, std::string>> cryptomatte;  // by key: name, manifest
    for (std::size_t i = 0; i < image.attributes.size(); ++i) {
        const auto& [name, value] = image.attributes[i];
        json += (i ? "," : "") + jsonQuoted(name) + ":" + jsonQuoted(value);
        if (name.rfind("cryptomatte/", 0) == 0) {
            const std::size_t slash = name.find('/', 12);
            if (slash != std::string::npos) cryptomatte[name.substr(12, slash - 12)][name.substr(slash + 1)] = value;
        }
    }
    json += "},\"cryptomatte\":[";
    bool first = true;
    for (auto& [key, fields] : cryptomatte) {
        json += (first ? "" : ",") + std::string("{\"key\":") + jsonQuoted(key) +
                ",\"name\":" + jsonQuoted(fields["name"]) + ",\"manifest\":" + jsonQuoted(fields["manifest"]) + "}";
        first = false;
    }
    return json + "]}";
}

std::string readReviewLayerPixels(const std::string& path, const std::string& layerName) {
    auto in = openImage(path);
    const OIIO::ImageSpec& spec = in->spec();
    const ReviewImage image = describe(spec);
    const ReviewLayer* layer = nullptr;
    for (const ReviewLayer& l : image.layers)
        if (l.name == layerName) layer = &l;
    if (!layer) throw ReviewInputError(path + ": no layer '" + layerName + "'");
    const OIIO::TypeDesc format = layer->half ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::FLOAT;
    const std::size_t pixels = std::size_t(spec.width) * std::size_t(spec.height);
    const std::size_t channels = layer->indices.size();
    const std::size_t size = format.size();
    std::string bytes(pixels * channels * size, '\0');
    std::string plane(pixels * size, '\0');
    for (std::size_t c = 0; c < channels; ++c) {
        const int index = layer->indices[c];
        if (!in->read_image(0, 0, index, index + 1, format, plane.data()))
            throw ReviewInputError(path + ": cannot read channel " + layer->channels[c] + ": " + in->geterror());
        for (std::size_t p = 0; p < pixels; ++p)
            std::copy_n(plane.data() + p * size, size, bytes.data() + (p * channels + c) * size);
    }
    return bytes;
}

}  // namespace fluence::app
