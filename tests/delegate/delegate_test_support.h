// Shared by the delegate tests: a stage from USDA text, populated with identity colour conversion
// and the warnings collected; and measurements of tessellated meshes.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "delegate/scene_delegate.h"
#include "scene/usda_parser.h"

namespace fluence::delegate::testing {

struct Populated {
    std::unique_ptr<usd::Stage> stage;
    DelegateResult result;
    std::vector<std::string> warnings;

    // The mesh named `name` (the first one), or nullptr.
    const render::MeshDesc* mesh(const std::string& name) const {
        for (const auto& m : result.scene.meshes)
            if (m.name == name) return &m;
        return nullptr;
    }
};

inline const std::string kCamera = "def Camera \"Cam\"\n{\n}\n";

// A unit quad /Quad bound to /Looks/M, whose body is `material`; `meshLines` adds to the mesh.
inline std::string quadBoundTo(const std::string& material, const std::string& meshLines = "") {
    return R"(
def Mesh "Quad"
{
    uniform token subdivisionScheme = "none"
    int[] faceVertexCounts = [4]
    int[] faceVertexIndices = [0, 1, 2, 3]
    point3f[] points = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)]
    rel material:binding = </Looks/M>
)" + meshLines +
           R"(
}
def Scope "Looks"
{
    def Material "M"
    {
)" + material +
           R"(
    }
}
)";
}

// A Shader "Tex" of /Looks/M: a UsdUVTexture reading `file` as raw data at the st of the
// Shader "St" beside it.
inline std::string rawTextureAtSt(const std::string& file) {
    return R"(
        def Shader "Tex"
        {
            uniform token info:id = "UsdUVTexture"
            asset inputs:file = @)" +
           file + R"(@
            token inputs:sourceColorSpace = "raw"
            float2 inputs:st.connect = </Looks/M/St.outputs:result>
            float3 outputs:rgb
        }
)";
}

inline std::unique_ptr<usd::Stage> stageFrom(const std::string& usda) {
    return std::make_unique<usd::Stage>(
        usd::parseUsdaString(usda.starts_with("#") ? usda : "#usda 1.0\n" + usda, "test.usda"));
}

// The options the tests populate with: colours kept as authored, warnings collected in `p`.
inline DelegateOptions testOptions(Populated& p) {
    DelegateOptions options;
    options.convertColor = [](const RGB& c, const std::string&) { return c; };
    options.warn = [&p](const std::string& path, const std::string& message) {
        p.warnings.push_back(path + ": " + message);
    };
    return options;
}

// Populates `usda` (a Camera is added unless the text starts with "#usda"), rendering through
// `cameraPath` when given; `strict`: DelegateOptions::strict (a malformed prim raises SceneError).
inline Populated populateWith(const std::string& usda, const std::string& cameraPath, bool strict) {
    Populated p;
    p.stage = stageFrom(usda.starts_with("#") ? usda : kCamera + usda);
    DelegateOptions options = testOptions(p);
    options.cameraPath = cameraPath;
    options.strict = strict;
    p.result = populateScene(*p.stage, options);
    return p;
}

// As `fluence render` does: a malformed prim is skipped with a warning.
inline Populated populate(const std::string& usda, const std::string& cameraPath = "") {
    return populateWith(usda, cameraPath, false);
}
// As `fluence render --strict` does: a malformed prim raises SceneError.
inline Populated populateStrict(const std::string& usda) { return populateWith(usda, "", true); }

inline Vec3d corner(const render::MeshDesc& m, std::size_t c) { return Vec3d(m.positions[m.indices[c]]); }

inline Vec3d triangleCross(const render::MeshDesc& m, std::size_t t) {
    Vec3d a = corner(m, 3 * t), b = corner(m, 3 * t + 1), c = corner(m, 3 * t + 2);
    return cross(b - a, c - a);
}

inline double surfaceArea(const render::MeshDesc& m) {
    double area = 0.0;
    for (std::size_t t = 0; t < m.indices.size() / 3; ++t) area += 0.5 * length(triangleCross(m, t));
    return area;
}

// Signed enclosed volume (divergence theorem), positive when the triangles wind outwards.
inline double enclosedVolume(const render::MeshDesc& m) {
    double volume = 0.0;
    for (std::size_t t = 0; t < m.indices.size() / 3; ++t)
        volume += dot(corner(m, 3 * t), cross(corner(m, 3 * t + 1), corner(m, 3 * t + 2))) / 6.0;
    return volume;
}

}  // namespace fluence::delegate::testing
