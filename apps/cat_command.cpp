#include "apps/cat_command.h"

#include <cstdio>
#include <fstream>
#include <memory>
#include <stdexcept>

#include "apps/cli_options.h"
#include "apps/scene_loading.h"
#include "output/atomic_file.h"
#include "scene/layer_file.h"
#include "scene/usda_parser.h"
#include "scene/usda_writer.h"

namespace fluence::app {

namespace {

// The layer file alone, read as the stage reads its layers. On failure prints why and returns
// nullptr with `exitCode` set (an unreadable file: kExitMissingInput; bad syntax or a format that
// needs a plugin Fluence does not have: kExitScene).
std::unique_ptr<usd::Layer> readLayer(const std::string& path, WarningLog& warnings, int& exitCode) {
    std::unique_ptr<usd::Layer> layer;
    try {
        layer = usd::readLayerFile(path);
    } catch (const usd::UnsupportedFormatError& e) {
        printError(e.what());
        exitCode = kExitScene;
        return nullptr;
    } catch (const usd::FileError& e) {
        printError(e.what());
        exitCode = kExitMissingInput;
        return nullptr;
    } catch (const usd::ParseError& e) {
        printError(e.what());
        exitCode = kExitScene;
        return nullptr;
    }
    for (const usd::ParseWarning& w : layer->warnings) warnings(w.location.str(), w.message);
    return layer;
}

int writeText(const std::string& text, const std::string& outputPath) {
    if (outputPath.empty()) {
        if (std::fwrite(text.data(), 1, text.size(), stdout) != text.size() || std::fflush(stdout) != 0) {
            printError("cannot write to standard output");
            return kExitOutput;
        }
        return kExitOk;
    }
    try {
        output::writeAtomically(outputPath, [&](const std::string& tempPath) {
            std::ofstream file(tempPath, std::ios::binary);
            file.write(text.data(), static_cast<std::streamsize>(text.size()));
            file.close();
            if (!file) throw std::runtime_error("the text could not be written");
        });
    } catch (const output::OutputError& e) {
        printError(e.what());
        return kExitOutput;
    }
    return kExitOk;
}

}  // namespace

CatOptions parseCatOptions(const std::vector<std::string>& args) {
    CatOptions o;
    // The layer and the stage options are those of `fluence info`, parsed by its parser.
    std::vector<std::string> stageArgs;
    std::string firstStageOption;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& arg = args[i];
        if (arg == "--flatten") {
            o.flatten = true;
        } else if (arg == "-o" || arg == "--output") {
            if (i + 1 == args.size()) throw UsageError(arg + " needs a value");
            o.output = args[++i];
        } else if (arg == "-s" || arg == "--settings") {
            throw UsageError("unknown option '" + arg + "'");
        } else {
            const bool takesValue = arg == "--variant" || arg == "--load" || arg == "--unload";
            if ((takesValue || arg == "--no-payloads") && firstStageOption.empty()) firstStageOption = arg;
            stageArgs.push_back(arg);
            if (takesValue && i + 1 < args.size()) stageArgs.push_back(args[++i]);
        }
    }
    if (!firstStageOption.empty() && !o.flatten)
        throw UsageError(firstStageOption + " applies to the composed stage: use it with --flatten");
    InfoOptions stage = parseInfoOptions(stageArgs);
    o.layer = std::move(stage.scene);
    o.variants = std::move(stage.variants);
    o.loadRules = std::move(stage.loadRules);
    return o;
}

int runCat(const CatOptions& options) {
    WarningLog warnings;
    std::unique_ptr<usd::Stage> stage;
    std::unique_ptr<usd::Layer> layer;
    if (options.flatten) {
        if (int exitCode = openStage(options.layer, {options.variants, options.loadRules}, warnings, stage))
            return exitCode;
    } else {
        int exitCode = kExitOk;
        layer = readLayer(options.layer, warnings, exitCode);
        if (!layer) return exitCode;
    }
    std::string text;
    try {
        text = usd::writeUsda(stage ? stage->composedLayer() : *layer);
    } catch (const std::invalid_argument& e) {
        printError(options.layer + ": " + e.what());
        return kExitScene;
    }
    return writeText(text, options.output);
}

}  // namespace fluence::app
