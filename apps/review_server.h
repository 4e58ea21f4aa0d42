// `fluence review`'s HTTP server (cpp-httplib): read-only, GET only, answering
//   /, /review.js, /review.css     the page (review/web/, embedded at build time)
//   /api/REQUEST?NAME=VALUE...     the requests of apps/review_api.h
//   /files/NAME                    a reviewed file's bytes
// and nothing else: a request target that is not a path (an absolute URL), a name with `..` or
// that was not given answers 400, 403 or 404.
#pragma once

#include <memory>
#include <string>

#include "apps/review_api.h"

namespace fluence::app {

class ReviewServer {
public:
    explicit ReviewServer(std::shared_ptr<const ReviewApi> api);
    ~ReviewServer();
    ReviewServer(const ReviewServer&) = delete;
    ReviewServer& operator=(const ReviewServer&) = delete;

    // Binds `address`:`port` (port 0: a free port). Returns the port, or -1 when binding failed
    // (another server listens there); a port a stopped server released binds again at once.
    int bind(const std::string& address, int port);
    // Serves until stop() (from another thread or a signal handler's thread).
    void serve();
    void stop();

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace fluence::app
