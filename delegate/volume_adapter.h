// A UsdVol Volume's volume material -> render::VolumeDesc::params (volumes::GridMediumParams) and
// the fields that feed them.
//
// The material: the one bound to the Volume (material:binding:full, material:binding, else
// material:binding:preview — volume files are often authored for preview renderers only), its
// `outputs:volume` followed (through NodeGraph outputs) to a Shader. The shader is read by input
// name, whatever its info:id (Fluence's "FluenceVolume", or a preview shader with the same
// names, such as the glslfx shaders of OpenUSD's UsdVol tests):
// | input              | type                 | fallback              | GridMediumParams          |
// |--------------------|----------------------|-----------------------|---------------------------|
// | density            | float (field reader) | the field "density"   | density grid              |
// | densityScale       | float                | 1                     | densityScale              |
// | albedo             | color3f or float     | 0.8                   | albedo                    |
// | anisotropy         | float                | 0                     | anisotropy (HG g)         |
// | emissionColor      | color3f              | (1, 1, 1)             | emissionColor             |
// | emissionScale      | float                | 0                     | emissionScale             |
// | temperature / heat | float (field reader) | the field "temperature" | temperature grid        |
// | temperatureScale / heatScale | float      | 1                     | temperatureScale          |
// | temperatureOffset  | float                | 0                     | temperatureOffset         |
// | blackbodyIntensity | float                | 0 (no blackbody)      | blackbodyIntensity        |
// | color              | color3f (field reader) | the field "Cd"      | color grid (tints albedo) |
// A field input connects to a field reader (info:id HwFieldReader_float / _float3, or any node
// with inputs:fieldname) naming one of the Volume's field:NAME relationships. Any input may
// instead connect to a UsdPrimvarReader_float / _float3: the Volume's constant primvar of that
// varname gives the value, else the reader's fallback. An unbound Volume (or a material without
// a volume output) uses every fallback: a grey scattering medium whose extinction per scene unit
// is the density field's value, as in Cycles and Houdini.
#pragma once

#include <string>

#include "delegate/material_adapter.h"
#include "volumes/grid_medium_params.h"

namespace fluence::delegate {

struct VolumeMaterial {
    std::string densityField = "density", temperatureField = "temperature", colorField = "Cd";
    volumes::GridMediumParams params;
};

VolumeMaterial volumeMaterialOf(const usd::Stage& stage, const usd::PrimSpec& volume, double time,
                                const ColorConverter& convertColor, const Warn& warn);

}  // namespace fluence::delegate
