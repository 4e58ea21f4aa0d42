// The parameters of a volume's material as volumes::GridMedium takes them (volumes/grid_medium.h
// has the model and the table of units and ranges). One struct, with its defaults, serves the
// render core's scene description (render::VolumeDesc), the delegate that fills it from a UsdVol
// Volume's material (delegate/volume_adapter.h) and the medium built from it.
#pragma once

#include "core/rgb.h"

namespace fluence::volumes {

struct GridMediumParams {
    float densityScale = 1.0f;
    RGB albedo{0.8f};
    RGB absorptionColor{0.0f};
    float anisotropy = 0.0f;
    float emissionScale = 0.0f;
    RGB emissionColor{1.0f};
    float blackbodyIntensity = 0.0f;
    float temperatureScale = 1.0f, temperatureOffset = 0.0f;
};

}  // namespace fluence::volumes
