// Tests for fluence::color::ColorManagement and the shipped config config/ocio/fluence.ocio.
#include "color/color_management.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <thread>
#include <unistd.h>
#include <vector>

namespace {

using fluence::RGB;
using fluence::color::ColorError;
using fluence::color::ColorManagement;
namespace fs = std::filesystem;

const std::string kShippedConfig = std::string(FLUENCE_SOURCE_DIR) + "/config/ocio/fluence.ocio";

// Sets or unsets $OCIO for the lifetime of the guard and restores the previous state afterwards.
class OcioEnv {
public:
    explicit OcioEnv(const std::optional<std::string>& value) {
        if (const char* old = std::getenv("OCIO")) saved_ = old;
        if (value)
            ::setenv("OCIO", value->c_str(), 1);
        else
            ::unsetenv("OCIO");
    }
    ~OcioEnv() {
        if (saved_)
            ::setenv("OCIO", saved_->c_str(), 1);
        else
            ::unsetenv("OCIO");
    }
    OcioEnv(const OcioEnv&) = delete;
    OcioEnv& operator=(const OcioEnv&) = delete;

private:
    std::optional<std::string> saved_;
};

// A scratch directory removed at the end of the test.
class TempDir {
public:
    TempDir() {
        static int counter = 0;
        path_ = fs::temp_directory_path() /
                ("fluence_color_test_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
        fs::create_directories(path_);
    }
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(path_, ec);
    }
    const fs::path& path() const { return path_; }

private:
    fs::path path_;
};

// The embedded config, independent of whatever $OCIO the test environment has.
ColorManagement builtin() {
    OcioEnv env(std::nullopt);
    return ColorManagement::load();
}

// IEC 61966-2-1 sRGB. OCIO's ExponentWithLinearTransform derives the toe slope and break point from
// gamma 2.4 / offset 0.055 for exact continuity (slope 12.9232 instead of the rounded 12.92), so in
// the toe the two differ by up to ~7e-6 in encoded values: compare toe values with 1e-5.
double srgbDecode(double v) { return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); }
double srgbEncode(double v) { return v <= 0.0031308 ? v * 12.92 : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055; }

TEST(ColorManagement, EmbeddedConfigLoadsAndValidates) {
    OcioEnv env(std::nullopt);
    const ColorManagement cm = ColorManagement::load();  // load() validates the config
    EXPECT_EQ(cm.configDescription(), "Fluence built-in config");
    EXPECT_TRUE(cm.hasColorSpace(ColorManagement::kRenderingSpace));
    EXPECT_TRUE(cm.hasColorSpace(""));
    EXPECT_EQ(std::string(ColorManagement::kRenderingSpace), "lin_rec709");
    for (const char* space : {"lin_rec709", "srgb_texture", "acescg", "lin_ap0", "acescct", "lin_displayp3", "raw"})
        EXPECT_TRUE(cm.hasColorSpace(space)) << space;
    // Aliases and roles.
    for (const char* space : {"Linear Rec.709 (sRGB)", "sRGB", "sRGB - Texture", "srgb_tx", "ACEScg", "ACES2065-1",
                              "scene_linear", "rendering", "data", "color_picking"})
        EXPECT_TRUE(cm.hasColorSpace(space)) << space;
    EXPECT_FALSE(cm.hasColorSpace("no_such_space"));
    EXPECT_EQ(cm.defaultDisplay(), "sRGB");
    EXPECT_EQ(cm.defaultView("sRGB"), "Standard");
    EXPECT_EQ(cm.defaultView(""), "Standard");
}

TEST(ColorManagement, ExplicitPathLoadsShippedConfig) {
    OcioEnv env(std::string("/definitely/not/here.ocio"));  // an explicit path overrides $OCIO
    const ColorManagement cm = ColorManagement::load(kShippedConfig);
    EXPECT_EQ(cm.configDescription(), kShippedConfig);
    EXPECT_TRUE(cm.hasColorSpace("acescg"));
}

TEST(ColorManagement, SrgbTextureDecodesExactly) {
    const ColorManagement cm = builtin();
    const RGB half = cm.toRenderingSpace("srgb_texture", RGB(0.5f));
    EXPECT_NEAR(srgbDecode(0.5), 0.214041, 1e-6);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(half[i], 0.214041, 1e-5);
    const RGB mixed = cm.toRenderingSpace("sRGB", RGB(1.0f, 0.0f, 0.04f));
    EXPECT_NEAR(mixed.x, 1.0, 1e-6);
    EXPECT_NEAR(mixed.y, 0.0, 1e-7);
    EXPECT_NEAR(mixed.z, srgbDecode(0.04), 1e-5);  // linear toe
    // The bulk overload and every alias agree.
    std::vector<float> values;
    for (int i = 0; i <= 10000; ++i) values.insert(values.end(), 3, static_cast<float>(i) / 10000.0f);
    cm.toRenderingSpace("sRGB - Texture", values.data(), values.size() / 3);
    for (std::size_t i = 0; i < values.size(); ++i)
        ASSERT_NEAR(values[i], srgbDecode(static_cast<double>(i / 3) / 10000.0), 2e-6) << i;
}

TEST(ColorManagement, RenderingSpaceAndDataAreIdentity) {
    const ColorManagement cm = builtin();
    const RGB c(0.25f, -1.5f, 100.0f);
    EXPECT_EQ(cm.toRenderingSpace("", c), c);
    EXPECT_EQ(cm.toRenderingSpace("lin_rec709", c), c);
    EXPECT_EQ(cm.toRenderingSpace("Linear Rec.709 (sRGB)", c), c);
    EXPECT_EQ(cm.toRenderingSpace("scene_linear", c), c);
    EXPECT_EQ(cm.toRenderingSpace("raw", c), c);
}

TEST(ColorManagement, AcescgMatchesPublishedMatrices) {
    // Expected AP1 -> linear Rec.709 matrix, built from published matrices:
    //  - AP1 RGB -> XYZ (ACES white): Academy S-2014-004 (ACEScg spec), section 4.3.
    //  - Bradford chromatic adaptation ACES white (0.32168, 0.33767) -> D65 (0.3127, 0.3290):
    //    aces-dev, ACESlib.ODT_Common.ctl, D60_2_D65_CAT (given here to 10 digits).
    //  - XYZ -> linear Rec.709/sRGB (D65): IEC 61966-2-1 / ITU-R BT.709 primaries (10 digits).
    const double ap1ToXyz[3][3] = {{0.6624541811, 0.1340042065, 0.1561876870},
                                   {0.2722287168, 0.6740817658, 0.0536895174},
                                   {-0.0055746495, 0.0040607335, 1.0103391003}};
    const double cat[3][3] = {{0.9872240087, -0.0061132286, 0.0159532883},
                              {-0.0075983718, 1.0018614847, 0.0053300358},
                              {0.0030725771, -0.0050959615, 1.0816806031}};
    const double xyzTo709[3][3] = {{3.2409699419, -1.5373831776, -0.4986107603},
                                   {-0.9692436363, 1.8759675015, 0.0415550574},
                                   {0.0556300797, -0.2039769589, 1.0569715142}};
    auto mul = [](const double a[3][3], const double b[3][3], double out[3][3]) {
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) {
                out[r][c] = 0.0;
                for (int k = 0; k < 3; ++k) out[r][c] += a[r][k] * b[k][c];
            }
    };
    double tmp[3][3], m[3][3];
    mul(cat, ap1ToXyz, tmp);
    mul(xyzTo709, tmp, m);
    // The widely quoted result: column 0 = (1.70505, -0.13026, -0.02400).
    EXPECT_NEAR(m[0][0], 1.70505, 1e-5);
    EXPECT_NEAR(m[1][0], -0.13026, 1e-5);
    EXPECT_NEAR(m[2][0], -0.02400, 1e-5);

    const ColorManagement cm = builtin();
    for (const char* space : {"acescg", "ACEScg", "lin_ap1"}) {
        for (int col = 0; col < 3; ++col) {
            RGB unit(0.0f);
            unit[col] = 1.0f;
            const RGB out = cm.toRenderingSpace(space, unit);
            for (int row = 0; row < 3; ++row)
                EXPECT_NEAR(out[row], m[row][col], 1e-4) << space << " " << row << "," << col;
        }
    }
    // ACES white (equal AP1 RGB) maps to equal Rec.709 RGB (white stays white under Bradford).
    const RGB white = cm.toRenderingSpace("acescg", RGB(1.0f));
    EXPECT_NEAR(white.x, 1.0, 1e-4);
    EXPECT_NEAR(white.y, 1.0, 1e-4);
    EXPECT_NEAR(white.z, 1.0, 1e-4);
}

TEST(ColorManagement, OtherLinearSpacesPreserveWhite) {
    const ColorManagement cm = builtin();
    for (const char* space : {"lin_ap0", "lin_displayp3"}) {
        const RGB white = cm.toRenderingSpace(space, RGB(1.0f));
        for (int i = 0; i < 3; ++i) EXPECT_NEAR(white[i], 1.0, 1e-4) << space;
    }
    // ACEScct 0.4135884 encodes 0.18 (ACEScct spec S-2016-001).
    const RGB grey = cm.toRenderingSpace("acescct", RGB(0.4135884f));
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(grey[i], 0.18, 1e-5);
}

TEST(ColorManagement, UnknownSpaceThrowsWithName) {
    const ColorManagement cm = builtin();
    try {
        cm.toRenderingSpace("Not A Real Space", RGB(1.0f));
        FAIL() << "expected ColorError";
    } catch (const ColorError& e) {
        EXPECT_NE(std::string(e.what()).find("Not A Real Space"), std::string::npos) << e.what();
    }
    float rgb[3] = {0.5f, 0.5f, 0.5f};
    EXPECT_THROW(cm.toRenderingSpace("bogus", rgb, 0), ColorError);  // checked even with nothing to convert
}

TEST(ColorManagement, OcioEnvMissingFileThrowsWithPath) {
    const std::string missing = "/nonexistent/fluence/missing_config.ocio";
    OcioEnv env(missing);
    try {
        ColorManagement::load();
        FAIL() << "expected ColorError";
    } catch (const ColorError& e) {
        EXPECT_NE(std::string(e.what()).find(missing), std::string::npos) << e.what();
    }
}

TEST(ColorManagement, ExplicitMissingOrBrokenFileThrows) {
    OcioEnv env(std::nullopt);
    EXPECT_THROW(ColorManagement::load("/nonexistent/x.ocio"), ColorError);
    TempDir dir;
    const fs::path broken = dir.path() / "broken.ocio";
    {
        std::FILE* f = std::fopen(broken.c_str(), "w");
        ASSERT_NE(f, nullptr);
        std::fputs("ocio_profile_version: 2\ncolorspaces: [this is not\n", f);
        std::fclose(f);
    }
    try {
        ColorManagement::load(broken.string());
        FAIL() << "expected ColorError";
    } catch (const ColorError& e) {
        EXPECT_NE(std::string(e.what()).find(broken.string()), std::string::npos) << e.what();
    }
}

TEST(ColorManagement, ConfigWithoutRenderingSpaceThrows) {
    OcioEnv env(std::nullopt);
    TempDir dir;
    const fs::path path = dir.path() / "norec709.ocio";
    {
        std::FILE* f = std::fopen(path.c_str(), "w");
        ASSERT_NE(f, nullptr);
        std::fputs(
            "ocio_profile_version: 2\n"
            "roles:\n  default: linear\n  scene_linear: linear\n"
            "file_rules:\n  - !<Rule> {name: Default, colorspace: default}\n"
            "displays:\n  sRGB:\n    - !<View> {name: Raw, colorspace: linear}\n"
            "colorspaces:\n  - !<ColorSpace>\n    name: linear\n    isdata: false\n",
            f);
        std::fclose(f);
    }
    try {
        ColorManagement::load(path.string());
        FAIL() << "expected ColorError";
    } catch (const ColorError& e) {
        EXPECT_NE(std::string(e.what()).find("lin_rec709"), std::string::npos) << e.what();
    }
}

TEST(ColorManagement, OcioEnvOverridesEmbeddedConfig) {
    TempDir dir;
    const fs::path copy = dir.path() / "copy.ocio";
    fs::copy_file(kShippedConfig, copy);
    OcioEnv env(copy.string());
    const ColorManagement cm = ColorManagement::load();
    EXPECT_NE(cm.configDescription().find(copy.string()), std::string::npos) << cm.configDescription();
    EXPECT_NEAR(cm.toRenderingSpace("srgb_texture", RGB(0.5f)).x, 0.214041, 1e-5);
    // An empty $OCIO means "not set".
    OcioEnv empty(std::string(""));
    EXPECT_EQ(ColorManagement::load().configDescription(), "Fluence built-in config");
}

TEST(ColorManagement, DisplayViewSrgbStandard) {
    const ColorManagement cm = builtin();
    std::vector<float> rgb = {0.0f,   1.0f,  0.18f,    //
                              4.0f,   -0.5f, 1.0001f,  //
                              0.002f, 0.5f,  std::nanf("")};
    cm.applyDisplayView("sRGB", "Standard", rgb.data(), 3);
    EXPECT_NEAR(rgb[0], 0.0, 1e-7);
    EXPECT_NEAR(rgb[1], 1.0, 1e-6);
    EXPECT_NEAR(rgb[2], 0.4613561, 1e-6);
    EXPECT_NEAR(srgbEncode(0.18), 0.4613561, 1e-7);
    EXPECT_NEAR(rgb[3], 1.0, 1e-6);  // > 1 clips
    EXPECT_EQ(rgb[4], 0.0f);         // < 0 clips
    EXPECT_NEAR(rgb[5], 1.0, 1e-6);
    EXPECT_NEAR(rgb[6], srgbEncode(0.002), 1e-5);  // linear toe
    EXPECT_NEAR(rgb[7], srgbEncode(0.5), 1e-6);
    EXPECT_EQ(rgb[8], 0.0f);  // NaN becomes 0
    for (float v : rgb) {
        EXPECT_GE(v, 0.0f);
        EXPECT_LE(v, 1.0f);
    }
    // Defaults are sRGB / Standard.
    float d[3] = {0.18f, 0.18f, 0.18f};
    cm.applyDisplayView("", "", d, 1);
    EXPECT_NEAR(d[0], 0.4613561, 1e-6);
}

TEST(ColorManagement, DisplayViewRawAndUnknown) {
    const ColorManagement cm = builtin();
    float rgb[6] = {0.18f, 0.5f, 2.0f, -1.0f, 0.0f, 1.0f};
    cm.applyDisplayView("sRGB", "Raw", rgb, 2);
    EXPECT_EQ(rgb[0], 0.18f);
    EXPECT_EQ(rgb[1], 0.5f);
    EXPECT_EQ(rgb[2], 1.0f);  // clamped
    EXPECT_EQ(rgb[3], 0.0f);
    try {
        cm.applyDisplayView("Imaginary Display", "", rgb, 2);
        FAIL() << "expected ColorError";
    } catch (const ColorError& e) {
        EXPECT_NE(std::string(e.what()).find("Imaginary Display"), std::string::npos) << e.what();
    }
    try {
        cm.applyDisplayView("sRGB", "Filmic Dreams", rgb, 2);
        FAIL() << "expected ColorError";
    } catch (const ColorError& e) {
        EXPECT_NE(std::string(e.what()).find("Filmic Dreams"), std::string::npos) << e.what();
    }
}

TEST(ColorManagement, RenderingChromaticitiesAreRec709D65) {
    const auto c = ColorManagement::renderingChromaticities();
    const float expected[8] = {0.64f, 0.33f, 0.30f, 0.60f, 0.15f, 0.06f, 0.3127f, 0.3290f};
    for (int i = 0; i < 8; ++i) EXPECT_EQ(c[i], expected[i]) << i;
}

TEST(ColorManagement, ConcurrentUseFromManyThreads) {
    const ColorManagement cm = builtin();
    const ColorManagement copy = cm;  // copies share the config and the cache
    std::vector<std::thread> threads;
    std::vector<int> failures(8, 0);
    for (int t = 0; t < 8; ++t) {
        threads.emplace_back([&, t] {
            const ColorManagement& mine = (t % 2) ? cm : copy;
            const char* spaces[] = {"srgb_texture", "acescg", "lin_ap0", "lin_displayp3"};
            for (int i = 0; i < 200; ++i) {
                const RGB s = mine.toRenderingSpace(spaces[(i + t) % 4], RGB(0.5f));
                if (((i + t) % 4) == 0 && std::abs(s.x - 0.2140411f) > 1e-5f) ++failures[t];
                float d[3] = {0.18f, 0.18f, 0.18f};
                mine.applyDisplayView("", "", d, 1);
                if (std::abs(d[0] - 0.4613561f) > 1e-5f) ++failures[t];
            }
        });
    }
    for (auto& th : threads) th.join();
    for (int t = 0; t < 8; ++t) EXPECT_EQ(failures[t], 0) << t;
}

}  // namespace
