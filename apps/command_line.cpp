#include "apps/command_line.h"

#include <cstdio>
#include <exception>

#include "apps/assemble_command.h"
#include "apps/cat_command.h"
#include "apps/cli_options.h"
#include "apps/denoise_command.h"
#include "apps/farm_command.h"
#include "apps/info_command.h"
#include "apps/render_command.h"
#include "apps/review_command.h"
#include "apps/scene_loading.h"
#include "scene/usda_parser.h"
#include "version.h"

namespace fluence::app {

int runCommandLine(std::vector<std::string> args) {
    if (args.empty()) {
        std::fputs(usageText().c_str(), stderr);
        return kExitUsage;
    }
    if (args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
        std::fputs(usageText().c_str(), stdout);
        return kExitOk;
    }
    if (args[0] == "--version") {
        std::printf("fluence %s\n", fluence::kFluenceVersion);
        return kExitOk;
    }
    const std::string command = args[0];
    if (command != "render" && command != "info" && command != "cat" && command != "assemble" && command != "farm" &&
        command != "review" && command != "denoise") {
        std::fprintf(stderr, "fluence: error: unknown command '%s' (try 'fluence --help')\n", command.c_str());
        return kExitUsage;
    }
    args.erase(args.begin());
    for (const std::string& a : args)
        if (a == "--help" || a == "-h") {
            std::fputs(usageText().c_str(), stdout);
            return kExitOk;
        }
    try {
        if (command == "cat") return runCat(parseCatOptions(args));
        if (command == "assemble") return runAssemble(parseAssembleOptions(args));
        if (command == "farm") return runFarm(args);
        if (command == "review") return runReview(parseReviewOptions(args));
        if (command == "denoise") return runDenoise(parseDenoiseOptions(args));
        return command == "info" ? runInfo(parseInfoOptions(args)) : runRender(parseRenderOptions(args));
    } catch (const UsageError& e) {
        std::fprintf(stderr, "fluence: error: %s\n(try 'fluence --help')\n", e.what());
        return kExitUsage;
    } catch (const fluence::usd::FileError& e) {
        // A damaged crate array found when first read, after the stage was opened.
        printError(e.what());
        return kExitMissingInput;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "fluence: internal error: %s\n", e.what());
        return kExitInternal;
    }
}

}  // namespace fluence::app
