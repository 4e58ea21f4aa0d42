#include "apps/frame_build.h"

#include <cstdio>

#include "apps/integrator_parameters.h"
#include "apps/sampler_choice.h"
#include "apps/scene_loading.h"
#include "apps/stopwatch.h"
#include "render/subsurface_method.h"
#include "integrators/automatic_choice.h"
#include "integrators/scene_path_classes.h"
#include "texture/texture_system.h"

namespace fluence::app {

namespace {

delegate::DelegateOptions delegateOptions(const RenderOptions& opt, const color::ColorManagement& colors, double time,
                                          const PlannedRender& planned, const std::set<std::string>& primvars,
                                          WarningLog& warnings) {
    delegate::DelegateOptions dopt;
    dopt.cameraPath = planned.cameraPath;
    dopt.settingsPath = opt.settings;
    dopt.resolution = planned.resolution;
    dopt.aovPrimvars = primvars;
    dopt.defaultResolution = {kDefaultWidth, kDefaultHeight};
    dopt.dicing.rate = static_cast<float>(opt.dicingRate);
    dopt.dicing.uniformLevel = opt.subdivLevel.value_or(-1);
    dopt.time = time;
    dopt.purposes = opt.purposes;
    dopt.allowMissing = opt.allowMissing;
    dopt.strict = opt.strict;
    dopt.defaultLight = opt.defaultLight;
    dopt.motionBlur = opt.motionBlur;
    dopt.textures = std::make_shared<texture::TextureSystem>(colors);  // displacement maps, read when meshes are diced
    dopt.convertColor = [&colors](const RGB& c, const std::string& space) { return colors.toRenderingSpace(space, c); };
    dopt.warn = [&warnings](const std::string& path, const std::string& message) { warnings(path, message); };
    return dopt;
}

// The integrator the render uses: --integrator, else the render settings' fluence:integrator,
// else the default. Throws SceneError when the settings name none that Fluence has.
// `sceneClasses`: the PathClass bits the scene can produce, for `auto`.
const integrators::IntegratorInfo& chosenIntegrator(const RenderOptions& opt, const delegate::DelegateResult& populated,
                                                    unsigned sceneClasses) {
    const auto& settings = populated.renderSettings;
    std::string name = !opt.integrator.empty()                     ? opt.integrator  // checked when parsed
                       : settings && !settings->integrator.empty() ? settings->integrator
                                                                   : kDefaultIntegrator;
    if (name == integrators::kAutomaticIntegrator) {
        const integrators::AutomaticChoice choice = integrators::chooseIntegrator(sceneClasses);
        std::printf("fluence: integrator auto: %s, %s\n", choice.integrator->name.c_str(), choice.reason.c_str());
        return *choice.integrator;
    }
    if (const integrators::IntegratorInfo* info = integrators::findIntegrator(name)) return *info;
    throw delegate::SceneError("render settings " + settings->path + ": fluence:integrator '" + settings->integrator +
                               "' is not an integrator (available: " + integratorNames() + ")");
}

// --subsurface: every material's subsurface method.
void overrideSubsurface(const std::string& method, render::SceneDescription& scene) {
    if (method.empty()) return;
    const render::SubsurfaceMethod chosen = *render::subsurfaceMethodNamed(method);  // checked by the CLI
    for (render::MaterialDesc& m : scene.materials) m.subsurfaceMethod = chosen;
}

// The delegate's and the render scene's work; returns the light paths the scene can produce.
unsigned populate(const RenderOptions& opt, usd::Stage& stage, const color::ColorManagement& colors,
                  const delegate::DelegateOptions& dopt, WarningLog& warnings, BuiltFrame& built) {
    built.populated = delegate::populateScene(stage, dopt);
    const unsigned sceneClasses = integrators::scenePathClasses(built.populated->scene);
    built.integrator = &chosenIntegrator(opt, *built.populated, sceneClasses);
    built.sampler = chosenSampler(opt, built.populated->renderSettings);
    built.parameters =
        integratorParameters(opt.integratorParameters, built.populated->renderSettings, *built.integrator, warnings);
    overrideSubsurface(opt.subsurface, built.populated->scene);
    built.populated->scene.domeLightSampling = chosenDomeLightSampling(opt, built.populated->renderSettings);
    built.scene =
        std::make_unique<render::RenderScene>(built.populated->scene, std::make_shared<texture::TextureSystem>(colors));
    for (const render::Warning& w : built.scene->warnings()) warnings(w.where, w.message);
    return sceneClasses;
}

}  // namespace

int buildFrame(const RenderOptions& opt, usd::Stage& stage, const color::ColorManagement& colors, double time,
               const PlannedRender& planned, const std::set<std::string>& primvars, WarningLog& warnings,
               BuiltFrame& built) {
    const Stopwatch clock;
    unsigned sceneClasses = 0;  // the light paths the scene can produce (integrators/path_classes.h)
    try {
        sceneClasses = populate(opt, stage, colors, delegateOptions(opt, colors, time, planned, primvars, warnings),
                                warnings, built);
    } catch (const delegate::MissingAssetError& e) {
        printError(e.what());
        return kExitMissingInput;
    } catch (const delegate::SceneError& e) {
        printError(e.what());
        return kExitScene;
    } catch (const color::ColorError& e) {
        printError(e.what());
        return kExitScene;
    } catch (const std::invalid_argument& e) {
        printError(e.what());
        return kExitScene;
    }
    built.seconds = clock.seconds();
    if (built.scene->lightCount() == 0)
        warnings(built.populated->cameraPath, "the scene has no lights; the image will be black");
    if (const unsigned missed = sceneClasses & ~built.integrator->covers)
        warnings(opt.scene, "integrator '" + built.integrator->name + "' misses: " +
                                integrators::describePathClasses(missed) + " (light that this scene has)");
    return kExitOk;
}

}  // namespace fluence::app
