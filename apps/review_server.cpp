#include "apps/review_server.h"

#include <httplib.h>
#include <sys/socket.h>

#include <fstream>
#include <sstream>

#include "review/review_assets.h"

namespace fluence::app {

struct ReviewServer::Impl {
    std::shared_ptr<const ReviewApi> api;
    httplib::Server server;
};

namespace {

void send(httplib::Response& res, const ReviewAnswer& answer) {
    res.status = answer.status;
    res.set_header("Cache-Control", "no-store");
    res.set_content(answer.body, answer.contentType.c_str());
}

void refuse(httplib::Response& res, int status, const std::string& why) {
    send(res, {status, "text/plain", why + "\n"});
}

}  // namespace

ReviewServer::ReviewServer(std::shared_ptr<const ReviewApi> api) : impl_(std::make_unique<Impl>()) {
    impl_->api = std::move(api);
    httplib::Server& server = impl_->server;
    const ReviewApi* reviewApi = impl_->api.get();
    // SO_REUSEADDR alone: a restart binds the port at once, though the connections the last server
    // closed still wait in TIME_WAIT on it; cpp-httplib's default (0.11) sets SO_REUSEPORT instead
    // on Linux, which lets a second server bind the port while the first listens, and share its
    // requests.
    server.set_socket_options([](socket_t socket) {
        const int yes = 1;
        setsockopt(socket, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
    });
    server.set_pre_routing_handler([](const httplib::Request& req, httplib::Response& res) {
        if (req.target.empty() || req.target.front() != '/') {
            refuse(res, 400, "only paths are served, not absolute URLs");
            return httplib::Server::HandlerResponse::Handled;
        }
        if (req.method != "GET" && req.method != "HEAD") {
            refuse(res, 405, "the review server is read-only");
            return httplib::Server::HandlerResponse::Handled;
        }
        return httplib::Server::HandlerResponse::Unhandled;
    });
    server.Get(R"(/api/([a-z]+))", [reviewApi](const httplib::Request& req, httplib::Response& res) {
        const std::string request = req.matches[1];
        const auto known = ReviewApi::requests().find(request);
        if (known == ReviewApi::requests().end()) return refuse(res, 404, "no such request: " + request);
        std::vector<std::string> args;
        for (const std::string& name : known->second) args.push_back(req.get_param_value(name.c_str()));
        send(res, reviewApi->answer(request, args));
    });
    server.Get(R"(/files/(.+))", [reviewApi](const httplib::Request& req, httplib::Response& res) {
        const std::string name = req.matches[1];
        if (isUnsafeReviewName(name)) return refuse(res, 403, "refused file name: " + name);
        const std::optional<ReviewFile> file = findReviewFile(reviewApi->files(), name);
        if (!file) return refuse(res, 404, "not a reviewed file: " + name);
        std::ifstream in(file->path, std::ios::binary);
        std::ostringstream bytes;
        bytes << in.rdbuf();
        if (!in) return refuse(res, 422, "cannot read " + name);
        send(res, {200, "application/octet-stream", bytes.str()});
    });
    server.Get(R"(/([a-z]*(\.[a-z]+)?))", [](const httplib::Request& req, httplib::Response& res) {
        const std::string name = req.matches[1].length() ? std::string(req.matches[1]) : "index.html";
        for (const review::ReviewAsset& asset : review::reviewAssets())
            if (name == asset.name) return send(res, {200, asset.contentType, asset.text});
        refuse(res, 404, "no such page file: " + name);
    });
}

ReviewServer::~ReviewServer() { stop(); }

int ReviewServer::bind(const std::string& address, int port) {
    if (port == 0) return impl_->server.bind_to_any_port(address);
    return impl_->server.bind_to_port(address, port) ? port : -1;
}

void ReviewServer::serve() { impl_->server.listen_after_bind(); }

void ReviewServer::stop() { impl_->server.stop(); }

}  // namespace fluence::app
