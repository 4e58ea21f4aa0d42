// open_census LISTING: opens each file of LISTING (one path a line) as `fluence render` does before
// it renders: the stage (every layer read and composed), then the delegate (with --allow-missing),
// in one process, one file at a time; prints one tab-separated row per file: path, ok or refused,
// seconds, the error. The reader half of a real-file census at a few files a second, where a
// render census (bench/census_summary.py) takes seconds a file; it says nothing of the image.
#include <chrono>
#include <fstream>
#include <iostream>
#include <string>

#include "delegate/scene_delegate.h"
#include "scene/stage.h"

namespace {

// The error opening `path` gives, or "" when it opens.
std::string openError(const std::string& path) {
    using namespace fluence;
    try {
        auto stage = usd::Stage::open(path);
        delegate::DelegateOptions options;
        options.allowMissing = true;
        options.resolution = {16, 16};
        options.defaultResolution = {16, 16};
        options.convertColor = [](const RGB& c, const std::string&) { return c; };
        options.warn = [](const std::string&, const std::string&) {};
        delegate::populateScene(*stage, options);
        return "";
    } catch (const std::exception& e) {
        std::string message = e.what();
        for (char& c : message)
            if (c == '\t' || c == '\n') c = ' ';
        return message.empty() ? "(an exception without a message)" : message;
    }
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: open_census LISTING\n";
        return 2;
    }
    std::ifstream listing(argv[1]);
    if (!listing) {
        std::cerr << "open_census: cannot read " << argv[1] << "\n";
        return 2;
    }
    std::string path;
    while (std::getline(listing, path)) {
        if (path.empty()) continue;
        const auto start = std::chrono::steady_clock::now();
        const std::string error = openError(path);
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::cout << path << '\t' << (error.empty() ? "ok" : "refused") << '\t' << seconds << '\t' << error
                  << std::endl;
    }
}
