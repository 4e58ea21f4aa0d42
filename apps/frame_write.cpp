#include "apps/frame_write.h"

#include "apps/frame_denoise.h"
#include "apps/scene_loading.h"
#include "output/atomic_file.h"
#include "output/preview_writer.h"

namespace fluence::app {

namespace {

// Product `p` of `planned`: its vars over the part of its data window the render took.
void writeProduct(const RenderOptions& opt, const PlannedRender& planned, std::size_t p,
                  const render::RenderScene& scene, const FrameOutputs& outputs, const Image& image,
                  const Image& firstHit, WarningLog& warnings, const RenderedFrame& frame) {
    const PlannedProduct& product = planned.products[p];
    const PixelWindow written = product.window.intersect(outputs.window);
    if (written.empty()) {
        warnings(product.path,
                 "tile " + std::to_string(opt.tileIndex) + " holds no pixel of its data window; not written");
        return;
    }
    output::ExrHeader productHeader = frame.header;
    Image productImg = productImage(product, written, image, firstHit, outputs.window, productHeader);
    describeProductHeader(productHeader, *frame.camera, written, planned.resolution);
    if (p == 0 && frame.cryptomatte) {
        if (written == outputs.window)
            appendCryptomatteLayers(productImg, productHeader, *frame.cryptomatte, frame.cryptomatteRequests, scene,
                                    opt.cryptomatteDepth);
        else
            warnings(product.path, "Cryptomatte layers need the product's data window to be its render's; left out");
    }
    if (p == 0 && keepsDenoiseBuffers(opt)) {
        if (written == outputs.window)
            addDenoiseOutputs(opt, *frame.film, image, productImg, productHeader, warnings, outputs.files[p]);
        else
            warnings(product.path,
                     "the denoiser's buffers need the product's data window to be its render's; left out");
    }
    output::writeExr(outputs.files[p], productImg, productHeader);
}

}  // namespace

int writeFrame(const RenderOptions& opt, const color::ColorManagement& colors, const PlannedRender& planned,
               const render::RenderScene& scene, const FrameOutputs& outputs, WarningLog& warnings,
               RenderedFrame& frame) {
    const Image image = frame.film->resolve();
    const Image firstHit =
        integrators::renderFirstHitAovs(scene, *frame.camera, frame.settings, *frame.film, planned.firstHitAovs);
    frame.header.floats.insert(frame.header.floats.end(),
                               {{"fluence/samplesPerPixel", float(frame.stats.samplesPerPixel)},
                                {"fluence/seed", float(opt.seed)},
                                {"fluence/renderSeconds", float(frame.stats.seconds)}});
    try {
        for (std::size_t p = 0; p < planned.products.size(); ++p)
            writeProduct(opt, planned, p, scene, outputs, image, firstHit, warnings, frame);
        if (!outputs.preview.empty()) output::writePreviewPng(outputs.preview, image, colors);
    } catch (const output::OutputError& e) {
        printError(e.what());
        return kExitOutput;
    }
    frame.passOutputs->finish();
    return kExitOk;
}

}  // namespace fluence::app
