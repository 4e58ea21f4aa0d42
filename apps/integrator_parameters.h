// The integrators' parameters (IntegratorInfo::parameters, integrators/registry.cpp): given on the
// command line (`--sppm-photons 200000`) or as RenderSettings attributes
// (`float fluence:sppm:photons = 200000`), checked, and merged for the render (the option wins).
#pragma once

#include <map>
#include <string>

#include "apps/warning_log.h"
#include "delegate/render_settings_adapter.h"
#include "integrators/integrator.h"

namespace fluence::app {

// The parameter whose option is `option` (without "--"), of any integrator; nullptr when none.
const integrators::IntegratorParameter* findIntegratorParameter(const std::string& option);

// Why `value` is not one `parameter` takes, e.g. "must be a whole number from 1 to 10000000, got
// 0.5"; "" when it is.
std::string parameterProblem(const integrators::IntegratorParameter& parameter, double value);

// The parameters the render with `integrator` uses: the render settings' fluence:<method>:<name>
// attributes, then `given` (the command line's) over them. Throws delegate::SceneError naming
// the settings prim and the attribute for a bad value; warns of an attribute that is no
// integrator's parameter, and of a parameter that `integrator` does not read.
std::map<std::string, double> integratorParameters(const std::map<std::string, double>& given,
                                                   const std::optional<delegate::RenderSettingsDesc>& settings,
                                                   const integrators::IntegratorInfo& integrator, WarningLog& warnings);

// "--sppm-photons N", "--radiosity-patch-size X", ... with what each sets, for --help.
std::string integratorParameterUsage();

}  // namespace fluence::app
