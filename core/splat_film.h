// The splat film: light that lands on pixels other than the sample's own (light tracing, bdpt's
// t = 1 strategy), from any thread, summed so that the total does not depend on the order of the
// adds, and so is bit-identical at any thread count and pass division.
//
// FIXED POINT. Each pixel keeps R G B as 64-bit integer sums of value * 2^kFractionBits (2^28:
// steps of 3.7e-9, rounded to nearest), added with atomic compare-and-swap. Integer addition is
// associative, so any order of the same adds gives the same sums. Only finite, non-negative values
// are taken (light-tracing contributions always are; add() refuses the others and the caller
// counts them); a value above kMaxValue (2^32, about 4.3e9) is clamped to it, and a pixel's sum
// saturates at kMaxSum (2^35, about 3.4e10 in the units of the values): with non-negative adds,
// a saturating sum is min(exact sum, limit) whatever the order, so saturation keeps determinism.
// Both limits are far above any radiance a render produces (a sum of 3.4e10 over 4096 samples per
// pixel is a mean of 8.4e6).
//
// WINDOW. The film covers the window of the image at (originX, originY), width x height pixels;
// positions are in the image's pixels, and a splat outside the window is dropped.
//
// LAYERS. Besides the beauty, a pixel may keep the sums of light path expression layers (bdpt's
// t = 1 paths go to the layers whose expressions match them, integrators/bdpt_events.h), each
// summed as the beauty is, so they too are bit-identical at any thread count.
//
// NORMALISATION (Veach's thesis, sec. 10.3.4; pbrt's Film::AddSplat): with the camera's importance
// normalised over the whole image (render/camera.h) and one light path traced per camera sample,
// a pixel's light-tracing estimate is its splat sum divided by the number of light paths per
// pixel of the image, total camera samples / image pixels (core/film.h, Film::resolve).
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <vector>

#include "core/rgb.h"

namespace fluence {

class SplatFilm {
public:
    static constexpr int kFractionBits = 28;
    static constexpr double kMaxValue = 4294967296.0;  // 2^32: larger values are clamped to it
    // A pixel's sum saturates at the largest int64, 2^35 in the units of the values.

    // The window of the image at (originX, originY), width x height pixels, with `layers` light
    // path layers besides the beauty.
    SplatFilm(int width, int height, int originX = 0, int originY = 0, int layers = 0);

    int width() const { return width_; }
    int height() const { return height_; }
    int layers() const { return layers_; }

    // Adds `value` to the pixel holding image position (x, y), in pixels (dropped outside the
    // window). False, adding nothing, when a channel of `value` is not finite or is negative.
    // Thread-safe.
    bool add(float x, float y, const RGB& value) { return addTo(0, x, y, value); }
    // The same for light path layer `layer` (0 <= layer < layers()).
    bool addToLayer(int layer, float x, float y, const RGB& value) { return addTo(layer + 1, x, y, value); }

    // Pixel (x, y) of the window's sums, R G B in the units of the values (read when no add() runs).
    std::array<double, 3> sum(int x, int y) const { return sumOf(0, x, y); }
    // The same for light path layer `layer`.
    std::array<double, 3> layerSum(int layer, int x, int y) const { return sumOf(layer + 1, x, y); }

    // Every sum in fixed point, pixel by pixel (row by row) and R G B, and their replacement by a
    // copy of such sums (render checkpoints, core/film_state.h; `sums` must have
    // 3 (1 + layers) width height: per pixel, the beauty then each layer).
    std::vector<std::int64_t> fixedSums() const;
    void restore(const std::vector<std::int64_t>& sums);

private:
    // Slot 0 is the beauty, slot l + 1 light path layer l.
    bool addTo(int slot, float x, float y, const RGB& value);
    std::array<double, 3> sumOf(int slot, int x, int y) const;
    std::size_t indexOf(int slot, std::size_t x, std::size_t y) const {
        return ((y * static_cast<std::size_t>(width_) + x) * static_cast<std::size_t>(layers_ + 1) +
                static_cast<std::size_t>(slot)) *
               3;
    }

    int width_, height_, originX_, originY_, layers_;
    std::vector<std::atomic<std::int64_t>> sums_;
};

}  // namespace fluence
