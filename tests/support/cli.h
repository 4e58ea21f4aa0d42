// Running the `fluence` binary from tests, and reading back the EXRs it writes.
#pragma once

#include <OpenImageIO/imageio.h>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace fluence::test {

struct RunResult {
    int exitCode = -1;
    std::string out, err;
};

inline std::string slurp(const std::filesystem::path& p) {
    std::ifstream in(p);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// Runs `fluence ARGS` with no standard input, capturing its output in files under `dir`.
inline RunResult runFluence(const std::string& args, const std::filesystem::path& dir) {
    std::filesystem::path out = dir / "stdout.txt", err = dir / "stderr.txt";
    std::string cmd =
        std::string(FLUENCE_BINARY) + " " + args + " > " + out.string() + " 2> " + err.string() + " < /dev/null";
    int status = std::system(cmd.c_str());
    RunResult r;
    r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = slurp(out);
    r.err = slurp(err);
    return r;
}

struct ExrImage {
    int width = 0, height = 0;
    std::vector<std::string> channels;
    std::vector<float> pixels;
    OIIO::ImageSpec spec;
    int channel(const std::string& name) const {
        for (std::size_t i = 0; i < channels.size(); ++i)
            if (channels[i] == name) return int(i);
        return -1;
    }
    float at(int x, int y, const std::string& name) const {
        return pixels[(std::size_t(y) * width + x) * channels.size() + channel(name)];
    }
};

inline ExrImage readExr(const std::filesystem::path& path) {
    auto in = OIIO::ImageInput::open(path.string());
    if (!in) throw std::runtime_error("cannot open " + path.string());
    ExrImage img;
    img.spec = in->spec();
    img.width = img.spec.width;
    img.height = img.spec.height;
    img.channels = img.spec.channelnames;
    img.pixels.resize(std::size_t(img.width) * img.height * img.channels.size());
    if (!in->read_image(0, 0, 0, -1, OIIO::TypeDesc::FLOAT, img.pixels.data())) throw std::runtime_error("cannot read");
    return img;
}

}  // namespace fluence::test
