#include "apps/integrator_parameters.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "delegate/prim_reader.h"

namespace fluence::app {

namespace {

// The parameter read from the RenderSettings attribute `attribute`; nullptr when none.
const integrators::IntegratorParameter* parameterOfAttribute(const std::string& attribute) {
    for (const integrators::IntegratorInfo& info : integrators::integratorRegistry())
        for (const integrators::IntegratorParameter& p : info.parameters)
            if (p.attribute == attribute) return &p;
    return nullptr;
}

std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.10g", value);
    return text;
}

}  // namespace

const integrators::IntegratorParameter* findIntegratorParameter(const std::string& option) {
    for (const integrators::IntegratorInfo& info : integrators::integratorRegistry())
        for (const integrators::IntegratorParameter& p : info.parameters)
            if (p.option == option) return &p;
    return nullptr;
}

std::string parameterProblem(const integrators::IntegratorParameter& parameter, double value) {
    if (parameter.count && !(value >= parameter.minimum && value <= parameter.maximum && value == std::floor(value)))
        return "must be a whole number from " + number(parameter.minimum) + " to " + number(parameter.maximum) +
               ", got " + number(value);
    if (!parameter.count && !(value > 0.0 && value <= parameter.maximum))
        return "must be a number > 0 (scene units), got " + number(value);
    return "";
}

std::map<std::string, double> integratorParameters(const std::map<std::string, double>& given,
                                                   const std::optional<delegate::RenderSettingsDesc>& settings,
                                                   const integrators::IntegratorInfo& integrator,
                                                   WarningLog& warnings) {
    const auto notRead = [&](const std::string& where, const std::string& option) {
        const auto& own = integrator.parameters;
        if (std::none_of(own.begin(), own.end(),
                         [&](const integrators::IntegratorParameter& p) { return p.option == option; }))
            warnings(where, "integrator '" + integrator.name + "' has no such parameter; ignored");
    };
    std::map<std::string, double> parameters;
    if (settings)
        for (const auto& [attribute, value] : settings->integratorParameters) {
            const integrators::IntegratorParameter* p = parameterOfAttribute(attribute);
            if (!p) {
                warnings(settings->path,
                         attribute + " is no integrator's parameter; ignored (fluence --help lists them)");
                continue;
            }
            if (const std::string why = parameterProblem(*p, value); !why.empty())
                throw delegate::SceneError("render settings " + settings->path + ": " + attribute + " " + why);
            notRead(settings->path + "." + attribute, p->option);
            parameters[p->option] = value;
        }
    for (const auto& [option, value] : given) {
        notRead("--" + option, option);
        parameters[option] = value;
    }
    return parameters;
}

std::string integratorParameterUsage() {
    std::string usage;
    for (const integrators::IntegratorInfo& info : integrators::integratorRegistry())
        for (const integrators::IntegratorParameter& p : info.parameters) {
            std::string flag = "      --" + p.option + (p.count ? " N" : " X");
            flag.resize(std::max<std::size_t>(flag.size() + 1, 26), ' ');
            usage += flag + info.name + ": " + p.meaning + ";\n" + std::string(26, ' ') + "also " + p.attribute +
                     " on the render settings\n";
        }
    return usage;
}

}  // namespace fluence::app
