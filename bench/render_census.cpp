// render_census LISTING OUT.tsv [TIMEOUT_SECONDS]: the render census of a list of USD files, as
// `fluence render FILE -o out.exr -r 16 16 --spp 1 -j 1` runs it (apps/command_line.h), again with
// --allow-missing when that exits 4 (a missing asset) or 3 for a layer that needs a file format
// plugin Fluence does not have (Alembic, Draco), each run in a forked child (a crash or a hang costs only that
// file: TIMEOUT_SECONDS, 60 by default, then SIGKILL). Forking skips what starting a process costs
// (loading the shared libraries takes most of a tiny render's time), so the 2,859 files of the
// four public mirrors take minutes instead of an hour. Rows already in OUT.tsv are skipped, so a
// stopped census resumes. One row per file, tab-separated, as bench/census_summary.py reads them:
// path; exit code of the plain run (or timeout, signal N); exit code with --allow-missing when the
// plain run was retried with it, else -; the image class (lit: some beauty above 0; dark: alpha above 0 but
// the beauty 0; empty: neither; nonfinite; - no image); seconds; whether stderr names a
// file:line:column (yes/no); stderr's first error line (else its first line).
#include <OpenImageIO/imageio.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "apps/command_line.h"

namespace fs = std::filesystem;

namespace {

// The class of the image at `exr` (see the header); "-" when there is none.
std::string imageClass(const fs::path& exr) {
    auto in = OIIO::ImageInput::open(exr.string());
    if (!in) return "-";
    const OIIO::ImageSpec& spec = in->spec();
    std::vector<float> pixels(std::size_t(spec.width) * std::size_t(spec.height) * std::size_t(spec.nchannels));
    if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data())) return "unreadable";
    const int r = spec.channelindex("R"), g = spec.channelindex("G"), b = spec.channelindex("B"),
              a = spec.channelindex("A");
    if (r < 0 || g < 0 || b < 0) return "unreadable";
    bool lit = false, covered = false;
    for (std::size_t p = 0; p < pixels.size(); p += std::size_t(spec.nchannels)) {
        for (int c : {r, g, b, a})
            if (c >= 0 && !std::isfinite(pixels[p + std::size_t(c)])) return "nonfinite";
        lit = lit || pixels[p + std::size_t(r)] > 0 || pixels[p + std::size_t(g)] > 0 || pixels[p + std::size_t(b)] > 0;
        covered = covered || (a >= 0 && pixels[p + std::size_t(a)] > 0);
    }
    return lit ? "lit" : covered ? "dark" : "empty";
}

struct Run {
    std::string exit;   // the exit code, "timeout" or "signal N"
    std::string image;  // imageClass of the output, when it exited 0
    std::string err;    // what it wrote on stderr
};

// `fluence render` of `scene` in a forked child working in `work`.
Run render(const std::string& scene, bool allowMissing, const fs::path& work, int timeoutSeconds) {
    const fs::path exr = work / "out.exr", err = work / "stderr.txt", image = work / "image.txt";
    for (const fs::path& p : {exr, err, image}) fs::remove(p);
    const pid_t child = fork();
    if (child == 0) {
        std::freopen(err.c_str(), "w", stderr);
        std::freopen("/dev/null", "w", stdout);
        fs::current_path(work);
        std::vector<std::string> args{"render", scene, "-o", exr.string(), "-r", "16", "16", "--spp", "1", "-j", "1"};
        if (allowMissing) args.push_back("--allow-missing");
        const int code = fluence::app::runCommandLine(args);
        std::fflush(stderr);
        if (code == 0) std::ofstream(image) << imageClass(exr);
        _exit(code);
    }
    Run run;
    int status = 0;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(timeoutSeconds);
    while (waitpid(child, &status, WNOHANG) == 0) {
        if (std::chrono::steady_clock::now() > deadline) {
            kill(child, SIGKILL);
            waitpid(child, &status, 0);
            run.exit = "timeout";
            break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    if (run.exit.empty())
        run.exit =
            WIFEXITED(status) ? std::to_string(WEXITSTATUS(status)) : "signal " + std::to_string(WTERMSIG(status));
    std::stringstream text;
    text << std::ifstream(err).rdbuf();
    run.err = text.str();
    std::ifstream(image) >> run.image;
    return run;
}

// stderr's first "error" line, else its first line, without tabs.
std::string firstErrorLine(const std::string& err) {
    std::istringstream lines(err);
    std::string line, first;
    while (std::getline(lines, line)) {
        if (first.empty()) first = line;
        if (line.find("error") != std::string::npos) {
            first = line;
            break;
        }
    }
    for (char& c : first)
        if (c == '\t') c = ' ';
    return first.substr(0, 300);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 3 || argc > 4) {
        std::cerr << "usage: render_census LISTING OUT.tsv [TIMEOUT_SECONDS]\n";
        return 2;
    }
    const int timeoutSeconds = argc == 4 ? std::stoi(argv[3]) : 60;
    std::set<std::string> done;
    {
        std::ifstream previous(argv[2]);
        for (std::string line; std::getline(previous, line);) done.insert(line.substr(0, line.find('\t')));
    }
    std::ifstream listing(argv[1]);
    if (!listing) {
        std::cerr << "render_census: cannot read " << argv[1] << "\n";
        return 2;
    }
    const fs::path work = fs::temp_directory_path() / ("render_census_" + std::to_string(getpid()));
    fs::create_directories(work);
    std::ofstream out(argv[2], std::ios::app);
    static const std::regex location(":[0-9]+:[0-9]+: ");
    for (std::string path; std::getline(listing, path);) {
        if (path.empty() || done.count(path)) continue;
        const auto start = std::chrono::steady_clock::now();
        const Run plain = render(path, false, work, timeoutSeconds);
        // A missing asset (exit 4), or a layer in a format Fluence has no plugin for (exit 3): again with --allow-missing.
        const bool retry = plain.exit == "4" ||
                           (plain.exit == "3" && plain.err.find("plugin Fluence does not have") != std::string::npos);
        const Run last = retry ? render(path, true, work, timeoutSeconds) : plain;
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const std::string& err =
            last.exit == "0" ? plain.err : last.err;  // why it failed, else the first run's warnings
        char time[32];
        std::snprintf(time, sizeof time, "%.2f", seconds);
        out << path << '\t' << plain.exit << '\t' << (retry ? last.exit : "-") << '\t'
            << (last.image.empty() ? "-" : last.image) << '\t' << time << '\t'
            << (std::regex_search(err, location) ? "yes" : "no") << '\t' << firstErrorLine(err) << std::endl;
    }
    fs::remove_all(work);
}
