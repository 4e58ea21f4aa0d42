// `fluence render --denoise` and `fluence denoise` on every sample scene (issue #27's "Done when"),
// small and cheap: 48 x 32 pixels, 2 samples. The sample scenes are the .usd/.usda files under
// usd_samples/ that define a camera or that no other file there names in an asset path (the rest
// are their sublayers, references and payloads), found on disk so that a new sample is covered
// without editing this test.
//
// Per scene, with --denoise-layers (so the light path layers of a product's lpe vars are denoised
// too): a plain render and a denoised one exit 0, and the latter warns of nothing the denoiser left
// out; its RGB is finite; its noisy.R/G/B, and each NAME_noisy layer, are bit-identical to the
// plain render's R G B and NAME (the buffers change no sample). The same render in two tiles,
// assembled and then denoised by `fluence denoise`, gives the same image (no seam).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "tests/support/cli.h"
#include "tests/support/exr_values.h"
#include "tests/support/temp_dir.h"

namespace fs = std::filesystem;

namespace fluence {
namespace {

using test::RunResult;

const fs::path kSamples = fs::path(FLUENCE_SOURCE_DIR) / "usd_samples";
const std::string kOptions = " -r 48 32 --spp 2 --seed 3 ";

bool isUsd(const fs::path& file) { return file.extension() == ".usda" || file.extension() == ".usd"; }

// The USD files under usd_samples/ that define a camera or that no other one names as
// `@.../NAME@` (binary crate files keep their asset paths as plain strings, so they are searched
// alike), sorted.
std::vector<fs::path> sampleScenes() {
    std::vector<fs::path> files;
    for (const auto& entry : fs::recursive_directory_iterator(kSamples))
        if (entry.is_regular_file() && isUsd(entry.path())) files.push_back(entry.path());
    std::vector<std::string> texts;
    for (const fs::path& file : files) texts.push_back(test::slurp(file));
    const auto namedByAny = [&](const std::string& name) {
        return std::any_of(texts.begin(), texts.end(), [&](const std::string& text) {
            return text.find("/" + name + "@") != std::string::npos || text.find("@" + name + "@") != std::string::npos;
        });
    };
    std::vector<fs::path> scenes;
    for (std::size_t f = 0; f < files.size(); ++f)
        if (texts[f].find("def Camera") != std::string::npos || !namedByAny(files[f].filename().string()))
            scenes.push_back(files[f]);
    std::sort(scenes.begin(), scenes.end());
    return scenes;
}

const std::vector<std::string> kRGB{"R", "G", "B"}, kNoisy{"noisy.R", "noisy.G", "noisy.B"};

// The light path layers `denoised` keeps a noisy copy of (NAME_noisy.R): NAME.R/G/B and NAME_noisy.R/G/B.
std::vector<std::pair<std::vector<std::string>, std::vector<std::string>>> denoisedLayers(
    const test::ExrImage& denoised) {
    std::vector<std::pair<std::vector<std::string>, std::vector<std::string>>> layers;
    for (const std::string& channel : denoised.channels)
        if (channel.ends_with("_noisy.R")) {
            const std::string name = channel.substr(0, channel.size() - std::string("_noisy.R").size());
            layers.push_back(
                {{name + ".R", name + ".G", name + ".B"}, {name + "_noisy.R", name + "_noisy.G", name + "_noisy.B"}});
        }
    return layers;
}

TEST(DenoiseSamplesCli, EverySampleSceneRendersDenoisedAndDenoisesFromTiles) {
    const std::vector<fs::path> scenes = sampleScenes();
    ASSERT_GE(scenes.size(), 20u) << "usd_samples/ not found where expected: " << kSamples;
    test::TempDir tmp{"fluence_denoise_samples"};
    const auto run = [&](const std::string& args) { return test::runFluence(args, tmp.path()); };
    for (const fs::path& scene : scenes) {
        SCOPED_TRACE(fs::relative(scene, kSamples).string());
        const std::string render = "render " + scene.string() + kOptions;
        RunResult r = run(render + "-o " + tmp.file("plain.exr"));
        ASSERT_EQ(r.exitCode, 0) << r.err;
        r = run(render + "--denoise-layers -o " + tmp.file("denoised.exr"));
        ASSERT_EQ(r.exitCode, 0) << r.err;
        EXPECT_EQ(r.err.find("not denoised"), std::string::npos) << r.err;
        EXPECT_EQ(r.err.find("denoiser's buffers"), std::string::npos) << r.err;
        std::string tiles;
        for (int tile = 0; tile < 2; ++tile) {
            const std::string index = std::to_string(tile);
            r = run(render + "--denoise-layers --tile-count 2 1 --tile-index " + index + " -o " + tmp.file("part.exr"));
            ASSERT_EQ(r.exitCode, 0) << r.err;
            tiles.append(" ").append(tmp.file("part_tile" + index + ".exr"));
        }
        r = run("assemble -o " + tmp.file("assembled.exr") + tiles);
        ASSERT_EQ(r.exitCode, 0) << r.err;
        r = run("denoise " + tmp.file("assembled.exr") + " --denoise-layers -o " + tmp.file("later.exr"));
        ASSERT_EQ(r.exitCode, 0) << r.err;

        const test::ExrImage plain = test::readExr(tmp.file("plain.exr")),
                             denoised = test::readExr(tmp.file("denoised.exr")),
                             later = test::readExr(tmp.file("later.exr"));
        ASSERT_GE(denoised.channel("noisy.B"), 0) << "no noisy beauty kept";
        const std::vector<float> rgb = test::channelValues(denoised, kRGB);
        EXPECT_TRUE(std::all_of(rgb.begin(), rgb.end(), [](float v) { return std::isfinite(v); }));
        EXPECT_EQ(test::channelValues(denoised, kNoisy), test::channelValues(plain, kRGB))
            << "the noisy beauty is not the plain render's";
        EXPECT_EQ(test::channelValues(later, kRGB), rgb) << "fluence denoise on the assembled tiles differs";
        EXPECT_EQ(test::channelValues(later, kNoisy), test::channelValues(denoised, kNoisy));
        for (const auto& [layer, noisyLayer] : denoisedLayers(denoised)) {
            SCOPED_TRACE(layer.front());
            EXPECT_EQ(test::channelValues(denoised, noisyLayer), test::channelValues(plain, layer));
            EXPECT_EQ(test::channelValues(later, layer), test::channelValues(denoised, layer));
        }
    }
}

}  // namespace
}  // namespace fluence
