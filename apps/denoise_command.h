// `fluence denoise IN.exr -o OUT.exr [--denoise-layers] [-j N]`: denoises an image rendered with
// --denoise or --denoise-buffers, or assembled from such tiles (apps/denoise_image.h), keeping its
// every channel and attribute. Exit codes: 4 when IN cannot be read or lacks a buffer (the message
// names the missing channels), 5 when OUT cannot be written; nothing is left at OUT on failure.
#pragma once

#include "apps/cli_options.h"

namespace fluence::app {

int runDenoise(const DenoiseOptions& options);

}  // namespace fluence::app
