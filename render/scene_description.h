// The render core's input: a scene in plain, USD-free structs, in world space.
//
// The delegate fills one from a USD stage; a unit test can fill one in ten lines. Units are the
// scene's own (whatever metersPerUnit says); colours are already in the rendering space
// (linear Rec.709); light quantities are already in radiance (UsdLux intensity, exposure,
// colour and normalize folded in).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/matrix.h"
#include "core/rgb.h"

namespace fluence::render {

// A UsdPreviewSurface reduced to what this slice renders: Lambertian diffuse plus emission.
struct MaterialDesc {
    std::string name;  // prim path, for messages
    RGB diffuse{0.18f};
    RGB emission{0.0f};  // emitted radiance, both sides
    // UsdPreviewSurface displacement along the normal, in object units. Geometry, not shading:
    // the delegate applies it when it tessellates a subdivision surface; the render core ignores it.
    float displacement = 0.0f;
};

struct MeshDesc {
    std::string name;                     // prim path, for messages
    std::vector<Vec3f> positions;         // world space (prototype space in a PrototypeDesc)
    std::vector<std::uint32_t> indices;   // 3 per triangle
    std::vector<Vec3f> cornerNormals;     // empty, or 3 per triangle (world space, shading)
    std::vector<RGB> cornerColors;        // empty, or 3 per triangle: diffuse colour (displayColor)
    int material = -1;                    // index into SceneDescription::materials, -1 = default
};

enum class LightType { Rect, Sphere, Distant, Dome };

struct LightDesc {
    std::string name;          // prim path
    LightType type = LightType::Rect;
    Matrix4 transform = Matrix4::identity();  // light-to-world; lights emit along local -Z
    // intensity * 2^exposure * colour. Rect and Sphere: emitted radiance, divided by the light's
    // world-space area when `normalize`. Distant: radiance of the sun disk, or, when normalized
    // or angleDegrees == 0, the irradiance on a surface facing the light. Dome: radiance.
    RGB radiance{1.0f};
    bool normalize = false;
    float width = 1.0f, height = 1.0f;  // Rect, local units (before transform)
    float radius = 0.5f;                // Sphere, local units
    float angleDegrees = 0.0f;          // Distant: angular diameter
};

enum class Projection { Perspective, Orthographic };

// USD camera semantics: focal length and apertures in the same unit (tenths of a scene unit by
// USD convention; only their ratios matter for perspective), camera looks along local -Z with +Y
// up, clipping range in scene units.
struct CameraDesc {
    std::string name;
    Matrix4 transform = Matrix4::identity();  // camera-to-world
    Projection projection = Projection::Perspective;
    float focalLength = 50.0f;
    float horizontalAperture = 20.955f;
    float verticalAperture = 15.2908f;
    float horizontalApertureOffset = 0.0f;
    float verticalApertureOffset = 0.0f;
    float nearClip = 1.0f, farClip = 1000000.0f;
};

// Geometry shared by instances: its meshes in the prototype's own space, stored once.
struct PrototypeDesc {
    std::string name;              // the prim it was read from, for messages
    std::vector<MeshDesc> meshes;  // prototype space
};

// One placement of a prototype.
struct InstanceDesc {
    int prototype = 0;                         // index into SceneDescription::prototypes
    Matrix4 transform = Matrix4::identity();  // prototype-to-world
};

struct SceneDescription {
    std::vector<MaterialDesc> materials;
    std::vector<MeshDesc> meshes;  // world space
    std::vector<PrototypeDesc> prototypes;
    std::vector<InstanceDesc> instances;
    std::vector<LightDesc> lights;
    std::optional<CameraDesc> camera;
};

}  // namespace fluence::render
