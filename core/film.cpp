#include "core/film.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace fluence {

namespace {

constexpr std::size_t kDenoiseSumsPerPixel = 12;
constexpr std::size_t kFeatureSquares = 6;  // the squared albedo and normal sums' offset

// The variance of the mean of n samples from their sum and their squares' sum (0 below 2 samples).
double varianceOfMean(double sum, double squares, double n) {
    if (n < 2) return 0.0;
    const double mean = sum / n;
    return std::max(0.0, (squares - n * mean * mean) / (n - 1.0)) / n;
}

}  // namespace

Film::Film(int width, int height, float farDepth, std::vector<std::string> lightPathLayers)
    : width_(width),
      height_(height),
      farDepth_(farDepth),
      pixels_(static_cast<std::size_t>(width) * height),
      lightPathLayers_(std::move(lightPathLayers)) {
    if (lightPathLayers_.size() > std::size_t(kMaxLightPathLayers))
        throw std::invalid_argument("at most " + std::to_string(kMaxLightPathLayers) + " light path expression AOVs");
    lightPathSums_.assign(pixels_.size() * lightPathLayers_.size() * 3, 0.0);
}

void Film::add(int x, int y, const FilmSample& s, double cost) {
    const std::size_t index = static_cast<std::size_t>(y) * width_ + x;
    Pixel& p = pixels_[index];
    if (!denoiseSums_.empty() && std::has_single_bit(p.samples)) {
        // The sample's index is a power of two 2^M: [0, 2^M) is the new upper prefix, the old one
        // the lower (see the top of film.h).
        double* prefixes = denoiseSums_.data() + index * kDenoiseSumsPerPixel;
        for (int c = 0; c < 3; ++c) {
            prefixes[c] = prefixes[3 + c];
            prefixes[3 + c] = p.radiance[c];
        }
    }
    for (int c = 0; c < 3; ++c) p.radiance[c] += s.radiance[c];
    double* layers = lightPathSums_.data() + index * lightPathLayers_.size() * 3;
    for (std::size_t l = 0; l < lightPathLayers_.size(); ++l)
        for (std::size_t c = 0; c < 3; ++c) layers[3 * l + c] += s.lightPaths[3 * l + c];
    if (!denoiseSums_.empty() && s.hit) {
        double* squares = denoiseSums_.data() + index * kDenoiseSumsPerPixel + kFeatureSquares;
        for (int c = 0; c < 3; ++c) {
            squares[c] += double(s.albedo[c]) * s.albedo[c];
            squares[3 + c] += double(s.normal[c]) * s.normal[c];
        }
    }
    const double brightness = luminance(s.radiance);
    p.luminance += brightness;
    p.luminanceSquared += brightness * brightness;
    if (s.hit) {
        for (int c = 0; c < 3; ++c) {
            p.albedo[c] += s.albedo[c];
            p.normal[c] += s.normal[c];
        }
        p.coverage += 1.0;
        p.minDepth = p.anyHit ? std::min(p.minDepth, s.depth) : s.depth;
        p.anyHit = true;
    }
    p.cost += cost;
    ++p.samples;
}

std::vector<std::string> Film::channelNames() const {
    std::vector<std::string> names{"R",        "G",   "B",   "A",   "albedo.R", "albedo.G",
                                   "albedo.B", "N.X", "N.Y", "N.Z", "Z",        "sampleCount"};
    for (const std::string& layer : lightPathLayers_)
        for (const char* c : {".R", ".G", ".B"}) names.push_back(layer + c);
    return names;
}

std::vector<std::string> Film::dataChannelNames() { return {"N.X", "N.Y", "N.Z", "Z", "sampleCount"}; }

SplatFilm& Film::enableSplats() {
    if (!splats_) splats_ = std::make_unique<SplatFilm>(width_, height_, 0, 0, int(lightPathLayers_.size()));
    return *splats_;
}

void Film::enableDenoiseBuffers() {
    if (denoiseSums_.empty()) denoiseSums_.assign(pixels_.size() * kDenoiseSumsPerPixel, 0.0);
}

std::vector<std::string> Film::denoiseBufferChannelNames() {
    return {"half0.R",          "half0.G",          "half0.B",     "half1.R",     "half1.G",
            "half1.B",          "variance.R",       "variance.G",  "variance.B",  "albedoVariance.R",
            "albedoVariance.G", "albedoVariance.B", "NVariance.X", "NVariance.Y", "NVariance.Z"};
}

Image Film::resolveDenoiseBuffers() const {
    if (denoiseSums_.empty()) throw std::logic_error("Film::resolveDenoiseBuffers: the buffers are not enabled");
    Image image(width_, height_, denoiseBufferChannelNames());
    const std::uint64_t samples = totalSamples();
    const double perLightPath = samples > 0 ? double(width_) * double(height_) / double(samples) : 0.0;
    for (int y = 0; y < height_; ++y)
        for (int x = 0; x < width_; ++x) {
            const std::size_t index = static_cast<std::size_t>(y) * width_ + x;
            const Pixel& p = pixels_[index];
            const double* squares = denoiseSums_.data() + index * kDenoiseSumsPerPixel + kFeatureSquares;
            const double n = p.samples;
            const std::array<double, 3> splat = splats_ ? splats_->sum(x, y) : std::array<double, 3>{};
            const HalfMeans halves = halfMeans(x, y);
            float* out = image.pixel(x, y);
            for (std::size_t c = 0; c < 3; ++c) {
                const double added = splat[c] * perLightPath;
                out[c] = static_cast<float>(halves.first[c] + added);
                out[3 + c] = static_cast<float>(halves.second[c] + added);
                out[6 + c] = static_cast<float>(halves.meanVariance(c));
                out[9 + c] = static_cast<float>(varianceOfMean(p.albedo[c], squares[c], n));
                out[12 + c] = static_cast<float>(varianceOfMean(p.normal[c], squares[3 + c], n));
            }
        }
    return image;
}

Film::HalfMeans Film::halfMeans(int x, int y) const {
    if (denoiseSums_.empty()) throw std::logic_error("Film::halfMeans: the denoiser's buffers are not enabled");
    const std::size_t index = static_cast<std::size_t>(y) * width_ + x;
    const Pixel& p = pixels_[index];
    HalfMeans h{};
    const std::uint32_t n = p.samples;
    if (n == 0) return h;
    if (n == 1) {
        for (std::size_t c = 0; c < 3; ++c) h.first[c] = h.second[c] = p.radiance[c];
        h.firstCount = 1;
        return h;
    }
    // n = 2^M + k, 1 <= k <= 2^M: the first half is [0, 2^(M-1)) when k < 2^(M-1), else [0, 2^M).
    const std::uint32_t upper = std::bit_floor(n - 1), lower = upper / 2;
    const bool lowerSplit = n - upper < lower;
    const double* prefix = denoiseSums_.data() + index * kDenoiseSumsPerPixel + (lowerSplit ? 0 : 3);
    h.firstCount = lowerSplit ? lower : upper;
    h.secondCount = n - h.firstCount;
    for (std::size_t c = 0; c < 3; ++c) {
        h.first[c] = prefix[c] / h.firstCount;
        h.second[c] = (p.radiance[c] - prefix[c]) / h.secondCount;
    }
    return h;
}

double Film::HalfMeans::meanVariance(std::size_t c) const {
    if (firstCount == 0 || secondCount == 0) return 0.0;
    const double difference = first[c] - second[c], n = double(firstCount) + double(secondCount);
    return difference * difference * double(firstCount) * double(secondCount) / (n * n);
}

Image Film::resolve() const {
    Image image(width_, height_, channelNames());
    const std::uint64_t samples = totalSamples();
    const double perLightPath = samples > 0 ? double(width_) * double(height_) / double(samples) : 0.0;
    for (int y = 0; y < height_; ++y)
        for (int x = 0; x < width_; ++x) {
            const Pixel& p = pixels_[static_cast<std::size_t>(y) * width_ + x];
            float* out = image.pixel(x, y);
            double inv = p.samples > 0 ? 1.0 / p.samples : 0.0;
            const std::array<double, 3> splat = splats_ ? splats_->sum(x, y) : std::array<double, 3>{};
            for (int c = 0; c < 3; ++c)
                out[c] = static_cast<float>(p.radiance[c] * inv + splat[std::size_t(c)] * perLightPath);
            out[3] = static_cast<float>(p.coverage * inv);
            for (int c = 0; c < 3; ++c) out[4 + c] = static_cast<float>(p.albedo[c] * inv);
            for (int c = 0; c < 3; ++c) out[7 + c] = static_cast<float>(p.normal[c] * inv);
            out[10] = p.anyHit ? p.minDepth : farDepth_;
            out[11] = static_cast<float>(p.samples);
            const double* layers =
                lightPathSums_.data() + (static_cast<std::size_t>(y) * width_ + x) * lightPathLayers_.size() * 3;
            for (std::size_t l = 0; l < lightPathLayers_.size(); ++l) {
                const std::array<double, 3> layerSplat =
                    splats_ ? splats_->layerSum(int(l), x, y) : std::array<double, 3>{};
                for (std::size_t c = 0; c < 3; ++c)
                    out[12 + 3 * l + c] = static_cast<float>(layers[3 * l + c] * inv + layerSplat[c] * perLightPath);
            }
        }
    return image;
}

double Film::relativeError(int x, int y) const {
    const Pixel& p = pixel(x, y);
    if (p.samples < 2) return std::numeric_limits<double>::infinity();
    const double n = p.samples, mean = p.luminance / n;
    return std::sqrt(varianceOfMean(p.luminance, p.luminanceSquared, n)) / (std::abs(mean) + kRelativeErrorFloor);
}

std::uint64_t Film::totalSamples() const {
    std::uint64_t n = 0;
    for (const Pixel& p : pixels_) n += p.samples;
    return n;
}

}  // namespace fluence
