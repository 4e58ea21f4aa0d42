// The render scene: geometry in Embree 3, materials and lights, ready for the integrators.
//
// Built once from a SceneDescription (the Embree scenes are committed at the end of the
// constructor and never edited while rendering). Two top-level Embree scenes are kept: the
// surfaces (meshes, instances, Embree's native curves for BasisCurves and NurbsCurves,
// render/curve_geometry.h, and Embree's points for UsdGeomPoints, render/point_geometry.h) and the
// light shapes (rect lights as two triangles, sphere
// lights as an Embree sphere, disk and cylinder lights as user geometry intersected exactly;
// point, line and infinite lights have no shape). Camera and BSDF rays look in both (in the light
// shapes only when the ray's segment up to the surface hit meets their bounds: most rays skip that
// second Embree call); shadow rays look only at surfaces, so light shapes cast no shadows.
//
// Light selection for next-event estimation: chooseLight(p, n, u) walks the light tree
// (render/light_tree.h), which favours the lights that can give the point p with normal n the
// most light, in O(log N) per choice; lightProbability(p, n, light) is the probability of that
// same choice, for the MIS weight of emission reached by BSDF sampling. The path tracer uses these;
// lightSelection(), the older choice proportional to power alone, remains as the baseline the
// many-lights benchmark compares the tree against, and chooses the lights sppm's photons leave.
// Under SceneDescription::domeLightSampling auto (the default) chooseLight never returns a light
// of constant radiance (Light::constantRadiance: an untextured dome) whose light passes no surface
// (lightPassesSurfaces) and lightProbability gives it 0, so every method that weighs BSDF-sampled light against next-event estimation through them
// gathers it by BSDF and phase sampling alone (render/dome_light_sampling.h); lightSelection()
// keeps every light.
//
// Instancing: each prototype is one Embree scene (its meshes, curves and points), built once, and
// each instance an Embree instance of it (one level), so N instances of a mesh cost its triangles
// once plus one transform each. A hit inside an instance is shaded in prototype space and moved to
// world space (a curve's with the ray taken into prototype space).
// Emissive prototype meshes are the exception: every emitting triangle is a light that next-event
// estimation samples in world space, so they are copied into world space per instance.
//
// Materials: each is a MaterialShader (render/material_shader.h) evaluated at every surface hit,
// textures looked up through one texture::TextureSystem with the pixel footprint of the camera
// given to setTextureFilterCamera() (without one, textures are point-sampled at full resolution).
// Volumes: each VolumeDesc becomes a volumes::GridMedium (its OpenVDB grids, read once per file);
// together they are one media::MediumUnion, which rays cross between surfaces. A grid that
// cannot be read raises std::invalid_argument naming the volume, the file and the grid. A
// material with an interior (MaterialDesc::interior) fills its closed meshes with a
// media::HomogeneousMedium; inside one, rays cross it and the volumes together (mediumInside).
//
// Motion blur: a mesh with MeshDesc::motionPositions and an instance with motionTransforms get
// Embree time steps (render/motion_geometry.h); rays are intersected at Ray::time and hits shaded
// where the geometry is at that time. Lights move too (lightAt): a light with
// LightDesc::motionTransforms (render/light_motion.h), its shape a render/moving_light_shape.h,
// and the triangles of a moving emissive mesh (world meshes, and emissive prototype meshes copied
// per instance, with the instance's motion); the light tree bounds each over the whole shutter
// (render/lights/swept_light.h).
//
// Opacity: a mesh whose material may be less than opaque gets Embree filter functions, so every
// ray (camera, BSDF and shadow) passes through its holes. A cut-out (opacityThreshold > 0) is a
// hole or not; partial opacity lets a ray through with probability 1 - opacity, decided by a hash
// of the ray and the triangle (deterministic, whatever the thread count, and unbiased over rays).
#pragma once

#include <deque>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/name_table.h"
#include "core/sampling.h"
#include "render/camera.h"
#include "render/curve_geometry.h"
#include "render/light.h"
#include "render/light_at_time.h"
#include "render/light_motion.h"
#include "render/light_links.h"
#include "render/light_tree.h"
#include "render/material_shader.h"
#include "render/material_tables.h"
#include "render/moving_light_shape.h"
#include "render/ray.h"
#include "media/medium.h"
#include "render/scene_description.h"
#include "texture/texture_system.h"

struct RTCGeometryTy;  // Embree's geometry handle (embree3/rtcore_geometry.h)
struct RTCSceneTy;     // Embree's scene handle (embree3/rtcore_scene.h)

namespace fluence::render {

struct MeshPresence;  // what the presence filter of a mesh with holes reads (render_scene.cpp)

// What a ray hit, with everything shading needs.
struct SurfaceHit {
    // User-provided, so that value-initialisation (std::optional's in-place construction) does not
    // zero the whole record before the member initialisers below run: that zeroing showed in profiles.
    SurfaceHit() {}
    // Starts from the given material parameters (copied once, with no default written before).
    explicit SurfaceHit(const MaterialParams& params) : material(params) {}

    float t = 0.0f;
    float time = 0.0f;  // the ray's time in the shutter interval (render::Ray::time): rays leaving the hit keep it
    Vec3f point;
    Vec3f geometricNormal;  // unit; on the same side as shadingNormal
    Vec3f shadingNormal;    // unit
    // Unit, perpendicular to shadingNormal, along the direction in which the texture coordinate s
    // (the first UV primvar a material reads) grows; zero where the surface has no UVs. Anisotropic
    // lobes align their x axis with it.
    Vec3f tangent{0.0f};
    // Where on a mesh the hit is, for RenderScene::primvarAt: the mesh, its triangle and the
    // barycentric weights of the triangle's second and third corners (mesh -1: a light shape).
    int mesh = -1;
    int instance = -1;  // the instance placing the mesh, -1 for a world mesh (RenderScene's own numbering)
    unsigned triangle = 0;
    float b1 = 0.0f, b2 = 0.0f;
    // A hit on curves: their Embree geometry (triangle is then the segment, b1 the curve parameter
    // along it); -1 otherwise.
    int curveGeometry = -1;
    // The material's parameters at this point (a mesh without a material: Lambertian, its
    // displayColor or 18% grey; light shapes: black). material.diffuse is the albedo AOV.
    MaterialParams material = lambertianParams(RGB(0.0f));
    // The BSDF of `material` made with the scene, when no texture or vertex colour drives the hit's
    // parameters (render/material_tables.h); null: the integrator makes the hit's BSDF itself.
    const Bsdf* bsdf = nullptr;
    RGB emission;             // emitted radiance of an emissive surface (both sides)
    int light = -1;           // index of the light this surface belongs to, or -1
    bool lightShape = false;  // a light's own shape (rect, disk, sphere, cylinder): emits, does not reflect
    // The interior medium of the surface's material (RenderScene::mediumInside), or -1: the
    // surface bounds no medium.
    int interior = -1;
    // Its names for Cryptomatte (RenderScene::objectNames, materialNames), kNoName where none.
    std::uint32_t objectName = kNoName, materialName = kNoName;
    int linkGroup = 0;  // the hit geometry's light and shadow links (render/light_links.h)
};

// What a ray met, before it is shaded (RenderScene::trace): Embree's ids, barycentrics, distance
// and unnormalised geometric normal of the nearest surface or light shape.
struct TracedHit {
    static constexpr unsigned kNone = ~0u;  // Embree's invalid geometry id
    unsigned geomID = kNone, primID = 0, instID = kNone;
    float u = 0.0f, v = 0.0f;
    float t = std::numeric_limits<float>::infinity();  // infinite when nothing was met
    Vec3f ng{0.0f};
    bool lightShape = false;  // in the light shapes' scene
    bool met() const { return geomID != kNone; }
};

// What a shadow ray towards a light meets (RenderScene::shadowTest).
enum class ShadowTest {
    Clear,          // no surface: BSDF sampling could have reached the light along it too
    PassedThrough,  // only surfaces the light casts no shadow of: next-event estimation alone reaches it
    Blocked,
};

struct SceneStats {
    std::size_t meshes = 0, triangles = 0;  // stored once (world meshes and prototype meshes)
    std::size_t instances = 0;              // Embree instances
    std::size_t instancedTriangles = 0;     // triangles seen through instances (not stored again)
    std::size_t lights = 0, emissiveTriangles = 0;
    std::size_t curves = 0, curveSegments = 0;  // CurvesDesc, and their Embree segments
    std::size_t pointSets = 0, points = 0;      // PointsDesc, and their Embree points
};

class RenderScene {
public:
    // `textures` may be null: one is made (with the default colour management) when a material
    // has texture bindings.
    explicit RenderScene(const SceneDescription& scene, std::shared_ptr<texture::TextureSystem> textures = nullptr);
    ~RenderScene();
    RenderScene(const RenderScene&) = delete;
    RenderScene& operator=(const RenderScene&) = delete;

    // The nearest surface or light shape the ray meets, shaded: shade(trace(ray), ray).
    std::optional<SurfaceHit> intersect(const Ray& ray) const;
    // The nearest surface or light shape the ray meets, not shaded yet: a caller that needs only
    // its distance at first (a guided walk's entry step, integrators/path_tracer.cpp) shades it
    // (shade, with the same ray) only if it turns out to need the hit.
    TracedHit trace(const Ray& ray) const;
    std::optional<SurfaceHit> shade(const TracedHit& traced, const Ray& ray) const;
    // True when a surface blocks the segment from `origin` along unit `direction` for `distance`,
    // at `time` in the shutter interval (render::Ray::time).
    bool occluded(const Vec3f& origin, const Vec3f& direction, float distance, float time = 0.0f) const;
    // True when the same segment meets the shape (rect, disk, sphere, cylinder) of a light other than
    // `light`: a shape emits and does not reflect, so a ray that meets it ends there (intersect()),
    // and no light reaches past it.
    bool meetsOtherLightShape(int light, const Vec3f& origin, const Vec3f& direction, float distance,
                              float time = 0.0f) const;
    // The shadow ray from `origin` along unit `direction` to light `light` at `distance`: whether a
    // surface blocks it, as occluded() says, unless every surface on it is one the light casts no
    // shadow of (LightDesc::castsShadows false: none) (render/shadow_rays.cpp).
    ShadowTest shadowTest(int light, const Vec3f& origin, const Vec3f& direction, float distance,
                          float time = 0.0f) const;
    // Whether some surface can be passed through by light `light`'s shadow rays (its shadows are
    // off, or shadow-linked away from some geometry).
    bool lightPassesSurfaces(int light) const { return shadowless(light) || links_.passesSomething(light); }
    // Whether light `light` lights geometry of link group `linkGroup` (SurfaceHit::linkGroup; 0 for
    // points in media and the camera), and the whole table (render/light_links.h).
    bool lightReaches(int light, int linkGroup) const { return links_.lights(light, linkGroup); }
    const LightLinkTable& lightLinks() const { return links_; }
    // The surfaces `ray`, leaving light `light`, reaches: the first surface it hits and, for a light
    // that passes surfaces, every surface after it that the light's shadow rays would pass, up to and
    // including the first that blocks them (at most kMaxSurfacesPassed). Light shapes are skipped.
    std::vector<SurfaceHit> surfacesReached(int light, const Ray& ray) const;
    static constexpr int kMaxSurfacesPassed = 64;
    // Shadow rays stop this fraction short of the light sample, so a sample on an emissive surface
    // is not occluded by that surface itself.
    static constexpr float kShadowRayShortening = 1e-4f;
    // Where the surface point of `hit` is at `time` in the shutter interval: the same point of the
    // same triangle, moved with its mesh and instance (the hit's own point for a light shape; on
    // curves, the hit moved as the curve's axis moves there; on points, the point's centre).
    Vec3f pointAt(const SurfaceHit& hit, float time) const;

    std::size_t lightCount() const { return lights_.size(); }
    // Light i as the light tree sees it (a moving light: at the frame, its bounds() over the shutter).
    const Light& light(std::size_t i) const { return *lights_[i]; }
    // Light i where it is at `time` in the shutter (render::Ray::time): what next-event estimation
    // samples, what a hit on its shape emits, what light subpaths and photons leave from
    // (render/light_at_time.h). The light itself when it does not move.
    LightAtTime lightAt(std::size_t i, float time) const;
    // The light group of the light or emissive mesh at prim path `name` (SceneDescription::
    // lightGroups), or null when it has none.
    const std::string* lightGroup(const std::string& name) const {
        auto found = lightGroups_.find(name);
        return found == lightGroups_.end() ? nullptr : &found->second;
    }
    // Lights at infinity (dome, distant), seen by rays that leave the scene.
    // The lights at infinity a ray that leaves the scene sees: all of them, but for a camera ray
    // (straight from the camera) those a LightDesc marks invisible to the camera.
    const std::vector<int>& lightsAtInfinity(bool cameraRay) const {
        return cameraRay ? lightsAtInfinitySeenByCamera_ : lightsAtInfinity_;
    }
    // Chooses a light for next-event estimation at point p with normal n (the geometric normal on
    // the side the light is gathered from; a zero vector where there is no surface) from u in
    // [0, 1). light = -1 when no light can reach p.
    LightChoice chooseLight(const Vec3f& p, const Vec3f& n, float u) const { return lightTree_.choose(p, n, u); }
    // The probability chooseLight(p, n, .) returns `light` with.
    float lightProbability(const Vec3f& p, const Vec3f& n, int light) const {
        return lightTree_.probability(p, n, light);
    }
    // Chooses a light for next-event estimation proportionally to its power, wherever p is.
    const DiscreteDistribution& lightSelection() const { return lightSelection_; }

    const SceneBounds& bounds() const { return bounds_; }
    const SceneStats& stats() const { return stats_; }
    // A surface triangle in world space, its material reduced to what finite-element methods
    // (integrators/radiosity.h) need: the diffuse albedo (the mean of the triangle's corner
    // colours where the mesh has them, else the material's diffuse; textures are not evaluated)
    // and the emitted radiance.
    struct SurfaceTriangle {
        Vec3f p0, p1, p2;
        RGB albedo, emission;
    };
    // Every surface triangle (instanced ones once per instance; light shapes are not surfaces).
    std::vector<SurfaceTriangle> surfaceTriangles() const;
    // The scene's volumes as one participating medium (media/medium_union.h), or nullptr when it
    // has none. Rays travel through it between surfaces; surfaces do not bound it.
    const media::Medium* medium() const { return medium_.get(); }
    // The medium inside a closed surface whose hits carry SurfaceHit::interior == `interior`: the
    // material's homogeneous interior together with the scene's volumes.
    const media::Medium* mediumInside(int interior) const {
        return interiors_[static_cast<std::size_t>(interior)].get();
    }
    // Whether any ray can travel through a medium: volumes or material interiors.
    bool hasMedia() const { return medium_ || !interiors_.empty(); }
    // Whether anything moves while the shutter is open: a mesh, curves or points with motion steps
    // (in the world or in a prototype), an instance or a light with motion transforms.
    // When nothing does, no ray's time changes what it meets, emits or lights.
    bool moves() const { return moves_; }

    // The names hits carry (SurfaceHit::objectName, materialName), for the Cryptomatte layers: the
    // prim path of the hit gprim (MeshDesc::name), of the instance for geometry placed by instancing
    // (InstanceDesc::name; none when it is empty), of the light for a light's own shape; and of the
    // bound material (MaterialDesc::name; none for a mesh without one).
    const NameTable& objectNames() const { return objectNames_; }
    const NameTable& materialNames() const { return materialNames_; }

    // What went wrong while building that did not stop it (unreadable textures).
    const std::vector<Warning>& warnings() const { return warnings_; }

    // The committed Embree scene of the surfaces (meshes and instances, no light shapes), for
    // benchmarks that cast rays through bare Embree (bench/embree_throughput_bench.cpp).
    RTCSceneTy* embreeSurfaces() const;

    // The value of the mesh primvar `name` (as CornerPrimvar names it, without "primvars:") at a
    // hit, interpolated over its triangle: writes its components (1 to 4) to `out` and returns how
    // many; 0 when the hit's mesh has no such primvar (the delegate keeps only the primvars
    // materials read, and DelegateOptions::aovPrimvars) or is a light shape.
    int primvarAt(const SurfaceHit& hit, const std::string& name, float out[4]) const;

    // The camera whose pixel footprint sets the texture filter width (call before rendering).
    void setTextureFilterCamera(const Camera& camera) { filterCamera_ = camera; }

private:
    struct Mesh;
    struct Prototype;
    struct Instance;
    // Validates `desc`, stores it and returns its index in meshes_ (`objectName`: its hits' name;
    // `shaping`: its mesh light's shaping when another copy of it has made one, else null).
    int storeMesh(const MeshDesc& desc, const std::vector<MaterialDesc>& materials, std::uint32_t objectName,
                  std::shared_ptr<const LightShaping> shaping = nullptr);
    // Turns a closed mesh of a solid material outward (render/solid_orientation.h); warns when a
    // subsurface mesh is not closed.
    void orientSolid(Mesh& mesh);
    void addMesh(const MeshDesc& mesh, const std::vector<MaterialDesc>& materials, std::uint32_t objectName,
                 std::shared_ptr<const LightShaping> shaping = nullptr);
    void addCurves(const CurvesDesc& curves, const std::vector<MaterialDesc>& materials);
    // Adds `curves` to `geometry` and attaches them to `scene` (the surfaces' or a prototype's) as `geomID`.
    void storeCurves(CurveGeometry& geometry, const CurvesDesc& curves, const std::vector<MaterialDesc>& materials,
                     std::uint32_t objectName, RTCSceneTy* scene, unsigned geomID);
    // A point set (render/point_geometry.h): Embree points, shaded through a mesh of its own.
    void addPoints(const PointsDesc& points, const std::vector<MaterialDesc>& materials);
    // Stores the shading mesh of `points` (returning its index in meshes_) and attaches their
    // Embree points to `scene` (the surfaces' or a prototype's) as `geomID`.
    int storePoints(const PointsDesc& points, const std::vector<MaterialDesc>& materials, std::uint32_t objectName,
                    RTCSceneTy* scene, unsigned geomID);
    void addPrototypes(const SceneDescription& scene);
    void addLight(const LightDesc& light);
    void addVolumes(const std::vector<VolumeDesc>& volumes);
    void addMaterialShaders();
    void addInteriors();
    void addPresenceFilter(RTCGeometryTy* geometry, int mesh);
    // The hit on triangle primID of mesh `mesh` at barycentrics (u, v), in world space
    // (`instance` places a prototype mesh).
    // (Both return the optional intersect() returns, built in place.)
    // `instance`: into instances_, -1 for a world mesh; `ray`: the ray that met it (its time, and
    // its direction for the side a mesh light is seen from).
    std::optional<SurfaceHit> shadeMesh(int mesh, unsigned primID, float u, float v, float t, int instance,
                                        const Ray& ray) const;
    // shadeMesh's steps: the record started from the parameters of the material `mesh` shows; the
    // hit moved to world space by instance `instance` (its triangle's edges e1, e2 too); the
    // material evaluated at the hit (corner colours, shader; where neither drives it, the hit
    // carries the material's BSDF made with the scene), `corner` the triangle's first corner and
    // (w, u, v) the hit's barycentric weights.
    std::optional<SurfaceHit> newMeshHit(const Mesh& mesh) const;
    void placeInWorld(SurfaceHit& hit, int instance, Vec3f& e1, Vec3f& e2) const;
    void shadeMaterial(const Mesh& mesh, SurfaceHit& hit, std::size_t corner, float w, float u, float v,
                       const Vec3f& e1, const Vec3f& e2) const;
    // A triangle's corners, and an instance's placement, at a ray's time (render/motion_geometry.h).
    struct Triangle {
        Vec3f p0, p1, p2;
    };
    Triangle triangleAt(const Mesh& mesh, unsigned triangle, float time) const;
    // Triangle `triangle` of an emissive mesh with corners `c`, named `name`.
    static TriangleLight triangleLight(const Mesh& mesh, std::string name, const Triangle& c, unsigned triangle);
    // The light of triangle `triangle` of an emissive mesh, its corners taken from `positions`.
    std::unique_ptr<TriangleLight> triangleLight(const Mesh& mesh, const std::vector<Vec3f>& positions,
                                                 unsigned triangle) const;
    // The instance at `index` (nullptr for -1), or, when it moves, its copy placed at `time` in `moved`.
    const Instance* instanceAt(int index, float time, std::optional<Instance>& moved) const;
    // The hit on curve geomID of an instance's prototype (`curves`), in world space.
    std::optional<SurfaceHit> shadeInstancedCurve(const CurveGeometry& curves, int instance, unsigned geomID,
                                                  unsigned primID, float u, const Ray& ray, float t,
                                                  const Vec3f& ng) const;
    std::optional<SurfaceHit> shadeLightShape(unsigned geomID, const Ray& ray, float t, const Vec3f& ng) const;

    struct EmbreeState;
    std::unique_ptr<EmbreeState> embree_;
    CurveGeometry curves_;  // the surface scene's curve geometries (released before embree_'s device)
    std::vector<Mesh> meshes_;
    std::vector<MaterialDesc> materials_;
    std::shared_ptr<texture::TextureSystem> textures_;
    std::vector<MaterialShader> shaders_;                       // one per material
    MaterialBsdfs materialBsdfs_;                               // one per material, at its authored parameters
    std::vector<std::unique_ptr<MeshPresence>> presenceTests_;  // user data of the filter functions
    std::optional<Camera> filterCamera_;
    std::unique_ptr<media::Medium> medium_;
    std::vector<std::unique_ptr<media::Medium>> interiorMedia_;  // the materials' homogeneous interiors
    std::vector<std::unique_ptr<media::Medium>> interiors_;      // each with the volumes (mediumInside)
    std::vector<int> materialInterior_;                          // material -> interior, or -1
    std::vector<Warning> warnings_;
    bool moves_ = false;                 // moves()
    std::vector<int> surfaceMeshes_;     // Embree geometry id in the surface scene -> mesh, or -1
    std::vector<int> surfaceInstances_;  // Embree geometry id in the surface scene -> instance, or -1
    std::vector<int> surfacePoints_;     // Embree geometry id in the surface scene -> a point set's shading mesh, or -1
    std::vector<Prototype> prototypes_;
    std::vector<Instance> instances_;
    std::vector<int> lightShapeToLight_;          // Embree geometry id in the light scene -> light
    std::vector<std::uint32_t> lightShapeNames_;  // Embree geometry id in the light scene -> object name
    NameTable objectNames_, materialNames_;
    std::vector<std::unique_ptr<Light>> lights_;
    std::vector<int> lightsAtInfinity_, lightsAtInfinitySeenByCamera_;
    std::vector<bool> shadowless_;  // per light, true where it casts no shadows (lightPassesSurfaces)
    LightLinkTable links_;
    std::map<std::string, std::string> lightGroups_;
    // Whether `hit`'s surface blocks light `light`'s shadow rays (render/shadow_rays.cpp).
    bool blocksShadowsOf(int light, const SurfaceHit& hit) const;
    bool shadowless(int light) const;  // LightDesc::castsShadows false
    // What moves among the lights, by light index (shorter than lights_: the rest stay still): a
    // UsdLux light's frame light and motion, or the world mesh whose triangle it is.
    struct MovingLight {
        const Light* frame = nullptr;
        const LightMotion* motion = nullptr;
        int mesh = -1;
    };
    std::vector<MovingLight> movingLights_;
    std::deque<LightMotion> lightMotions_;       // stable addresses, for movingLights_ and the shapes
    std::deque<MovingLightShape> movingShapes_;  // the user data of moving lights' Embree shapes
    std::deque<Vec3f> quadLightFronts_;          // each quad light's emitting direction, its Embree filter's user data
    DiscreteDistribution lightSelection_;
    LightTree lightTree_;
    SceneBounds bounds_;
    SceneStats stats_;
};

}  // namespace fluence::render
