// The render core's input: a scene in plain, USD-free structs, in world space.
//
// The delegate fills one from a USD stage; a unit test can fill one in ten lines. Units are the
// scene's own (whatever metersPerUnit says); colours are already in the rendering space
// (linear Rec.709); light quantities are already in radiance (UsdLux intensity, exposure,
// colour and colour temperature folded in; normalize is applied by the render core, which knows
// the lights' world-space areas).
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/matrix.h"
#include "core/rgb.h"
#include "render/curves_description.h"
#include "render/dome_light_sampling.h"
#include "render/light_links.h"
#include "media/medium.h"
#include "render/points_description.h"
#include "texture/ies_file.h"
#include "texture/texture_types.h"
#include "volumes/grid_medium_params.h"

namespace fluence::render {

// How light that enters a subsurface material finds where it leaves: by a random walk in the
// object's interior medium (unbiased; MaterialDesc::interior), or by the normalized diffusion
// profile of a flat, semi-infinite medium, sampled with probe rays (fast, approximate:
// integrators/diffusion_probe.h). RandomWalkGuided walks too, with steps guided towards the
// surface and combined with the classic ones by MIS (media/guided_walk.h): the same image, with
// less noise for its CPU time; the delegate gives it to every material that does not name a
// method (a MaterialDesc built in C++ keeps the classic walk unless it asks).
enum class SubsurfaceMethod { RandomWalk, Diffusion, RandomWalkGuided };

// A surface material's parameters at one surface point: one layered "principled" parameter set
// that both UsdPreviewSurface and MaterialX Standard Surface map onto (delegate/surface_shaders.h
// gives the mapping). From the bottom up (render/material_bsdf.h has the exact stack): a diffuse
// base; a sheen over it; a dielectric specular lobe over that (Fresnel from `ior`, tinted by
// `specularColor`, weighted by `specular`) or, with `specularWorkflow`, a specular lobe whose
// normal-incidence reflectance is `specularColor` itself; glass in place of the diffuse by weight
// `transmission`; a metal (weight `metallic`, normal-incidence reflectance `diffuse`); a clear
// coat on top; emission. Colours are linear, in the rendering space; roughness values are
// perceptual (alpha = roughness^2). render/material_bsdf.h turns them into a BSDF.
struct MaterialParams {
    RGB diffuse{0.18f};
    float diffuseRoughness = 0.0f;  // Oren-Nayar sigma-like roughness, 0 = Lambertian
    float specular = 1.0f;          // weight of the dielectric specular lobe
    RGB specularColor{1.0f};
    bool specularWorkflow = false;  // UsdPreviewSurface useSpecularWorkflow: specularColor is F0
    float roughness = 0.5f;
    float anisotropy = 0.0f;
    float ior = 1.5f;
    float metallic = 0.0f;
    float transmission = 0.0f;
    RGB transmissionColor{1.0f};
    float sheen = 0.0f;
    RGB sheenColor{1.0f};
    float sheenRoughness = 0.3f;
    float coat = 0.0f;
    RGB coatColor{1.0f};
    float coatRoughness = 0.01f;
    float coatIor = 1.5f;
    RGB emission{0.0f};             // emitted radiance, both sides
    float opacity = 1.0f;           // < 1: partly transparent (light passes straight through)
    float opacityThreshold = 0.0f;  // > 0: a cut-out mask (opacity below it is fully transparent)
    bool thinWalled = false;
    // Subsurface scattering (Standard Surface): the weight of the subsurface lobe, the colour it
    // shows, its mean free path (radius x scale), and how light travels under the surface.
    float subsurface = 0.0f;
    RGB subsurfaceColor{1.0f};
    RGB subsurfaceRadius{1.0f};
    float subsurfaceScale = 1.0f;
    SubsurfaceMethod subsurfaceMethod = SubsurfaceMethod::RandomWalk;
    // UsdPreviewSurface displacement along the normal, in object units. Geometry, not shading:
    // the delegate applies it when it dices a mesh (delegate/displacement.h); the render core
    // ignores it.
    float displacement = 0.0f;
    // Set on a curve's hits: the material is the hair BSDF (render/bsdfs/hair.h) with these
    // parameters, derived from the rest by render/hair_material.h; the lobes above are not used.
    std::optional<HairParams> hair;
};

// The parameters of a plain Lambertian surface (every other lobe off): the material of a mesh
// that has none.
inline MaterialParams lambertianParams(const RGB& albedo) {
    MaterialParams p;
    p.diffuse = albedo;
    p.specular = 0.0f;
    return p;
}

// The parameters a shading network can drive per surface point.
enum class MaterialInput {
    Diffuse,
    Emission,
    SpecularColor,
    Specular,
    Metallic,
    Roughness,
    Ior,
    Coat,
    CoatColor,
    CoatRoughness,
    Transmission,
    TransmissionColor,
    Sheen,
    SheenColor,
    Opacity,
    Normal,  // a tangent-space normal in [-1, 1]^3 (after the texture's scale and bias): perturbs the shading normal
    Displacement,  // geometry: only in MaterialDesc::displacementBinding, evaluated by the delegate when it dices
};

// UsdTransform2d: st' = rotate(st * scale) + translation, rotation counter-clockwise in degrees.
struct UvTransform {
    float scale[2] = {1.0f, 1.0f};
    float rotationDegrees = 0.0f;
    float translation[2] = {0.0f, 0.0f};
};

// A UsdUVTexture node and the texture coordinates it reads (a UsdPrimvarReader_float2, through
// an optional UsdTransform2d). Its value at a point is texel * scale + bias, per RGBA channel;
// `fallback` where the file cannot be read.
struct TextureDesc {
    std::string file;  // resolved path; may hold the UDIM tag <UDIM>
    // The delegate found no such file (and said so): the fallback is used without trying it.
    bool missing = false;
    texture::Wrap wrapS = texture::Wrap::Repeat, wrapT = texture::Wrap::Repeat;
    float fallback[4] = {0.0f, 0.0f, 0.0f, 1.0f};
    float scale[4] = {1.0f, 1.0f, 1.0f, 1.0f};
    float bias[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    texture::SourceColorSpace colorSpace = texture::SourceColorSpace::Auto;
    std::string colorSpaceName;    // a colour space of the OCIO config (MaterialX colorspace); overrides colorSpace
    std::string uvPrimvar = "st";  // the reader's varname; "" = no reader (uvFallback everywhere)
    float uvFallback[2] = {0.0f, 0.0f};  // where the mesh has no such primvar
    UvTransform uvTransform;
    texture::Filter filter = texture::Filter::Linear;  // within a mip level (MaterialX filtertype)
};

// One node of a binding's shading graph (MaterialX multiply and mix over images and constants,
// delegate/shading_network.h). Every node's value has four channels; a one-channel value is
// replicated into all four. Operands name earlier nodes of the same graph.
struct ShadingNode {
    enum class Op {
        Constant,  // `constant`
        Source,    // InputBinding::sources[source] at the point
        Multiply,  // operands[0] * operands[1], per channel
        Mix,       // operands[1] * (1 - operands[2]) + operands[0] * operands[2], per channel (fg, bg, mix)
    };
    Op op = Op::Constant;
    float constant[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    int source = -1;
    int operands[3] = {-1, -1, -1};
};

// The most nodes one binding's graph may hold (its values live on the stack while it is evaluated).
inline constexpr std::size_t kMaxShadingNodes = 64;

// One material input driven by a node: a texture's output, or a primvar read directly
// (UsdPrimvarReader_float / _float3). Channels [firstChannel, firstChannel + channels) of the
// source feed the input; one channel feeding a colour is replicated.
// Or driven by a graph: when `nodes` is not empty the value is its last node's (channels from
// 0), and the texture and primvar above are unused: the graph's leaves are `sources`, bindings
// of their own (each a texture or primvar, its channels and factor; their `input` unused).
struct InputBinding {
    MaterialInput input = MaterialInput::Diffuse;
    int firstChannel = 0;  // r 0, g 1, b 2, a 3, rgb 0
    int channels = 3;      // 1 or 3
    std::optional<TextureDesc> texture;
    float factor = 1.0f;  // the value is multiplied by it (Standard Surface: base for base_color)
    std::string primvar;  // when there is no texture
    float primvarFallback[3] = {0.0f, 0.0f, 0.0f};  // where the mesh has no such primvar
    std::vector<ShadingNode> nodes;                 // at most kMaxShadingNodes
    std::vector<InputBinding> sources;
};

// Calls `f` on every texture or primvar a binding reads: itself, or its graph's sources.
template <typename F>
void forEachSource(const InputBinding& b, F&& f) {
    if (b.nodes.empty())
        f(b);
    else
        for (const InputBinding& s : b.sources) f(s);
}

// A surface material as the render core takes it: its parameters where nothing drives them, the
// inputs that textures or primvars drive, and the name for messages.
// `interior`: the homogeneous medium that fills a closed mesh with this material (glass tinted
// through its depth, a murky liquid; media/medium.h units, per scene unit of length). Rays that
// cross the surface against its geometric normal enter it, and leave it crossing back
// (integrators/medium_stack.h); only surfaces that let light through (transmission) are crossed.
struct MaterialDesc : MaterialParams {
    std::string name;  // prim path, for messages
    std::vector<InputBinding> bindings;
    std::optional<media::MediumProperties> interior;
    // What drives `displacement` per surface point (a texture's channel, with its scale and bias),
    // kept out of `bindings`: the delegate evaluates it when it dices, the render core never does.
    std::optional<InputBinding> displacementBinding;
};

// A mesh primvar the render core interpolates for a material: `components` floats per triangle
// corner (3 corners per triangle), whatever the primvar's USD interpolation was.
struct CornerPrimvar {
    std::string name;
    int components = 2;
    std::vector<float> values;  // triangles * 3 * components
};

// UsdLuxShapingAPI: the emission narrowed around the light's local -Z axis (render/light_shaping.h).
struct LightShapingDesc {
    float coneAngleDegrees = 90.0f;  // no light leaves further than this from the axis
    float coneSoftness = 0.0f;       // 0: hard edge; 1: fades from the axis to the cone's edge
    float focus = 0.0f;              // off-axis cosine power
    RGB focusTint{0.0f};             // what the focus fades towards off the axis
    // inputs:shaping:ies:file read by texture::readIesFile (null: none), and how it is applied
    // (render/ies_profile.h).
    std::shared_ptr<const texture::IesTable> ies;
    float iesAngleScale = 0.0f;
    bool iesNormalize = false;
};

// UsdLuxMeshLightAPI on a mesh (delegate/mesh_light.h): the mesh is an area light that emits
// `radiance` from the front of each triangle (the side cross(p1 - p0, p2 - p0) points to), as a
// RectLight emits from its front, in place of its material's emission; sampled like any emissive
// mesh, triangle by triangle, by the light tree. The radiance already holds UsdLux's intensity,
// exposure, colour, colour temperature, the material's glow tint (materialSyncMode) and, when
// normalized, the division by the world area of the whole prim (which may be split into several
// MeshDescs by its subsets, so the delegate divides).
struct MeshLightDesc {
    RGB radiance{1.0f};
    // materialSyncMode noMaterialResponse: false, the surface reflects and transmits nothing.
    bool materialResponse = true;
    // The prim that applies MeshLightAPI (a part of one GeomSubset is named by the subset): what
    // the delegate reads its light and shadow links from. The render core does not read it.
    std::string prim{};
    // Its number among the scene's linked mesh lights (render/light_links.h), shared by every part
    // and instance of the prim; -1: its links hold everything.
    int linkId = -1;
    // UsdLuxShapingAPI on the prim: each triangle's emission shaped about its front normal
    // (render/lights/triangle_light.h), an IES profile's azimuth from `lightToWorld`'s X and Y (the
    // prim's local axes, in the mesh's space: transformMesh moves them with it).
    std::optional<LightShapingDesc> shaping{};
    Matrix4 lightToWorld = Matrix4::identity();
    // `radiance` is divided by its prim's area (inputs:normalize) in the mesh's own space: a copy
    // that an instance places is divided by its placed area instead (RenderScene), part by part.
    bool normalized = false;
    // Which copy of the prim a prototype's part belongs to (nested point instancers place a prim
    // several times, possibly in one place): the delegate's, as `prim`; the render core does not read it.
    int copy = 0;
};

struct MeshDesc {
    std::string name;                     // prim path, for messages
    std::vector<Vec3f> positions;         // world space (prototype space in a PrototypeDesc)
    std::vector<std::uint32_t> indices;   // 3 per triangle
    std::vector<Vec3f> cornerNormals;     // empty, or 3 per triangle (world space, shading)
    std::vector<RGB> cornerColors;        // empty, or 3 per triangle: diffuse colour (displayColor)
    int material = -1;                    // index into SceneDescription::materials, -1 = default
    std::vector<CornerPrimvar> primvars;  // those the mesh's material reads (st, ...)
    // Deformation blur: the positions at evenly spaced times over the shutter, the first at its
    // opening and the last at its close (render/motion_geometry.h), each indexed like `positions`;
    // empty: the mesh does not move while the shutter is open. `positions` stays the frame's.
    std::vector<std::vector<Vec3f>> motionPositions{};
    int linkGroup = 0;                     // its light and shadow links (render/light_links.h); 0: every light
    std::optional<MeshLightDesc> light{};  // a UsdLux mesh light; none: it emits its material's emission
};

enum class LightType { Rect, Disk, Sphere, Cylinder, Distant, Dome };

// An RGB image in the rendering space, row-major, top row first (as image files store rows).
struct RgbImage {
    int width = 0, height = 0;
    std::vector<RGB> texels;

    const RGB& at(int x, int y) const { return texels[std::size_t(y) * width + x]; }
};

struct LightDesc {
    std::string name;  // prim path
    LightType type = LightType::Rect;
    Matrix4 transform = Matrix4::identity();  // light-to-world; lights emit along local -Z
    // intensity * 2^exposure * colour (* the colour temperature's tint). Rect, Disk, Sphere and
    // Cylinder: emitted radiance, divided by the light's world-space area when `normalize`.
    // Distant: radiance of the sun disk, or, when normalized or angleDegrees == 0, the irradiance
    // on a surface facing the light. Dome: radiance (multiplying the texture, when there is one).
    RGB radiance{1.0f};
    bool normalize = false;
    float width = 1.0f, height = 1.0f;  // Rect, local units (before transform)
    float radius = 0.5f;                // Disk, Sphere, Cylinder, local units
    float length = 1.0f;                // Cylinder, along local X
    float angleDegrees = 0.0f;          // Distant: angular diameter
    bool treatAsPoint = false;          // Sphere: render as a point light of the same power
    bool treatAsLine = false;           // Cylinder: render as a line light of the same power
    // Rect: emission texture (its top-left texel at local (+X, +Y)); Dome: lat-long environment.
    // Null: the constant radiance.
    std::shared_ptr<const RgbImage> texture;
    std::optional<LightShapingDesc> shaping;  // Rect, Disk, Sphere, Cylinder
    // Dome: whether a camera ray that leaves the scene sees it (false: the background is black with
    // alpha 0, while the dome still lights the scene and shows in reflections).
    bool visibleToCamera = true;
    // UsdLux ShadowAPI inputs:shadow:enable: false, and no surface blocks this light's shadow rays
    // (render/shadow_rays.cpp).
    bool castsShadows = true;
    // A moving light: light-to-world at evenly spaced times over the shutter, as
    // InstanceDesc::motionTransforms (render/light_motion.h); empty: it stays at `transform`.
    std::vector<Matrix4> motionTransforms{};
};

// One grid of an OpenVDB file (a UsdVol OpenVDBAsset).
struct VolumeFieldDesc {
    std::string file;      // resolved path
    std::string gridName;  // fieldName
    int gridIndex = -1;    // fieldIndex among grids of that name, -1 = the first
};

// A UsdVol Volume as the render core takes it: its grids and the parameters of its volume
// material (delegate/volume_adapter.h gives the mapping and the fallbacks). Extinction is
// density * densityScale per scene unit; of it, the fraction `albedo` (times the colour grid,
// when there is one) scatters, with Henyey-Greenstein anisotropy, and the rest absorbs. The
// emitted radiance Le (per unit of absorption, as media/medium.h defines it) is emissionColor *
// emissionScale plus, when blackbodyIntensity > 0, the blackbody radiance of temperature *
// temperatureScale + temperatureOffset kelvin times blackbodyIntensity (volumes/grid_medium.h).
struct VolumeDesc {
    std::string name;                         // prim path
    Matrix4 transform = Matrix4::identity();  // volume-to-world (the grids' own transforms apply first)
    std::optional<VolumeFieldDesc> density, temperature, color;
    volumes::GridMediumParams params;  // the material's parameters
};

enum class Projection { Perspective, Orthographic };

// USD camera semantics: focal length and apertures in the same unit (tenths of a scene unit by
// USD convention; only their ratios matter for perspective), camera looks along local -Z with +Y
// up, clipping range in scene units.
// UsdGeomCamera's lens at one motion step (CameraDesc::motionLenses).
struct CameraLensStep {
    float focalLength = 50.0f, fStop = 0.0f, focusDistance = 0.0f;
};

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
    // Depth of field (render/thin_lens.h): UsdGeomCamera's fStop (0: a pinhole) and focusDistance
    // (scene units; 0: a pinhole), and Fluence's fluence:camera:apertureBlades (0: round) and
    // fluence:camera:apertureRotation (degrees).
    float fStop = 0.0f, focusDistance = 0.0f;
    int apertureBlades = 0;
    float apertureRotation = 0.0f;
    // UsdGeomCamera shutter:open and shutter:close, in time codes relative to the frame; equal:
    // no motion blur. The render core only needs to know that a ray's time 0 is the opening and
    // 1 the close (render::Ray::time); the delegate samples the motion over this interval.
    double shutterOpen = 0.0, shutterClose = 0.0;
    // A moving camera: camera-to-world at evenly spaced times over the shutter (the first at its
    // opening, the last at its close; interpolated as render/camera_motion.h says); empty: it
    // stays at `transform`, the frame's.
    std::vector<Matrix4> motionTransforms{};
    // A zoom or a focus pull: focalLength, fStop and focusDistance at the same evenly spaced times
    // (each linear between steps, as USD interpolates them); empty: the frame's at every time.
    std::vector<CameraLensStep> motionLenses{};
};

// Geometry shared by instances: its meshes, curves and points in the prototype's own space,
// stored once.
struct PrototypeDesc {
    std::string name;                  // the prim it was read from, for messages
    std::vector<MeshDesc> meshes;      // prototype space
    std::vector<CurvesDesc> curves{};  // prototype space
    std::vector<PointsDesc> points{};  // prototype space
};

// One placement of a prototype.
struct InstanceDesc {
    int prototype = 0;                        // index into SceneDescription::prototypes
    Matrix4 transform = Matrix4::identity();  // prototype-to-world
    // What names its hits: the instance prim's path, or a PointInstancer's path and the instance's
    // id, "/World/trees[12]" ("": unnamed).
    std::string name;
    // Transformation blur: prototype-to-world at evenly spaced times over the shutter, as
    // MeshDesc::motionPositions; empty: the instance does not move. `transform` stays the frame's.
    std::vector<Matrix4> motionTransforms{};
    // Its light and shadow links (render/light_links.h), for every mesh of its prototype; 0: those
    // of the prototype's meshes.
    int linkGroup = 0;
};

struct SceneDescription {
    std::vector<MaterialDesc> materials;
    std::vector<MeshDesc> meshes;    // world space
    std::vector<CurvesDesc> curves;  // world space
    std::vector<PointsDesc> points;  // world space (render/points_description.h)
    std::vector<PrototypeDesc> prototypes;
    std::vector<InstanceDesc> instances;
    std::vector<LightDesc> lights;
    std::vector<VolumeDesc> volumes;
    std::optional<CameraDesc> camera;
    std::vector<LightLinkGroup> lightLinkGroups;  // group g > 0 of render/light_links.h is [g - 1]
    // Light groups (delegate/light_groups.h): the prim path of a light or emissive mesh -> the label
    // its event carries in light path expressions instead of its prim's name.
    std::map<std::string, std::string> lightGroups;
    // Whether next-event estimation samples a dome of constant radiance (render/dome_light_sampling.h).
    DomeLightSampling domeLightSampling = DomeLightSampling::Auto;
};

}  // namespace fluence::render
