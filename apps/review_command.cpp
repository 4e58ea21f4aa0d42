#include "apps/review_command.h"

#include <spawn.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <thread>

#include "apps/cli_options.h"
#include "apps/review_server.h"
#include "apps/review_static.h"
#include "apps/scene_loading.h"
#include "apps/stop_signals.h"
#include "output/atomic_file.h"

extern char** environ;

namespace fluence::app {

namespace {

void openBrowser(const std::string& url) {
    pid_t pid = 0;
    const char* argv[] = {"xdg-open", url.c_str(), nullptr};
    if (posix_spawnp(&pid, "xdg-open", nullptr, nullptr, const_cast<char* const*>(argv), environ) != 0)
        std::fprintf(stderr, "fluence: warning: cannot run xdg-open; open %s yourself\n", url.c_str());
}

}  // namespace

ReviewOptions parseReviewOptions(const std::vector<std::string>& args) {
    ReviewOptions o;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& arg = args[i];
        const auto value = [&]() -> const std::string& {
            if (i + 1 == args.size()) throw UsageError(arg + " needs a value");
            return args[++i];
        };
        if (arg == "--port") {
            const std::string& text = value();
            try {
                std::size_t used = 0;
                o.port = std::stoi(text, &used);
                if (used != text.size() || o.port < 1 || o.port > 65535) throw UsageError("");
            } catch (const std::exception&) {
                throw UsageError("--port needs a port number from 1 to 65535, not '" + text + "'");
            }
        } else if (arg == "--bind") {
            o.bind = value();
        } else if (arg == "--open") {
            o.open = true;
        } else if (arg == "--static") {
            o.staticDir = value();
        } else if (arg.size() > 1 && arg[0] == '-') {
            throw UsageError("unknown option '" + arg + "'");
        } else {
            o.paths.push_back(arg);
        }
    }
    if (o.paths.empty()) throw UsageError("review needs at least one EXR file, folder or frame sequence");
    return o;
}

int runReview(const ReviewOptions& options) {
    std::shared_ptr<const ReviewApi> api;
    try {
        api = std::make_shared<const ReviewApi>(expandReviewPaths(options.paths));
    } catch (const ReviewInputError& e) {
        printError(e.what());
        return kExitMissingInput;
    }
    if (!options.staticDir.empty()) {
        try {
            writeStaticReview(*api, options.staticDir);
        } catch (const ReviewInputError& e) {
            printError(e.what());
            return kExitMissingInput;
        } catch (const output::OutputError& e) {
            printError(e.what());
            return kExitOutput;
        }
        std::printf("Wrote the review page of %zu image(s) to %s/index.html\n", api->files().size(),
                    options.staticDir.c_str());
        return kExitOk;
    }
    ReviewServer server(api);
    const int port = server.bind(options.bind, options.port);
    if (port < 0) {
        printError("cannot listen on " + options.bind + ":" + std::to_string(options.port));
        return kExitOutput;
    }
    const std::string host = options.bind.find(':') != std::string::npos ? "[" + options.bind + "]" : options.bind;
    const std::string url = "http://" + host + ":" + std::to_string(port) + "/";
    std::printf("Reviewing %zu image(s) at %s (Ctrl-C stops)\n", api->files().size(), url.c_str());
    std::fflush(stdout);
    if (options.open) openBrowser(url);
    StopSignals signals;
    std::atomic<bool> served{false};
    std::thread watcher([&server, &served] {
        while (!StopSignals::flag() && !served) std::this_thread::sleep_for(std::chrono::milliseconds(100));
        server.stop();
    });
    server.serve();
    served = true;
    watcher.join();
    return kExitOk;
}

}  // namespace fluence::app
