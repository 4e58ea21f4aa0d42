// The Cryptomatte layers a render writes (output/cryptomatte.h), from the USD render settings and
// the command line.
//
// USD: a RenderVar of the rendered product with sourceType "raw" and sourceName "CryptoObject" or
// "CryptoMaterial" (the names husk and Karma give them) is a layer; the var prim's name is its type
// name (channels NAME00.R ... and the metadata's cryptomatte/<key>/name), e.g.
//     def RenderVar "CryptoObject" { uniform string sourceName = "CryptoObject"  uniform token sourceType = "raw" }
// CLI: `--cryptomatte object,material` adds the layers CryptoObject and CryptoMaterial, each unless
// a RenderVar already writes a layer of that name. `--cryptomatte-depth N` sets the ranks every layer
// keeps per pixel (default 6: three RGBA layers NAME00 to NAME02).
// Object layers name the prim path of the hit gprim (a GeomSubset part: the subset's path), of the
// instance (native instancing) or PointInstancer[id] for instanced geometry, of the light for a
// light's own shape; material layers name the bound Material prim. Volumes are not named.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/cryptomatte_film.h"
#include "core/image.h"
#include "delegate/render_settings_adapter.h"
#include "output/exr_writer.h"
#include "render/render_scene.h"

namespace fluence::app {

inline constexpr int kDefaultCryptomatteDepth = 6;
inline constexpr int kMaxCryptomatteDepth = 16;

struct CryptomatteLayerRequest {
    std::string typeName;
    CryptomatteSource source;
};

// The sources of `--cryptomatte` "object,material" split at its commas (either, in any order,
// repeats ignored). Throws UsageError.
std::vector<CryptomatteSource> parseCryptomatteOption(const std::vector<std::string>& items);

// The layers of `product`'s Cryptomatte RenderVars (none without a product), then the command
// line's. Throws delegate::SceneError naming the RenderVar when two layers share a name.
std::vector<CryptomatteLayerRequest> cryptomatteLayers(const delegate::RenderProductDesc* product,
                                                       const std::vector<CryptomatteSource>& options);

// The film that accumulates `layers` over a width x height window, or null when there are none.
std::unique_ptr<CryptomatteFilm> cryptomatteFilm(const std::vector<CryptomatteLayerRequest>& layers, int width,
                                                 int height);

// Appends the film's channels and metadata (output/cryptomatte.h) to the resolved image and its
// header, `depth` ranks per layer, the names read from `scene`'s name tables.
void appendCryptomatteLayers(Image& image, output::ExrHeader& header, const CryptomatteFilm& film,
                             const std::vector<CryptomatteLayerRequest>& layers, const render::RenderScene& scene,
                             int depth);

}  // namespace fluence::app
