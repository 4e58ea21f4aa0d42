// The render products `fluence render` writes for one frame, planned from the UsdRender settings
// (delegate/render_settings_adapter.h) and the command line: the renders they need and, for each
// product, the EXR channels it writes and how. docs/RENDER_PRODUCTS.md is the user's reference.
//
// Products and renders. Every RenderProduct of the settings prim is written (no settings, or no
// products: one default product). Products that share a camera, resolution and framing (pixel
// aspect ratio, conform policy) share one render: the image is rendered once, over the union of
// their data windows, and each writes its vars from the same film. Another camera, resolution or
// framing is another render. -c and -r apply to every product; -o replaces the first product's
// productName; a product without a productName is written to SCENE.exr (the first) or
// SCENE_PRODUCT.exr. Every other setting (integrator, samples, seed, depth, adaptive sampling,
// time limit — the limit per render) is the render settings' and the command line's, the same for
// every render: UsdRender lets a product override only its camera and image. A render's light
// path expressions are the union of its products' lpe vars (--lpe layers join the first product).
//
// Vars. A product without raw or primvar RenderVars writes the default channels (R G B A albedo N
// Z sampleCount, as Film resolves them) and its light path layers. Otherwise it writes its vars,
// after the beauty R G B A unless a var writes R itself. Each var: sourceType "raw" (the table in
// rawSourceNames), "primvar" (sourceName "primvars:NAME" or "NAME": a float, float2, float3 or
// colour primvar of meshes at the first hit, integrators/first_hit_aovs.h) or "lpe"
// (apps/light_path_aovs.h). dataType sets the components and the pixel type: half, half2..4 and
// the *h role types are half; float, double and the *f/*d types float; int/uint types 32-bit
// unsigned int. Channel names: the bare R G B (A) for a beauty var named like a beauty source, A
// for an alpha var named like an alpha source, Z for a depth var named like a depth source (case
// ignored: "Beauty", "Z"); else NAME for one
// component, NAME.R/G/B(/A) for colour types, NAME.X/Y(/Z/W) otherwise. Filters (fluence:filter):
// box (the mean; the default), min, max, closest (the first hit's value nearest the camera) for
// depth (whose default is min, as the film keeps it), normal, albedo and primvars; colour sources
// take box only. An unsupported filter is a warning, and box is used.
//
// Errors (delegate::SceneError naming the RenderVar or RenderProduct prim, exit code 3): an
// unknown sourceType, raw sourceName or dataType; a dataType whose component count the source
// cannot give (but a one-component source, such as depth, under a 2-4 component dataType is
// repeated in each channel, with a warning: arnold-usd's tests declare Z as color3f); two vars writing the same channel; two products writing the same file; an unknown
// compression; a data window outside the image. Warnings: an unsupported filter; lossy compression
// (b44, b44a, dwaa, dwab, pxr24) on a product with data channels, which is written with zip.
#pragma once

#include <functional>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "apps/cli_options.h"
#include "core/image.h"
#include "delegate/render_settings_adapter.h"
#include "integrators/first_hit_aovs.h"
#include "integrators/light_path_tracker.h"
#include "output/exr_writer.h"
#include "render/camera.h"

namespace fluence::app {

// A rectangle of image pixels, [x0, x1) x [y0, y1), row 0 at the top.
struct PixelWindow {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    int width() const { return x1 - x0; }
    int height() const { return y1 - y0; }
    bool empty() const { return x1 <= x0 || y1 <= y0; }
    PixelWindow intersect(const PixelWindow& o) const;
    PixelWindow unite(const PixelWindow& o) const;  // the bounding rectangle
    bool operator==(const PixelWindow&) const = default;
};

// The pixels whose centres lie in `ndc` (xmin, ymin, xmax, ymax; (0, 0) the bottom-left corner).
PixelWindow pixelWindowOf(const std::array<float, 4>& ndc, std::pair<int, int> resolution);

enum class VarSource { Beauty, Alpha, Albedo, Normal, Depth, SampleCount, LightPath, Primvar, MotionVector };

// The raw sourceNames each source answers to (docs/RENDER_PRODUCTS.md lists them).
const std::vector<std::string>& rawSourceNames(VarSource source);

struct ProductVar {
    std::string path;  // the RenderVar prim; "" for the default channels and the implicit beauty
    VarSource source = VarSource::Beauty;
    std::string name;    // LightPath: the layer; Primvar: the primvar, without "primvars:"
    int components = 3;  // the components its source gives (a single one is repeated in every channel)
    output::PixelType type = output::PixelType::Float;
    integrators::PixelFilter filter = integrators::PixelFilter::Box;
    bool colour = true;  // colour channels (in the rendering space), else data
    std::vector<std::string> channels;
    int firstHitAov = -1;  // its index in the render's first-hit AOVs, -1: from the film
};

struct PlannedProduct {
    std::string path;           // the RenderProduct prim, "" for the default product
    std::string outputPattern;  // the file, before frame tokens and the tile suffix
    std::string compression = "zip";
    PixelWindow window;  // its data window, in image pixels
    std::vector<ProductVar> vars;
};

struct PlannedRender {
    std::string cameraPath;  // "" = the delegate's choice (the settings' camera, else the first)
    std::pair<int, int> resolution;
    render::ImageFraming framing;
    std::vector<PlannedProduct> products;
    std::vector<integrators::LightPathAov> lightPaths;  // the union of its products' lpe vars
    std::vector<integrators::FirstHitAov> firstHitAovs;
    PixelWindow window() const;  // the union of its products' windows
};

struct RenderPlan {
    std::vector<PlannedRender> renders;
    std::set<std::string> primvars() const;  // those primvar vars read (delegate::DelegateOptions::aovPrimvars)
};

// Plans the frame's renders. `sceneStem`: the scene file's name without extension (default
// outputs). Throws delegate::SceneError (naming the prim) and UsageError (--lpe); `warn` gets
// (prim path, message).
RenderPlan planRenders(const std::optional<delegate::RenderSettingsDesc>& settings, const RenderOptions& opt,
                       const std::string& sceneStem,
                       const std::function<void(const std::string&, const std::string&)>& warn);

// The RenderProduct prim at `path` in `settings` (nullptr for the default product).
const delegate::RenderProductDesc* findProduct(const std::optional<delegate::RenderSettingsDesc>& settings,
                                               const std::string& path);

// Adds to a product's header what its render's camera and image say: OpenEXR's worldToCamera and
// worldToNDC (render::Camera), the colour space's colorInteropID, and `written` as the data
// window of the resolution's display window (when it is not the whole image).
void describeProductHeader(output::ExrHeader& header, const render::Camera& camera, const PixelWindow& written,
                           std::pair<int, int> resolution);

// The EXR image of `product` from its render: `film` is Film::resolve() of the render's window
// `filmWindow`, `firstHit` the render's first-hit AOVs over the same window. `window` is the part
// written (the product's window, or its part in a tile); `header` gets the channel types, data
// channels and compression. Light path vars whose layers the film lacks (an integrator without
// them) are left out.
Image productImage(const PlannedProduct& product, const PixelWindow& window, const Image& film, const Image& firstHit,
                   const PixelWindow& filmWindow, output::ExrHeader& header);

}  // namespace fluence::app
