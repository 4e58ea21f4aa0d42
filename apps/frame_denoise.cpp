#include "apps/frame_denoise.h"

#include "apps/denoise_image.h"
#include "apps/stopwatch.h"

#include <cstdio>
#include <ctime>

namespace fluence::app {

bool keepsDenoiseBuffers(const RenderOptions& opt) { return opt.denoise || opt.denoiseBuffers; }

void addDenoiseOutputs(const RenderOptions& opt, const Film& film, Image& image, output::ExrHeader& header,
                       WarningLog& warnings, const std::string& path) {
    if (!keepsDenoiseBuffers(opt)) return;
    const std::size_t before = image.channelCount();
    image = withChannels(image, film.resolveDenoiseBuffers());
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
    if (!header.channelTypes.empty())
        header.channelTypes.resize(header.channelTypes.size() + image.channelCount() - before,
                                   output::PixelType::Float);
}

}  // namespace fluence::app
