// `fluence review PATH... [--port N] [--bind ADDR] [--open] [--static OUT_DIR]`: the review page
// over EXR files, folders and frame sequences, served on 127.0.0.1 (a free port unless --port)
// until SIGINT/SIGTERM, or written as static files (apps/review_static.h).
#pragma once

#include <string>
#include <vector>

namespace fluence::app {

struct ReviewOptions {
    std::vector<std::string> paths;
    int port = 0;                    // --port N (0: a free port)
    std::string bind = "127.0.0.1";  // --bind ADDR
    bool open = false;               // --open: start the desktop's browser on the URL
    std::string staticDir;           // --static OUT_DIR
};

// Throws UsageError.
ReviewOptions parseReviewOptions(const std::vector<std::string>& args);
int runReview(const ReviewOptions& options);

}  // namespace fluence::app
