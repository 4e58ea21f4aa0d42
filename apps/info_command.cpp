#include "apps/info_command.h"

#include <algorithm>
#include <cstdio>
#include <functional>
#include <map>

#include "apps/scene_loading.h"
#include "color/color_management.h"
#include "delegate/instancing.h"
#include "delegate/light_adapter.h"
#include "delegate/material_adapter.h"
#include "delegate/prim_reader.h"
#include "delegate/render_settings_adapter.h"
#include "delegate/scene_delegate.h"
#include "integrators/integrator.h"
#include "integrators/scene_path_classes.h"

namespace fluence::app {

namespace {

const char* specifierName(usd::Specifier s) {
    switch (s) {
        case usd::Specifier::Def: return "def";
        case usd::Specifier::Over: return "over";
        case usd::Specifier::Class: return "class";
    }
    return "?";
}

std::string metadataString(const usd::PrimSpec& prim, const char* key) {
    const usd::MetadataEntry* e = usd::findMetadata(prim.metadata, key);
    return e ? e->value.toString() : std::string();
}

void printTree(const usd::PrimSpec& prim, int depth) {
    std::string line(2 * depth + 2, ' ');
    line += prim.name;
    if (!prim.typeName.empty()) line += "  " + prim.typeName;
    if (prim.specifier != usd::Specifier::Def) line += std::string("  (") + specifierName(prim.specifier) + ")";
    for (const char* key : {"kind", "active", "instanceable"}) {
        std::string v = metadataString(prim, key);
        if (!v.empty()) line += std::string("  ") + key + "=" + v;
    }
    if (usd::findMetadata(prim.metadata, "fluence:unloadedPayload")) line += "  (payload not loaded)";
    std::printf("%s\n", line.c_str());
    for (const auto& child : prim.children) printTree(*child, depth + 1);
}

// What `describe` says of a prim, or, when reading it raises SceneError, that it is malformed.
std::string describedOrMalformed(const std::function<std::string()>& describe) {
    try {
        return describe();
    } catch (const delegate::SceneError&) {
        return "  (malformed: see 'malformed prims')";
    }
}

void section(const char* title, std::size_t count) { std::printf("\n%s (%zu)\n", title, count); }

// The scene as `fluence render` would describe it to the render core, but for the subdivision
// surfaces' tessellation (nullopt, with a warning, when it cannot be), and the malformed prims
// the render leaves out.
struct DescribedScene {
    std::optional<render::SceneDescription> scene;
    std::vector<delegate::MalformedPrim> malformed;
};

DescribedScene describeScene(usd::Stage& stage, const InfoOptions& opt, double time, WarningLog& warnings) {
    DescribedScene described;
    try {
        const color::ColorManagement colors = color::ColorManagement::load();
        delegate::DelegateOptions dopt;
        dopt.settingsPath = opt.settings;
        dopt.time = time;
        dopt.defaultLight = true;  // as the render, which adds them (and says so) by default
        // Subdivision surfaces as their cages: the path classes do not depend on the tessellation.
        dopt.dicing.uniformLevel = 0;
        dopt.convertColor = [&](const RGB& c, const std::string& space) { return colors.toRenderingSpace(space, c); };
        dopt.warn = [&](const std::string& path, const std::string& message) { warnings(path, message); };
        delegate::SceneDelegate delegate(stage, dopt);
        delegate.sync();
        described.malformed = delegate.malformedPrims();
        described.scene = delegate.sceneDescription();
    } catch (const delegate::SceneError& e) {
        warnings("path classes", e.what());
    } catch (const color::ColorError& e) {
        warnings("path classes", e.what());
    }
    return described;
}

// The classes of light paths the scene can produce, and which of them each integrator misses.
void printPathClasses(const render::SceneDescription& scene) {
    const unsigned classes = integrators::scenePathClasses(scene);
    std::printf("\npath classes  %s\n", integrators::describePathClasses(classes).c_str());
    const auto& registry = integrators::integratorRegistry();
    int width = 0;
    for (const integrators::IntegratorInfo& i : registry) width = std::max(width, int(i.name.size()));
    for (const integrators::IntegratorInfo& i : registry) {
        const unsigned missed = classes & ~i.covers;
        std::printf("  %-*s  %s\n", width, i.name.c_str(),
                    missed ? ("misses " + integrators::describePathClasses(missed)).c_str() : "covers them all");
    }
}

}  // namespace

int runInfo(const InfoOptions& opt) {
    WarningLog warnings;
    std::unique_ptr<usd::Stage> stage;
    if (int code = openStage(opt.scene, {opt.variants, opt.loadRules}, warnings, stage); code != kExitOk) return code;
    const double time = stage->startTimeCode().value_or(usd::kDefaultTime);

    std::printf("scene        %s\n", opt.scene.c_str());
    std::printf("stage        upAxis %c, metersPerUnit %g, defaultPrim %s\n", stage->upAxis(), stage->metersPerUnit(),
                stage->defaultPrim().empty() ? "(none)" : stage->defaultPrim().c_str());
    if (auto start = stage->startTimeCode(), end = stage->endTimeCode(); start || end)
        std::printf("time codes   %g to %g\n", start.value_or(0.0), end.value_or(start.value_or(0.0)));

    std::vector<std::string> layers = stage->layerFiles();
    section("layers", layers.size());
    for (const std::string& l : layers) std::printf("  %s\n", l.c_str());

    const usd::Layer& composed = stage->composedLayer();
    std::size_t primCount = 0;
    std::function<void(const usd::PrimSpec&)> count = [&](const usd::PrimSpec& p) {
        ++primCount;
        for (const auto& c : p.children) count(*c);
    };
    for (const auto& root : composed.rootPrims) count(*root);
    section("prims", primCount);
    for (const auto& root : composed.rootPrims) printTree(*root, 0);

    std::vector<std::string> cameras, lights, materials, volumes, settings, instancing;
    std::map<std::string, std::size_t> prototypeNumbers;  // native-instancing key -> number, in order met
    stage->traverse([&](const usd::PrimSpec& p) {
        delegate::PrimReader r(p, time);
        if (std::string key = delegate::instancePrototypeKey(p); !key.empty()) {
            auto [it, first] = prototypeNumbers.try_emplace(key, prototypeNumbers.size() + 1);
            instancing.push_back(p.path + "  instance of prototype " + std::to_string(it->second) +
                                 (first ? " (read from here)" : ""));
        }
        if (p.typeName == "PointInstancer") {
            instancing.push_back(p.path + describedOrMalformed([&] {
                                     delegate::PointInstances points = delegate::pointInstancesFromPrim(
                                         r, [&](const std::string& message) { warnings(p.path, message); });
                                     return "  PointInstancer: " + std::to_string(points.instances.size()) +
                                            " instances of " + std::to_string(points.prototypes.size()) + " prototypes";
                                 }));
        }
        if (p.typeName == "Camera") {
            cameras.push_back(p.path + describedOrMalformed([&] {
                                  return "  focalLength " + std::to_string(r.number({"focalLength"}, 50.0)) +
                                         ", aperture " + std::to_string(r.number({"horizontalAperture"}, 20.955)) +
                                         " x " + std::to_string(r.number({"verticalAperture"}, 15.2908));
                              }));
        } else if (p.typeName.ends_with("Light")) {
            lights.push_back(p.path + "  " + p.typeName +
                             (delegate::isLightType(p.typeName) ? "" : "  (not supported yet)"));
        } else if (p.typeName == "Material") {
            const usd::AttributeSpec* surface = p.attribute("outputs:surface");
            std::string shader = surface && !surface->connections.empty()
                                     ? delegate::resolveTargetPath(p.path, surface->connections.front())
                                     : std::string("(no outputs:surface)");
            materials.push_back(p.path + "  surface " + shader);
        } else if (p.typeName == "Volume") {
            std::string fields;
            for (const usd::RelationshipSpec& rel : p.relationships)
                if (rel.name.starts_with("field:") && !rel.targets.empty())
                    fields.append(" ")
                        .append(rel.name.substr(6))
                        .append("=")
                        .append(delegate::resolveTargetPath(p.path, rel.targets.front()));
            volumes.push_back(p.path + (fields.empty() ? "  (no fields)" : " " + fields));
        } else if (p.typeName == "RenderSettings") {
            settings.push_back(p.path);
        }
        return true;
    });
    auto list = [](const char* title, const std::vector<std::string>& items) {
        section(title, items.size());
        for (const std::string& i : items) std::printf("  %s\n", i.c_str());
    };
    list("instancing", instancing);
    list("cameras", cameras);
    list("lights", lights);
    list("materials", materials);
    list("volumes", volumes);
    list("render settings prims", settings);
    try {
        std::function<void(const std::string&, const std::string&)> warnMissing;
        if (!opt.strict)
            warnMissing = [&](const std::string& where, const std::string& message) { warnings(where, message); };
        if (auto s = delegate::renderSettingsFromStage(*stage, opt.settings, time, warnMissing)) {
            std::printf("  used: %s  resolution %d x %d, camera %s, %zu products%s\n", s->path.c_str(),
                        s->resolution.first, s->resolution.second,
                        s->cameraPath.empty() ? "(none)" : s->cameraPath.c_str(), s->products.size(),
                        s->integrator.empty() ? "" : (", integrator " + s->integrator).c_str());
            for (const auto& p : s->products) {
                std::printf("    product %s  productName '%s'  %d x %d\n", p.path.c_str(), p.productName.c_str(),
                            p.resolution.first, p.resolution.second);
                for (const auto& v : p.vars)
                    std::printf("      var %s  %s %s (%s)\n", v.path.c_str(), v.sourceType.c_str(),
                                v.sourceName.c_str(), v.dataType.c_str());
            }
        }
    } catch (const delegate::SceneError& e) {
        warnings("render settings", e.what());
    }

    const DescribedScene described = describeScene(*stage, opt, time, warnings);
    if (described.scene) printPathClasses(*described.scene);
    section("malformed prims", described.malformed.size());
    for (const delegate::MalformedPrim& m : described.malformed)
        std::printf("  %s  %s\n", m.path.c_str(), m.reason.c_str());

    std::vector<usd::AssetReference> assets = stage->assetReferences();
    std::size_t missing = 0;
    for (const auto& a : assets) missing += a.exists ? 0 : 1;
    std::printf("\nassets (%zu, %zu missing)\n", assets.size(), missing);
    for (const auto& a : assets)
        std::printf("  %-8s %s  (%s%s%s)\n", a.exists ? "ok" : "MISSING", a.resolved.c_str(), a.primPath.c_str(),
                    a.property.empty() ? "" : ".", a.property.c_str());
    std::printf("\n%zu warnings\n", warnings.count());
    if (opt.strict && !described.malformed.empty()) {
        printError(std::to_string(described.malformed.size()) + " malformed prim" +
                   (described.malformed.size() == 1 ? "" : "s") +
                   " (listed above under 'malformed prims'), which `fluence render --strict` refuses");
        return kExitScene;
    }
    return kExitOk;
}

}  // namespace fluence::app
