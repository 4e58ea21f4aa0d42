// apps/review_server.h over a real socket: the page, the API (layers losslessly, the OCIO shader),
// the reviewed files' bytes, and the refusals (traversal, absolute URLs, writes, files not given).
#include "apps/review_server.h"

#include <OpenImageIO/imageio.h>
#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <httplib.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <Imath/half.h>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <thread>

#include "tests/support/temp_dir.h"

namespace fluence::app {
namespace {

namespace fs = std::filesystem;

// A 3x2 EXR: RGBA as half, N.X/N.Y/N.Z as float, a fluence/ attribute and a Cryptomatte manifest.
void writeExr(const std::string& path, std::vector<Imath::half>& rgba, std::vector<float>& normals) {
    OIIO::ImageSpec spec(3, 2, 7, OIIO::TypeDesc::FLOAT);
    spec.channelnames = {"R", "G", "B", "A", "N.X", "N.Y", "N.Z"};
    spec.channelformats = {OIIO::TypeDesc::HALF,  OIIO::TypeDesc::HALF,  OIIO::TypeDesc::HALF, OIIO::TypeDesc::HALF,
                           OIIO::TypeDesc::FLOAT, OIIO::TypeDesc::FLOAT, OIIO::TypeDesc::FLOAT};
    spec.attribute("fluence/integrator", "path");
    spec.attribute("cryptomatte/abc1234/name", "CryptoObject");
    spec.attribute("cryptomatte/abc1234/manifest", "{\"/World/Ball\":\"3f800000\"}");
    std::vector<float> pixels(6 * 7);
    for (std::size_t p = 0; p < 6; ++p)
        for (std::size_t c = 0; c < 7; ++c) pixels[p * 7 + c] = 0.1f * float(p) + 0.013f * float(c) + 1e-4f;
    for (std::size_t p = 0; p < 6; ++p) {
        for (std::size_t c = 0; c < 4; ++c) rgba.push_back(Imath::half(pixels[p * 7 + c]));
        for (std::size_t c = 4; c < 7; ++c) normals.push_back(pixels[p * 7 + c]);
    }
    auto out = OIIO::ImageOutput::create(path);
    ASSERT_TRUE(out && out->open(path, spec));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()));
    out->close();
}

// Sends `request` as it is (no client normalising it) and returns the status code of the answer.
int rawStatus(int port, const std::string& request) {
    const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(static_cast<std::uint16_t>(port));
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (::connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0) return -1;
    ::send(fd, request.data(), request.size(), 0);
    char buffer[64] = {};
    const ssize_t n = ::recv(fd, buffer, sizeof buffer - 1, 0);
    ::close(fd);
    return n > 12 ? std::atoi(buffer + 9) : -1;  // "HTTP/1.1 403 ..."
}

class ReviewServerTest : public ::testing::Test {
protected:
    void SetUp() override {
        fs::create_directories(dir.path() / "out");
        writeExr(dir.file("out/a.exr"), rgba, normals);
        std::ofstream(dir.file("secret.exr")) << "secret";
        fs::create_symlink(dir.path() / "secret.exr", dir.path() / "out/escape.exr");
        server = std::make_unique<ReviewServer>(std::make_shared<ReviewApi>(expandReviewPaths({dir.file("out")})));
        port = server->bind("127.0.0.1", 0);
        ASSERT_GT(port, 0);
        thread = std::thread([this] { server->serve(); });
    }
    void TearDown() override {
        server->stop();
        thread.join();
    }
    httplib::Result get(const std::string& path) {
        httplib::Client client("127.0.0.1", port);
        return client.Get(path.c_str());
    }

    test::TempDir dir;
    std::vector<Imath::half> rgba;
    std::vector<float> normals;
    std::unique_ptr<ReviewServer> server;
    int port = 0;
    std::thread thread;
};

TEST_F(ReviewServerTest, ServesThePageTheListAndTheMetadata) {
    auto page = get("/");
    ASSERT_TRUE(page);
    EXPECT_EQ(page->status, 200);
    EXPECT_NE(page->body.find("review.js"), std::string::npos);
    EXPECT_EQ(get("/review.js")->status, 200);
    auto list = get("/api/files");
    EXPECT_EQ(list->body, R"({"files":[{"name":"out/a.exr","sequence":"","frame":0}]})");
    auto image = get("/api/image?file=out/a.exr");
    ASSERT_EQ(image->status, 200);
    EXPECT_NE(image->body.find(R"({"name":"rgba","format":"half","channels":["R","G","B","A"]})"), std::string::npos)
        << image->body;
    EXPECT_NE(image->body.find(R"({"name":"N","format":"float","channels":["N.X","N.Y","N.Z"]})"), std::string::npos);
    EXPECT_NE(image->body.find(R"("fluence/integrator":"path")"), std::string::npos);
    EXPECT_NE(image->body.find(R"("cryptomatte":[{"key":"abc1234","name":"CryptoObject","manifest":)"),
              std::string::npos);
}

TEST_F(ReviewServerTest, LayersArriveLosslesslyInTheirStoredFormat) {
    auto half = get("/api/pixels?file=out/a.exr&layer=rgba");
    ASSERT_EQ(half->status, 200);
    ASSERT_EQ(half->body.size(), rgba.size() * sizeof(Imath::half));
    EXPECT_EQ(std::memcmp(half->body.data(), rgba.data(), half->body.size()), 0);
    auto full = get("/api/pixels?file=out/a.exr&layer=N");
    ASSERT_EQ(full->body.size(), normals.size() * sizeof(float));
    EXPECT_EQ(std::memcmp(full->body.data(), normals.data(), full->body.size()), 0);
    EXPECT_EQ(get("/api/pixels?file=out/a.exr&layer=nope")->status, 422);
}

TEST_F(ReviewServerTest, TheShaderIsOciosGlslEs3WithExposureAndGammaUniforms) {
    auto menus = get("/api/menus?file=out/a.exr");
    EXPECT_NE(menus->body.find(R"("displays":["sRGB"])"), std::string::npos) << menus->body;
    auto shader = get("/api/shader?file=out/a.exr&display=sRGB&view=Standard&look=");
    ASSERT_EQ(shader->status, 200) << shader->body;
    EXPECT_NE(shader->body.find("vec4 ocioDisplay(vec4 inPixel)"), std::string::npos);
    EXPECT_NE(shader->body.find(R"("setting":"exposure")"), std::string::npos);
    EXPECT_NE(shader->body.find(R"("setting":"gamma")"), std::string::npos);
    EXPECT_EQ(get("/api/shader?file=out/a.exr&display=sRGB&view=Nope&look=")->status, 422);
}

TEST_F(ReviewServerTest, ServesTheGivenFilesOnlyAndRefusesTraversal) {
    auto file = get("/files/out/a.exr");
    ASSERT_EQ(file->status, 200);
    EXPECT_EQ(file->body.size(), fs::file_size(dir.file("out/a.exr")));
    EXPECT_EQ(get("/files/out/escape.exr")->status, 404);  // a symlink out of the folder
    EXPECT_EQ(get("/files/secret.exr")->status, 404);
    EXPECT_EQ(get("/api/image?file=../secret.exr")->status, 403);
    EXPECT_EQ(rawStatus(port, "GET /files/out/../secret.exr HTTP/1.1\r\nHost: x\r\n\r\n"), 403);
    EXPECT_EQ(rawStatus(port, "GET /files/out/%2e%2e/secret.exr HTTP/1.1\r\nHost: x\r\n\r\n"), 403);
    EXPECT_EQ(rawStatus(port, "GET /files//etc/passwd HTTP/1.1\r\nHost: x\r\n\r\n"), 403);
    EXPECT_EQ(rawStatus(port, "GET http://127.0.0.1/files/out/a.exr HTTP/1.1\r\nHost: x\r\n\r\n"), 400);
    EXPECT_EQ(rawStatus(port, "DELETE /files/out/a.exr HTTP/1.1\r\nHost: x\r\n\r\n"), 405);
    EXPECT_EQ(rawStatus(port, "PUT /files/out/a.exr HTTP/1.1\r\nHost: x\r\nContent-Length: 0\r\n\r\n"), 405);
    EXPECT_TRUE(fs::exists(dir.file("out/a.exr")));
}

// Sends a request that asks the server to close the connection, and reads until it has: the
// server's side then waits in TIME_WAIT on its port. Returns the bytes read.
std::size_t requestClosedByTheServer(int port, const std::string& path) {
    const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(static_cast<std::uint16_t>(port));
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (::connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0) return 0;
    const std::string request = "GET " + path + " HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n";
    ::send(fd, request.data(), request.size(), 0);
    std::size_t total = 0;
    char buffer[4096];
    for (ssize_t n; (n = ::recv(fd, buffer, sizeof buffer, 0)) > 0;) total += std::size_t(n);
    ::close(fd);
    return total;
}

// A review server stopped right after it served (its side of the connection in TIME_WAIT) starts
// again on the same port at once (SO_REUSEADDR), and while one listens a second cannot take its
// port (as SO_REUSEPORT, cpp-httplib's default socket option on Linux, let it).
TEST_F(ReviewServerTest, ListensAgainOnItsPortRightAfterAStopButNeverSharesIt) {
    EXPECT_GT(requestClosedByTheServer(port, "/api/files"), 0u);
    ReviewServer second(std::make_shared<ReviewApi>(expandReviewPaths({dir.file("out")})));
    EXPECT_EQ(second.bind("127.0.0.1", port), -1) << "a second server bound the port of one listening";
    server->stop();
    thread.join();
    server = std::make_unique<ReviewServer>(std::make_shared<ReviewApi>(expandReviewPaths({dir.file("out")})));
    ASSERT_EQ(server->bind("127.0.0.1", port), port) << "the port just released could not be bound again";
    thread = std::thread([this] { server->serve(); });
    EXPECT_EQ(get("/api/files")->status, 200);
}

// `fluence review` itself: 127.0.0.1 and a free port by default, the URL printed, SIGTERM stops it.
TEST(ReviewCommand, ListensOnLocalhostAtAFreePortAndPrintsTheUrl) {
    test::TempDir dir;
    std::ofstream(dir.file("a.exr")) << "x";
    int out[2];
    ASSERT_EQ(::pipe(out), 0);
    const pid_t pid = ::fork();
    if (pid == 0) {
        ::dup2(out[1], 1);
        ::execl(FLUENCE_BINARY, FLUENCE_BINARY, "review", dir.file("a.exr").c_str(), static_cast<char*>(nullptr));
        ::_exit(127);
    }
    ::close(out[1]);
    std::string line;
    char c = 0;
    while (::read(out[0], &c, 1) == 1 && c != '\n') line += c;
    ::close(out[0]);
    const std::string prefix = "Reviewing 1 image(s) at http://127.0.0.1:";
    ASSERT_EQ(line.rfind(prefix, 0), 0u) << line;
    const int port = std::atoi(line.c_str() + prefix.size());
    EXPECT_GT(port, 0);
    EXPECT_EQ(rawStatus(port, "GET /files/a.exr HTTP/1.1\r\nHost: x\r\n\r\n"), 200);
    ::kill(pid, SIGTERM);
    int status = 0;
    ::waitpid(pid, &status, 0);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << status;
}

TEST(ReviewCommand, NoInputIsAUsageErrorAndAMissingPathAnErrorNamingIt) {
    EXPECT_EQ(std::system((std::string(FLUENCE_BINARY) + " review 2>/dev/null").c_str()) >> 8, 2);
    EXPECT_EQ(std::system((std::string(FLUENCE_BINARY) + " review /nonexistent/x.exr 2>/dev/null").c_str()) >> 8, 4);
    EXPECT_EQ(std::system((std::string(FLUENCE_BINARY) + " review a.exr --port 99999 2>/dev/null").c_str()) >> 8, 2);
}

}  // namespace
}  // namespace fluence::app
