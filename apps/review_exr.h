// What `fluence review` reads from an EXR (OIIO): its layers (channels grouped by the name before
// the last dot; R, G, B, A as the layer "rgba" and any other dot-less channel a layer of its own),
// its header attributes and Cryptomatte manifests, and a layer's pixels, losslessly: as float16
// when every channel of the layer is stored as half, else as float32.
#pragma once

#include <string>
#include <vector>

namespace fluence::app {

struct ReviewLayer {
    std::string name;
    std::vector<std::string> channels;  // full channel names, in file order
    std::vector<int> indices;           // their indices in the file
    bool half = false;                  // every channel stored as float16
};

struct ReviewImage {
    int width = 0, height = 0;
    std::vector<ReviewLayer> layers;
    std::vector<std::pair<std::string, std::string>> attributes;  // every header attribute, as text
};

// Throws ReviewInputError naming the file when it cannot be read.
ReviewImage readReviewImage(const std::string& path);

// {"width":..,"height":..,"layers":[{"name","channels","format"}],"attributes":{..},
//  "cryptomatte":[{"name","layer","manifest"}]}
std::string reviewImageJson(const ReviewImage& image);

// The layer's pixels, channels interleaved, rows from the top, as float16 or float32 bytes
// (ReviewLayer::half). Throws ReviewInputError for an unknown layer or a read error.
std::string readReviewLayerPixels(const std::string& path, const std::string& layer);

}  // namespace fluence::app
