// BasisCurves and NurbsCurves read into render::CurvesDesc (delegate/curves_adapter.h): segment
// counts per type, basis and wrap as UsdGeom's basisCurves.h tabulates them, periodic and pinned
// curves unrolled, widths by each interpolation, displayColor, normals making ribbons, the
// curveStyle primvar, bad counts skipping the prim with a warning naming it, NURBS curves
// evaluated, and the public scenes that use these schemas no longer dropping them.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "tests/delegate/delegate_test_support.h"
#include "tests/support/shared_data.h"

namespace fluence::delegate {
namespace {

using testing::populate;

const render::CurvesDesc* curvesNamed(const testing::Populated& p, const std::string& name) {
    for (const render::CurvesDesc& c : p.result.scene.curves)
        if (c.name == name) return &c;
    return nullptr;
}

std::string curves(const std::string& body) { return "def BasisCurves \"C\"\n{\n" + body + "}\n"; }

TEST(CurvesAdapter, SegmentCountsFollowTheUsdGeomTables) {
    struct Case {
        std::string type, basis, wrap;
        int vertices;
        std::size_t segments, controlPoints;
    };
    const Case cases[] = {
        {"linear", "bezier", "nonperiodic", 5, 4, 5},    {"linear", "bezier", "periodic", 5, 5, 6},
        {"cubic", "bezier", "nonperiodic", 7, 2, 7},     {"cubic", "bezier", "periodic", 6, 2, 7},
        {"cubic", "bspline", "nonperiodic", 6, 3, 6},    {"cubic", "bspline", "periodic", 5, 5, 8},
        {"cubic", "bspline", "pinned", 5, 4, 7},         {"cubic", "catmullRom", "pinned", 2, 1, 4},
        {"cubic", "catmullRom", "nonperiodic", 4, 1, 4}, {"cubic", "bezier", "pinned", 4, 1, 4},
    };
    for (const Case& c : cases) {
        std::string points;
        for (int i = 0; i < c.vertices; ++i)
            points += (i ? ", (" : "(") + std::to_string(i) + ", 0, " + std::to_string(i % 2) + ")";
        auto p = populate(curves("    uniform token type = \"" + c.type + "\"\n    uniform token basis = \"" + c.basis +
                                 "\"\n    uniform token wrap = \"" + c.wrap + "\"\n    int[] curveVertexCounts = [" +
                                 std::to_string(c.vertices) + "]\n    point3f[] points = [" + points + "]\n"));
        const render::CurvesDesc* d = curvesNamed(p, "/C");
        ASSERT_NE(d, nullptr) << c.type << " " << c.basis << " " << c.wrap;
        EXPECT_EQ(d->segments.size(), c.segments) << c.type << " " << c.basis << " " << c.wrap;
        EXPECT_EQ(d->points.size(), c.controlPoints) << c.type << " " << c.basis << " " << c.wrap;
        EXPECT_EQ(d->radii.size(), d->points.size());
        EXPECT_FLOAT_EQ(d->radii[0], 0.5f) << "unauthored widths are 1";
    }
}

TEST(CurvesAdapter, PinnedCurvesGainPhantomPointsAndPeriodicOnesWrap) {
    auto pinned = populate(curves(R"(    uniform token type = "cubic"
    uniform token basis = "bspline"
    uniform token wrap = "pinned"
    int[] curveVertexCounts = [3]
    point3f[] points = [(0, 0, 0), (1, 0, 0), (1, 2, 0)]
)"));
    const render::CurvesDesc* d = curvesNamed(pinned, "/C");
    ASSERT_NE(d, nullptr);
    ASSERT_EQ(d->points.size(), 5u);
    EXPECT_EQ(d->basis, render::CurveBasis::BSpline);
    EXPECT_EQ(d->points.front(), Vec3f(-1, 0, 0)) << "P[-1] = 2 P[0] - P[1]";
    EXPECT_EQ(d->points.back(), Vec3f(1, 4, 0)) << "P[n] = 2 P[n-1] - P[n-2]";
    auto periodic = populate(curves(R"(    uniform token type = "cubic"
    uniform token basis = "bezier"
    uniform token wrap = "periodic"
    int[] curveVertexCounts = [3, 6]
    point3f[] points = [(0, 0, 0), (1, 0, 0), (2, 0, 0), (0, 1, 0), (1, 1, 0), (2, 1, 0), (3, 1, 0), (4, 1, 0), (5, 1, 0)]
)"));
    d = curvesNamed(periodic, "/C");
    ASSERT_NE(d, nullptr);
    ASSERT_EQ(d->segments, (std::vector<std::uint32_t>{0, 4, 7}));
    EXPECT_EQ(d->points[3], Vec3f(0, 0, 0)) << "the first curve closes on its first vertex";
    EXPECT_EQ(d->points[10], Vec3f(0, 1, 0)) << "the second one too";
}

TEST(CurvesAdapter, WidthsByEveryInterpolation) {
    const std::string topology = R"(    uniform token type = "cubic"
    uniform token basis = "bezier"
    int[] curveVertexCounts = [4, 7]
    point3f[] points = [(0, 0, 0), (1, 0, 0), (2, 0, 0), (3, 0, 0), (0, 1, 0), (1, 1, 0), (2, 1, 0), (3, 1, 0), (4, 1, 0), (5, 1, 0), (6, 1, 0)]
)";
    auto radii = [&](const std::string& widths) {
        auto p = populate(curves(topology + widths));
        const render::CurvesDesc* d = curvesNamed(p, "/C");
        EXPECT_NE(d, nullptr) << widths;
        return d ? d->radii : std::vector<float>{};
    };
    EXPECT_EQ(radii("    float[] widths = [0.2] (interpolation = \"constant\")\n"), std::vector<float>(11, 0.1f));
    std::vector<float> uniform = radii("    float[] widths = [0.2, 0.4] (interpolation = \"uniform\")\n");
    EXPECT_EQ(uniform, (std::vector<float>{0.1f, 0.1f, 0.1f, 0.1f, 0.2f, 0.2f, 0.2f, 0.2f, 0.2f, 0.2f, 0.2f}));
    std::vector<float> vertex = radii("    float[] widths = [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11]\n");
    EXPECT_FLOAT_EQ(vertex[10], 5.5f) << "vertex is the default interpolation";
    // Varying: segments + 1 per curve (2 and 3), at vertices 0, 3, 6, linear between.
    std::vector<float> varying = radii("    float[] widths = [2, 4, 2, 8, 14] (interpolation = \"varying\")\n");
    ASSERT_EQ(varying.size(), 11u);
    EXPECT_FLOAT_EQ(varying[0], 1.0f);
    EXPECT_FLOAT_EQ(varying[3], 2.0f);
    EXPECT_FLOAT_EQ(varying[1], 1.0f + 1.0f / 3.0f);
    EXPECT_FLOAT_EQ(varying[4], 1.0f);
    EXPECT_FLOAT_EQ(varying[6], 3.0f);
    EXPECT_FLOAT_EQ(varying[8], 5.0f);
    EXPECT_FLOAT_EQ(varying[10], 7.0f);
}

TEST(CurvesAdapter, BadCountsSkipThePrimWithAWarningNamingIt) {
    const std::string bad[] = {
        // The counts add up to more than the points.
        R"(    uniform token type = "linear"
    int[] curveVertexCounts = [3]
    point3f[] points = [(0, 0, 0), (1, 0, 0)]
)",
        // Varying widths need segments + 1 = 2 values per curve.
        R"(    uniform token type = "linear"
    int[] curveVertexCounts = [2, 2]
    point3f[] points = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (1, 1, 0)]
    float[] widths = [1, 2, 3] (interpolation = "varying")
)",
        R"(    uniform token type = "linear"
    uniform token basis = "hermite"
    uniform token wrap = "sideways"
    int[] curveVertexCounts = [2]
    point3f[] points = [(0, 0, 0), (1, 0, 0)]
)",
    };
    for (const std::string& body : bad) {
        auto p = populate(curves(body));
        EXPECT_EQ(curvesNamed(p, "/C"), nullptr) << body;
        bool named = false;
        for (const std::string& w : p.warnings) named = named || w.starts_with("/C: ");
        EXPECT_TRUE(named) << body;
        EXPECT_THROW(testing::populateStrict(curves(body)), SceneError) << body;
    }
}

TEST(CurvesAdapter, ACurveOfInvalidCountIsLeftOutAloneAndOneValueIsConstant) {
    // 5 is not 4 + 3k for a Bezier curve: that curve is left out with a warning, the other renders
    // (as Hydra draws a batch's valid curves); one width (no interpolation said) is constant.
    auto p = populate(curves(R"(    uniform token type = "cubic"
    int[] curveVertexCounts = [5, 4]
    point3f[] points = [(0, 0, 0), (1, 0, 0), (2, 0, 0), (3, 0, 0), (4, 0, 0), (0, 1, 0), (1, 1, 0), (2, 1, 0), (3, 1, 0)]
    float[] widths = [0.5]
)"));
    const render::CurvesDesc* d = curvesNamed(p, "/C");
    ASSERT_NE(d, nullptr);
    EXPECT_EQ(d->segments, (std::vector<std::uint32_t>{0}));
    EXPECT_EQ(d->points.front(), Vec3f(0, 1, 0));
    EXPECT_EQ(d->radii, std::vector<float>(4, 0.25f));
    bool named = false;
    for (const std::string& w : p.warnings)
        named = named || (w.starts_with("/C: ") && w.find("curve 0 has 5 vertices") != std::string::npos);
    EXPECT_TRUE(named);
}

TEST(CurvesAdapter, ColoursNormalsStyleAndTransform) {
    auto p = populate(R"(def Xform "X"
{
    double3 xformOp:scale = (2, 2, 2)
    uniform token[] xformOpOrder = ["xformOp:scale"]
    def BasisCurves "Ribbon"
    {
        uniform token type = "linear"
        int[] curveVertexCounts = [2]
        point3f[] points = [(0, 0, 0), (1, 0, 0)]
        float[] widths = [0.1] (interpolation = "constant")
        normal3f[] normals = [(0, 0, 1), (0, 1, 0)]
        color3f[] primvars:displayColor = [(1, 0, 0), (0, 0, 1)] (interpolation = "vertex")
    }
    def BasisCurves "Flat"
    {
        uniform token type = "linear"
        int[] curveVertexCounts = [2]
        point3f[] points = [(0, 0, 0), (1, 0, 0)]
        normal3f[] normals = [(0, 0, 1), (0, 1, 0)]
        token primvars:fluence:curveStyle = "flat"
    }
}
)");
    const render::CurvesDesc* ribbon = curvesNamed(p, "/X/Ribbon");
    ASSERT_NE(ribbon, nullptr);
    EXPECT_EQ(ribbon->style, render::CurveStyle::Oriented);
    EXPECT_EQ(ribbon->normals.size(), 2u);
    EXPECT_EQ(ribbon->colors, (std::vector<RGB>{RGB(1, 0, 0), RGB(0, 0, 1)}));
    EXPECT_EQ(ribbon->points[1], Vec3f(2, 0, 0)) << "world space";
    EXPECT_FLOAT_EQ(ribbon->radii[0], 0.1f) << "half the width, times the scale";
    const render::CurvesDesc* flat = curvesNamed(p, "/X/Flat");
    ASSERT_NE(flat, nullptr);
    EXPECT_EQ(flat->style, render::CurveStyle::Flat);
}

TEST(CurvesAdapter, NurbsCurvesAreEvaluatedThroughTheirEnds) {
    // A quadratic NURBS arc: three points, weights (1, sqrt(1/2), 1) over knots (0 0 0 1 1 1) make
    // a quarter circle of radius 1, which every evaluated point lies on.
    auto p = populate(R"(def NurbsCurves "Arc"
{
    int[] curveVertexCounts = [3]
    int[] order = [3]
    double[] knots = [0, 0, 0, 1, 1, 1]
    double[] pointWeights = [1, 0.70710678, 1]
    point3f[] points = [(1, 0, 0), (1, 1, 0), (0, 1, 0)]
    float[] widths = [0.05] (interpolation = "constant")
}
)");
    const render::CurvesDesc* arc = curvesNamed(p, "/Arc");
    ASSERT_NE(arc, nullptr);
    EXPECT_EQ(arc->basis, render::CurveBasis::CatmullRom);
    ASSERT_GE(arc->points.size(), 10u);
    for (std::size_t i = 1; i + 1 < arc->points.size(); ++i) EXPECT_NEAR(length(arc->points[i]), 1.0f, 1e-5f) << i;
    EXPECT_NEAR(arc->points[1].x, 1.0f, 1e-6f) << "starts at its first point";
    EXPECT_NEAR(arc->points[arc->points.size() - 2].y, 1.0f, 1e-6f) << "ends at its last";
    auto bad = populate(R"(def NurbsCurves "Bad"
{
    int[] curveVertexCounts = [3]
    int[] order = [3]
    double[] knots = [0, 0, 1, 1]
    point3f[] points = [(1, 0, 0), (1, 1, 0), (0, 1, 0)]
}
)");
    EXPECT_EQ(curvesNamed(bad, "/Bad"), nullptr);
}

TEST(CurvesAdapter, PublicScenesNoLongerDropCurves) {
    // Every .usda of the shared corpus that defines BasisCurves or NurbsCurves: none of those prims
    // is reported as unsupported, and the scene describes curves.
    const std::filesystem::path corpus = test::sharedPath("usd_corpus");
    FLUENCE_REQUIRE_SHARED(corpus);
    int files = 0, withCurves = 0;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(corpus)) {
        if (entry.path().extension() != ".usda") continue;
        std::ifstream in(entry.path());
        std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        if (text.find("def BasisCurves") == std::string::npos && text.find("def NurbsCurves") == std::string::npos)
            continue;
        ++files;
        std::unique_ptr<usd::Stage> stage;
        try {
            stage = usd::Stage::open(entry.path().string());
        } catch (const std::exception&) {
            continue;  // a layer this reader refuses is another test's business
        }
        std::vector<std::string> warnings;
        DelegateOptions options;
        options.allowMissing = true;
        options.convertColor = [](const RGB& c, const std::string&) { return c; };
        options.warn = [&](const std::string& path, const std::string& message) {
            warnings.push_back(path + ": " + message);
        };
        DelegateResult result;
        try {
            result = populateScene(*stage, options);
        } catch (const std::exception&) {
            continue;
        }
        for (const std::string& w : warnings) {
            EXPECT_EQ(w.find("'BasisCurves' is not supported"), std::string::npos) << entry.path() << ": " << w;
            EXPECT_EQ(w.find("'NurbsCurves' is not supported"), std::string::npos) << entry.path() << ": " << w;
        }
        withCurves += result.scene.curves.empty() ? 0 : 1;
    }
    std::printf("[ measured ] %d corpus files define curves; %d describe curves\n", files, withCurves);
    EXPECT_GT(withCurves, 0);
}

}  // namespace
}  // namespace fluence::delegate
