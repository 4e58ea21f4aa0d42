#include "apps/denoise_command.h"

#include <cstdio>
#include <ctime>

#include "apps/denoise_image.h"
#include "apps/scene_loading.h"
#include "apps/stopwatch.h"
#include "output/atomic_file.h"
#include "output/exr_channels.h"

namespace fluence::app {

int runDenoise(const DenoiseOptions& opt) {
    try {
        Image image = output::readImageChannels(opt.input);
        const Stopwatch clock;
        const std::clock_t cpuStart = std::clock();
        denoiseImage(image, opt.layers ? lightPathLayersOf(image) : std::vector<std::string>{}, opt.threads);
        const double seconds = clock.seconds(), cpu = double(std::clock() - cpuStart) / CLOCKS_PER_SEC;
        output::writeExrLike(opt.input, opt.output, image);
        std::printf("fluence: denoised %s into %s in %.2f s (%.2f s CPU)\n", opt.input.c_str(), opt.output.c_str(),
                    seconds, cpu);
    } catch (const output::ImageReadError& e) {
        printError(e.what());
        return kExitMissingInput;
    } catch (const DenoiseInputError& e) {
        printError(opt.input + ": " + e.what());
        return kExitMissingInput;
    } catch (const output::OutputError& e) {
        printError(e.what());
        return kExitOutput;
    }
    return kExitOk;
}

}  // namespace fluence::app
