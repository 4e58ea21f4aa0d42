// The stability suite in CI (issue #10): the scenes of bench/stability/, where methods are known to
// fail, are the files the benchmark renders in full; here each is read through the delegate, as
// `fluence render` reads it, and rendered small by every integrator its header lists.
//
// Asserted per scene and method: no sample was NaN or infinite (RenderCounters::nonFiniteSamples)
// and every pixel is finite. The energy checks compare image means through the per-pixel
// differences of two renders (independent across pixels, so their spread gives the standard
// error of the mean difference), with a tolerance of kStandardErrors of it:
// - the unbiased methods the header expects to converge agree pairwise;
// - a method it expects to miss light is not brighter than the first of those;
// - where fewer than two such methods apply, the first unbiased method listed agrees with itself
//   under another seed.
// Only methods whose pixels are independent estimates take part (sppm's photon maps and the
// radiosity solution are shared by every pixel). Each file's header is checked against the
// contract in bench/stability/README.md, which the benchmark (bench/run.py) reads.
// Lives with the end-to-end tests because it needs the delegate (apps_tests links the whole app);
// tests/integrators/stability_test.cpp keeps the stress scenes built in C++.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "color/color_management.h"
#include "delegate/scene_delegate.h"
#include "integrators/integrator.h"
#include "scene/stage.h"
#include "tests/integrators/render_support.h"
#include "tests/support/statistics.h"

namespace fluence {
namespace {

namespace fs = std::filesystem;
using integrators::test_support::Rendered;

const fs::path kSuite = fs::path(FLUENCE_SOURCE_DIR) / "bench/stability";
constexpr int kSize = 48;  // pixels on a side
constexpr int kSpp = 32;
constexpr double kStandardErrors = 5.0;
// The methods whose pixels are independent, unbiased estimates of what they cover.
const std::vector<std::string> kPixelIndependent = {"path", "bdpt", "naive", "direct", "whitted"};

// The header every scene of the suite starts with (bench/stability/README.md).
struct StabilityHeader {
    std::string stability;
    std::string referenceIntegrator;
    int referenceSpp = 0;
    std::vector<std::string> integrators;
    std::map<std::string, std::string> expect;  // integrator -> converges | biased | misses | refuses
    std::string why;
};

std::vector<std::string> words(const std::string& text) {
    std::istringstream in(text);
    std::vector<std::string> out;
    for (std::string w; in >> w;) out.push_back(w);
    return out;
}

// The header of `file`; throws std::runtime_error saying which line is missing or malformed.
StabilityHeader readHeader(const fs::path& file) {
    std::ifstream in(file);
    std::string line;
    if (!std::getline(in, line) || line != "#usda 1.0") throw std::runtime_error("line 1 is not '#usda 1.0'");
    auto field = [&](const std::string& key) {
        const std::string prefix = "# " + key + ": ";
        if (!std::getline(in, line) || !line.starts_with(prefix) || line.size() == prefix.size())
            throw std::runtime_error("expected '" + prefix + "...', found '" + line + "'");
        return line.substr(prefix.size());
    };
    StabilityHeader h;
    h.stability = field("stability");
    const std::vector<std::string> reference = words(field("reference"));
    if (reference.size() != 2) throw std::runtime_error("reference: not '<integrator> <spp>'");
    h.referenceIntegrator = reference[0];
    h.referenceSpp = std::stoi(reference[1]);
    h.integrators = words(field("integrators"));
    for (const std::string& token : words(field("expect"))) {
        const std::size_t eq = token.find('=');
        if (eq == std::string::npos) throw std::runtime_error("expect: '" + token + "' is not integrator=verdict");
        h.expect[token.substr(0, eq)] = token.substr(eq + 1);
    }
    h.why = field("why");
    return h;
}

std::vector<fs::path> suiteScenes() {
    std::vector<fs::path> files;
    for (const fs::directory_entry& e : fs::directory_iterator(kSuite))
        if (e.path().extension() == ".usda") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    return files;
}

bool pixelIndependent(const std::string& integrator) {
    return std::find(kPixelIndependent.begin(), kPixelIndependent.end(), integrator) != kPixelIndependent.end();
}

// The scene as `fluence render` describes it: composed, populated through the delegate, colours
// in the rendering space.
render::SceneDescription describe(const fs::path& file) {
    static const color::ColorManagement colors = color::ColorManagement::load();
    std::unique_ptr<usd::Stage> stage = usd::Stage::open(file.string());
    delegate::DelegateOptions options;
    options.convertColor = [](const RGB& c, const std::string& space) { return colors.toRenderingSpace(space, c); };
    options.warn = [&file](const std::string& path, const std::string& message) {
        ADD_FAILURE() << file.filename() << ": " << path << ": " << message;
    };
    return delegate::populateScene(*stage, options).scene;
}

// The mean over pixels of (mean of R, G, B of a) - (the same of b), with its standard error.
test::MeanEstimate meanDifference(const Image& a, const Image& b) {
    test::MeanEstimate d;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            const float *p = a.pixel(x, y), *q = b.pixel(x, y);
            d.add(((p[0] + p[1] + p[2]) - (q[0] + q[1] + q[2])) / 3.0);
        }
    return d;
}

double imageMean(const Image& image) {
    double sum = 0.0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const float* p = image.pixel(x, y);
            sum += (p[0] + p[1] + p[2]) / 3.0;
        }
    return sum / (double(image.width) * image.height);
}

TEST(StabilityScenes, EveryFileStatesTheContract) {
    const std::vector<fs::path> files = suiteScenes();
    EXPECT_GE(files.size(), 9u) << "issue #10 names nine cases";
    for (const fs::path& file : files) {
        SCOPED_TRACE(file.filename().string());
        StabilityHeader h;
        try {
            h = readHeader(file);
        } catch (const std::exception& e) {
            ADD_FAILURE() << e.what();
            continue;
        }
        EXPECT_GT(h.referenceSpp, 0);
        EXPECT_EQ(h.expect.size(), h.integrators.size()) << "one expect token per listed integrator";
        EXPECT_TRUE(h.expect.contains(h.referenceIntegrator) && h.expect.at(h.referenceIntegrator) == "converges")
            << "the reference must be a listed method expected to converge";
        for (const std::string& name : h.integrators) {
            EXPECT_NE(integrators::findIntegrator(name), nullptr) << name;
            ASSERT_TRUE(h.expect.contains(name)) << name << " has no expect token";
            const std::string& verdict = h.expect.at(name);
            EXPECT_TRUE(verdict == "converges" || verdict == "biased" || verdict == "misses" || verdict == "refuses")
                << name << "=" << verdict;
        }
    }
}

class StabilityScene : public ::testing::TestWithParam<std::string> {};

TEST_P(StabilityScene, NoMethodMakesANaNOrInfinityAndTheEnergyChecksHold) {
    const fs::path file = kSuite / GetParam();
    const StabilityHeader h = readHeader(file);
    for (const std::string& name : h.integrators) ASSERT_NE(integrators::findIntegrator(name), nullptr) << name;
    const render::SceneDescription scene = describe(file);
    auto renderBy = [&](const std::string& name, std::uint64_t seed) {
        const std::unique_ptr<integrators::Integrator> integrator = integrators::findIntegrator(name)->create({});
        return integrators::test_support::renderWith(*integrator, scene, kSize, kSpp, 0, seed);
    };

    // Each method under a seed of its own: methods that share sampling decisions (bdpt's camera
    // subpaths are path's) would otherwise share their rare bright samples, and the standard
    // error of their difference would shrink below what independent estimates have.
    std::map<std::string, Image> images;
    std::uint64_t seed = 0;
    for (const std::string& name : h.integrators) {
        Rendered r = renderBy(name, ++seed);
        std::uint64_t nonFinitePixels = 0;
        for (float v : r.image.pixels) nonFinitePixels += !std::isfinite(v);
        std::printf("[ measured ] %-24s %-9s %llu non-finite samples, image mean %.5g (expect %s)\n",
                    GetParam().c_str(), name.c_str(),
                    static_cast<unsigned long long>(r.stats.counters.nonFiniteSamples), imageMean(r.image),
                    h.expect.at(name).c_str());
        EXPECT_EQ(r.stats.counters.nonFiniteSamples, 0u) << name;
        EXPECT_EQ(nonFinitePixels, 0u) << name;
        images.emplace(name, std::move(r.image));
    }

    // a - b over the pixels, printed with its standard error.
    auto difference = [&](const std::string& a, const Image& imageA, const std::string& b, const Image& imageB) {
        const test::MeanEstimate d = meanDifference(imageA, imageB);
        std::printf("[ measured ] %-24s %s - %s = %.3g +- %.2g\n", GetParam().c_str(), a.c_str(), b.c_str(), d.mean(),
                    d.standardError());
        return d;
    };
    std::vector<std::string> converging, missing;
    for (const auto& [name, image] : images)
        if (pixelIndependent(name)) {
            if (h.expect.at(name) == "converges") converging.push_back(name);
            if (h.expect.at(name) == "misses") missing.push_back(name);
        }
    for (std::size_t i = 0; i < converging.size(); ++i)
        for (std::size_t j = i + 1; j < converging.size(); ++j) {
            const std::string &a = converging[i], &b = converging[j];
            const test::MeanEstimate d = difference(a, images.at(a), b, images.at(b));
            EXPECT_LE(std::abs(d.mean()), kStandardErrors * d.standardError()) << a << " and " << b << " disagree";
        }
    if (!converging.empty())
        for (const std::string& name : missing) {
            const test::MeanEstimate d =
                difference(name, images.at(name), converging.front(), images.at(converging.front()));
            EXPECT_LE(d.mean(), kStandardErrors * d.standardError())
                << name << " misses light yet is brighter than " << converging.front();
        }
    if (converging.size() < 2) {
        const auto first = std::find_if(h.integrators.begin(), h.integrators.end(), [&](const std::string& n) {
            return pixelIndependent(n) && images.contains(n);
        });
        ASSERT_NE(first, h.integrators.end()) << "no unbiased method rendered the scene";
        const Rendered again = renderBy(*first, seed + 1);
        const test::MeanEstimate d =
            difference(*first + "(seed 1)", images.at(*first), *first + "(seed 2)", again.image);
        EXPECT_LE(std::abs(d.mean()), kStandardErrors * d.standardError()) << *first << " disagrees with itself";
    }
}

std::vector<std::string> suiteSceneNames() {
    std::vector<std::string> names;
    for (const fs::path& file : suiteScenes()) names.push_back(file.filename().string());
    return names;
}

INSTANTIATE_TEST_SUITE_P(BenchStability, StabilityScene, ::testing::ValuesIn(suiteSceneNames()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                             return fs::path(info.param).stem().string();
                         });

}  // namespace
}  // namespace fluence
