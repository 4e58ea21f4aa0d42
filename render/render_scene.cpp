#include "render/render_scene.h"

#include <embree3/rtcore.h>
#include <immintrin.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/random.h"
#include "media/homogeneous_medium.h"
#include "media/medium_union.h"
#include "render/embree_ray.h"
#include "render/light_shape.h"
#include "render/material_tables.h"
#include "render/lights/light_registry.h"
#include "render/lights/swept_light.h"
#include "render/lights/triangle_light.h"
#include "render/mesh_transform.h"
#include "render/point_geometry.h"
#include "render/solid_orientation.h"
#include "render/motion_geometry.h"
#include "volumes/grid_medium.h"

namespace fluence::render {

namespace {

void throwOnEmbreeError(RTCDevice device, const char* what) {
    RTCError code = rtcGetDeviceError(device);
    if (code != RTC_ERROR_NONE)
        throw std::runtime_error(std::string("Embree error ") + std::to_string(int(code)) + " while " + what);
}

// A committed triangle geometry holding `positions` and `indices` (3 per triangle), with the time
// steps of `motion` when it moves (render/motion_geometry.h).
RTCGeometry triangleGeometry(RTCDevice device, const std::vector<Vec3f>& positions,
                             const std::vector<std::uint32_t>& indices,
                             const std::vector<std::vector<Vec3f>>& motion = {}) {
    RTCGeometry geom = newTriangleGeometry(device, positions, motion, indices);
    rtcCommitGeometry(geom);
    return geom;
}

// Embree callbacks of a disk or cylinder light's user geometry; the user pointer is the light's
// AnalyticLightShape.
void analyticShapeBounds(const RTCBoundsFunctionArguments* args) {
    Vec3f lo, hi;
    static_cast<const AnalyticLightShape*>(args->geometryUserPtr)->shapeBounds(lo, hi);
    *args->bounds_o = RTCBounds{lo.x, lo.y, lo.z, 0.0f, hi.x, hi.y, hi.z, 0.0f};
}

void analyticShapeIntersect(const RTCIntersectFunctionNArguments* args) {
    if (args->N != 1 || !args->valid[0]) return;  // the scene is only traced with rtcIntersect1
    const RTCRay& r = reinterpret_cast<const RTCRayHit*>(args->rayhit)->ray;
    std::optional<ShapeHit> hit =
        static_cast<const AnalyticLightShape*>(args->geometryUserPtr)
            ->intersect({r.org_x, r.org_y, r.org_z}, {r.dir_x, r.dir_y, r.dir_z}, r.tnear, r.tfar);
    if (hit) storeUserHit(args, hit->t, hit->normal);
}

RTCGeometry analyticGeometry(RTCDevice device, const AnalyticLightShape& shape) {
    RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(geom, 1);
    rtcSetGeometryUserData(geom, const_cast<AnalyticLightShape*>(&shape));
    rtcSetGeometryBoundsFunction(geom, analyticShapeBounds, nullptr);
    rtcSetGeometryIntersectFunction(geom, analyticShapeIntersect);
    rtcCommitGeometry(geom);
    return geom;
}

// The Embree geometry of a light's surface for camera and BSDF rays, committed (nullptr: none).
RTCGeometry lightSurfaceGeometry(RTCDevice device, const LightSurface& surface) {
    switch (surface.kind) {
        case LightSurface::Kind::None: return nullptr;
        case LightSurface::Kind::Quad: {
            const auto& c = surface.corners;
            return triangleGeometry(device, {c[0], c[1], c[2], c[3]}, {0, 1, 2, 0, 2, 3});
        }
        case LightSurface::Kind::Sphere: {
            RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_SPHERE_POINT);
            auto* v = static_cast<float*>(
                rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float), 1));
            v[0] = surface.centre.x;
            v[1] = surface.centre.y;
            v[2] = surface.centre.z;
            v[3] = surface.radius;
            rtcCommitGeometry(geom);
            return geom;
        }
        case LightSurface::Kind::Analytic: return analyticGeometry(device, *surface.shape);
    }
    return nullptr;
}

bool emits(const MeshDesc& mesh, const std::vector<MaterialDesc>& materials) {
    return mesh.light || (mesh.material >= 0 && mesh.material < static_cast<int>(materials.size()) &&
                          mayEmit(materials[mesh.material]));
}

// Whether anything `scene` holds has motion steps or motion transforms (RenderScene::moves).
bool describesMotion(const SceneDescription& scene) {
    const auto deforms = [](const MeshDesc& m) { return !m.motionPositions.empty(); };
    // (Motion radii come only with motion positions: checkMotionRadii.)
    const auto sways = [](const CurvesDesc& c) { return !c.motionPoints.empty(); };
    const auto drifts = [](const PointsDesc& p) { return !p.motionPositions.empty(); };
    const auto anyMoves = [&](const auto& meshes, const auto& curves, const auto& points) {
        return std::ranges::any_of(meshes, deforms) || std::ranges::any_of(curves, sways) ||
               std::ranges::any_of(points, drifts);
    };
    const auto travels = [](const auto& placed) { return !placed.motionTransforms.empty(); };
    return anyMoves(scene.meshes, scene.curves, scene.points) ||
           std::ranges::any_of(scene.prototypes,
                               [&](const PrototypeDesc& p) { return anyMoves(p.meshes, p.curves, p.points); }) ||
           std::ranges::any_of(scene.instances, travels) || std::ranges::any_of(scene.lights, travels);
}

// Whether the segment [tMin, tMax] of the ray from o along d meets the box [lo, hi]. Conservative:
// a slab whose bound is NaN (0 x infinity, the ray parallel to a face and on its plane) excludes
// nothing. Every ray traced in a scene with light shapes asks it, so the three slabs are computed
// side by side in SSE lanes (one division for the three inverses instead of three), each lane doing
// the scalar code's IEEE operations; the swap when tNear > tFar is min_ps(tFar, tNear) and
// max_ps(tNear, tFar), whose operand order keeps the scalar outcome when a bound is NaN (an
// unordered comparison swaps nothing).
bool segmentMeetsBox(const Vec3f& o, const Vec3f& d, float tMin, float tMax, const Vec3f& lo, const Vec3f& hi) {
    const __m128 origin = _mm_setr_ps(o.x, o.y, o.z, 0.0f);
    const __m128 inverse = _mm_div_ps(_mm_set1_ps(1.0f), _mm_setr_ps(d.x, d.y, d.z, 1.0f));
    const __m128 tNear = _mm_mul_ps(_mm_sub_ps(_mm_setr_ps(lo.x, lo.y, lo.z, 0.0f), origin), inverse);
    const __m128 tFar = _mm_mul_ps(_mm_sub_ps(_mm_setr_ps(hi.x, hi.y, hi.z, 0.0f), origin), inverse);
    alignas(16) float nearer[4], farther[4];
    _mm_store_ps(nearer, _mm_min_ps(tFar, tNear));
    _mm_store_ps(farther, _mm_max_ps(tNear, tFar));
    for (int axis = 0; axis < 3; ++axis) {
        tMin = std::max(tMin, nearer[axis]);
        tMax = std::min(tMax, farther[axis]);
    }
    return tMin <= tMax;
}

// The matrix that takes a normal through `m` as m.transformNormal does, but as one linear map.
Matrix4 normalMatrixOf(const Matrix4& m) {
    Matrix4 n = Matrix4::identity();
    for (int column = 0; column < 3; ++column) {
        Vec3d e(column == 0, column == 1, column == 2);
        Vec3d t = m.transformNormal(e);
        n.m[0][column] = t.x;
        n.m[1][column] = t.y;
        n.m[2][column] = t.z;
    }
    return n;
}

}  // namespace

struct RenderScene::Mesh {
    std::string name;
    std::vector<Vec3f> positions;
    std::vector<std::uint32_t> indices;
    std::vector<Vec3f> cornerNormals;
    std::vector<RGB> cornerColors;
    std::vector<CornerPrimvar> primvars;
    std::vector<std::vector<Vec3f>> motionPositions;  // MeshDesc::motionPositions
    // Per triangle, its unit geometric normal (unitTriangleNormal), for a world mesh that does not
    // move (empty otherwise: shadeMesh computes it per hit): a square root and three divisions per
    // hit saved, the values the same bit for bit.
    std::vector<Vec3f> unitNormals;
    // For each primvar slot of the material's shader, the mesh's primvar (nullptr: none). Points
    // into `primvars`' buffer, which moving a Mesh does not move.
    std::vector<const CornerPrimvar*> slots;
    RGB diffuse;
    RGB emission;
    std::unique_ptr<TexturedEmission> texturedEmission;  // where a node drives the emission, else null
    // A UsdLux mesh light (MeshDesc::light): `emission` is the light's, from the front only; with
    // noMaterialResponse the surface is black.
    EmittingSides emittingSides = EmittingSides::Both;
    bool reflects = true;
    bool meshLight = false;  // a UsdLux mesh light: a camera ray sees its surface, not its light
    int material = -1;       // into materials_, -1 = the default (Lambertian) material
    int firstLight = -1;
    int linkId = -1;  // MeshLightDesc::linkId
    // A mesh light's shaping (MeshLightDesc::shaping), about the default frame (each triangle
    // evaluates it in its own), shared by the copies an instanced prototype's mesh places, and
    // the prim's axes that orient an IES profile; null: unshaped.
    std::shared_ptr<const LightShaping> shaping;
    Matrix4 shapingToWorld = Matrix4::identity();
    std::uint32_t objectName = kNoName, materialName = kNoName;  // objectNames_, materialNames_
    int linkGroup = 0;                                           // MeshDesc::linkGroup
};

// What a presence filter needs to know of its mesh (the user data of its Embree geometry).
struct MeshPresence {
    const MaterialShader* shader;
    const CornerPrimvar* const* slots;
};

namespace {

// The unit geometric normal of a triangle whose edges' cross product is `ng` ((0, 0, 1) for a
// degenerate one): shadeMesh's, per hit or stored per triangle (Mesh::unitNormals).
Vec3f unitTriangleNormal(const Vec3f& ng) { return lengthSquared(ng) > 0.0f ? normalize(ng) : Vec3f(0, 0, 1); }

// A uniform number in [0, 1) that is a pure function of the ray and the triangle it meets.
float hashOfHit(const float (&ray)[6], unsigned geomID, unsigned primID, unsigned instID) {
    std::uint64_t h = mix64((std::uint64_t(geomID) << 32) ^ primID ^ (std::uint64_t(instID) << 48));
    for (float f : ray) h = mix64(h ^ std::bit_cast<std::uint32_t>(f));
    return toUnitFloat(h);
}

// Rejects the candidate hit of a filter function (called for one ray) where the ray meets the back
// of a light shape whose emitting side faces `front` (render/light_shape.h, THE BACK OF A LIGHT):
// the ray passes through it.
void passThroughBack(const RTCFilterFunctionNArguments* args, const Vec3f& front) {
    const Vec3f direction(RTCRayN_dir_x(args->ray, 1, 0), RTCRayN_dir_y(args->ray, 1, 0),
                          RTCRayN_dir_z(args->ray, 1, 0));
    if (!meetsFront(direction, front)) args->valid[0] = 0;
}

// Embree filter function of a quad light's triangles (user data: its emitting direction, a Vec3f).
void frontSideFilter(const RTCFilterFunctionNArguments* args) {
    if (args->N != 1 || !args->valid[0]) return;  // the scenes are only traced one ray at a time
    passThroughBack(args, *static_cast<const Vec3f*>(args->geometryUserPtr));
}

// Embree filter function of a sphere light: it emits outwards only (SphereLight::sample, power and
// sampleEmission), so a ray from inside passes through its surface. Embree's geometric normal of
// a sphere points outwards.
void outerSideFilter(const RTCFilterFunctionNArguments* args) {
    if (args->N != 1 || !args->valid[0]) return;  // the scenes are only traced one ray at a time
    passThroughBack(args,
                    Vec3f(RTCHitN_Ng_x(args->hit, 1, 0), RTCHitN_Ng_y(args->hit, 1, 0), RTCHitN_Ng_z(args->hit, 1, 0)));
}

// Embree filter function of a mesh whose material may have holes: rejects the candidate hit
// where the surface is absent (see render_scene.h).
void presenceFilter(const RTCFilterFunctionNArguments* args) {
    if (args->N != 1 || !args->valid[0]) return;  // the scenes are only traced one ray at a time
    const auto* test = static_cast<const MeshPresence*>(args->geometryUserPtr);
    ShadingPatch patch;
    unsigned primID = RTCHitN_primID(args->hit, 1, 0);
    float u = RTCHitN_u(args->hit, 1, 0), v = RTCHitN_v(args->hit, 1, 0);
    patch.corner = 3 * std::size_t(primID);
    patch.b0 = 1.0f - u - v;
    patch.b1 = u;
    patch.b2 = v;
    float presence = test->shader->presence(patch, test->slots);
    if (presence >= 1.0f) return;
    float ray[6] = {RTCRayN_org_x(args->ray, 1, 0), RTCRayN_org_y(args->ray, 1, 0), RTCRayN_org_z(args->ray, 1, 0),
                    RTCRayN_dir_x(args->ray, 1, 0), RTCRayN_dir_y(args->ray, 1, 0), RTCRayN_dir_z(args->ray, 1, 0)};
    if (presence <= 0.0f ||
        hashOfHit(ray, RTCHitN_geomID(args->hit, 1, 0), primID, RTCHitN_instID(args->hit, 1, 0, 0)) >= presence)
        args->valid[0] = 0;
}

}  // namespace

struct RenderScene::Prototype {
    std::vector<int> meshes;  // Embree geometry id in the prototype's scene -> mesh, or -1
    std::vector<int> points;  // Embree geometry id in the prototype's scene -> a point set's shading mesh, or -1
    std::unique_ptr<CurveGeometry> curves = std::make_unique<CurveGeometry>();  // its curve geometries
    // Its emissive meshes, copied per instance: each one's index into SceneDescription::prototypes[i].meshes,
    // its area in the prototype's space (a normalized mesh light's copy divides by its placed area
    // instead), and its mesh light's shaping, made for the first copy and shared by the rest.
    struct EmissiveMesh {
        int mesh = -1;
        float area = 0.0f;
        std::shared_ptr<const LightShaping> shaping;
    };
    std::vector<EmissiveMesh> emissiveMeshes;
    Vec3f lo{std::numeric_limits<float>::max()}, hi{-std::numeric_limits<float>::max()};  // bounds
};

struct RenderScene::Instance {
    int prototype = 0;
    Matrix4 toWorld, normalToWorld;
    std::uint32_t objectName = kNoName;     // objectNames_
    std::vector<Matrix4> motionTransforms;  // InstanceDesc::motionTransforms
    int linkGroup = 0;                      // InstanceDesc::linkGroup
};

struct RenderScene::EmbreeState {
    RTCDevice device = nullptr;
    RTCScene surfaces = nullptr;
    RTCScene lightShapes = nullptr;
    std::vector<RTCScene> prototypes;
    // The light shapes' bounds, padded (set when there are any): a ray that misses them is not
    // traced through lightShapes.
    Vec3f lightShapesLo, lightShapesHi;
    // The light every shape in lightShapes belongs to (-1: none, or shapes of several lights): a
    // shadow ray towards it can meet no other light's shape, so none is looked for (one rect light,
    // as in the Cornell box, saved a light-shape trace per shadow ray: 6% of its render). A query
    // for any light's shape (light -1, bdpt's joins) still looks.
    int lightOfEveryShape = -1;
    ~EmbreeState() {
        for (RTCScene s : prototypes) rtcReleaseScene(s);
        if (surfaces) rtcReleaseScene(surfaces);
        if (lightShapes) rtcReleaseScene(lightShapes);
        if (device) rtcReleaseDevice(device);
    }
};

RenderScene::RenderScene(const SceneDescription& scene, std::shared_ptr<texture::TextureSystem> textures)
    : embree_(std::make_unique<EmbreeState>()), materials_(scene.materials), textures_(std::move(textures)) {
    addMaterialShaders();
    materialBsdfs_ = buildMaterialTables(materials_);
    checkLinkGroups(scene);
    moves_ = describesMotion(scene);
    embree_->device = rtcNewDevice(nullptr);
    if (!embree_->device) throw std::runtime_error("cannot create the Embree device");
    embree_->surfaces = rtcNewScene(embree_->device);
    embree_->lightShapes = rtcNewScene(embree_->device);
    rtcSetSceneBuildQuality(embree_->surfaces, RTC_BUILD_QUALITY_HIGH);
    // Robust intersection: watertight along shared edges and vertices (a diced subdivision
    // surface must not let rays through its seams), at some cost in speed.
    rtcSetSceneFlags(embree_->surfaces, RTC_SCENE_FLAG_ROBUST);

    for (const MeshDesc& mesh : scene.meshes) addMesh(mesh, scene.materials, objectNames_.add(mesh.name));
    for (const CurvesDesc& curves : scene.curves) addCurves(curves, scene.materials);
    for (const PointsDesc& points : scene.points) addPoints(points, scene.materials);
    addPrototypes(scene);
    // The render lights of each emitter a link group names (render/light_links.h).
    std::vector<std::vector<int>> lightsOfEmitter;
    for (const LightDesc& light : scene.lights) {
        lightsOfEmitter.push_back({static_cast<int>(lights_.size())});
        addLight(light);
    }
    lightsOfEmitter.resize(linkEmitterCount(scene));
    for (const Mesh& mesh : meshes_)
        if (mesh.linkId >= 0 && mesh.firstLight >= 0)
            for (std::size_t t = 0; t < mesh.indices.size() / 3; ++t)
                lightsOfEmitter[scene.lights.size() + std::size_t(mesh.linkId)].push_back(mesh.firstLight + int(t));
    links_ = LightLinkTable(scene.lightLinkGroups, lightsOfEmitter, lights_.size());
    lightGroups_ = scene.lightGroups;
    addVolumes(scene.volumes);
    addInteriors();

    // Scene bounds (for the power of lights at infinity) from surfaces, instances and lights.
    Vec3f lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (const std::vector<int>* shapes : {&surfaceMeshes_, &surfacePoints_})
        for (int m : *shapes)
            if (m >= 0) {
                for (const Vec3f& p : meshes_[m].positions) {
                    lo = vmin(lo, p);
                    hi = vmax(hi, p);
                }
                for (const std::vector<Vec3f>& step : meshes_[m].motionPositions)
                    for (const Vec3f& p : step) {
                        lo = vmin(lo, p);
                        hi = vmax(hi, p);
                    }
            }
    curves_.growBounds(lo, hi);
    for (const Instance& instance : instances_) {
        const Prototype& proto = prototypes_[instance.prototype];
        if (proto.lo.x > proto.hi.x) continue;
        std::vector<Matrix4> placements = instance.motionTransforms;
        placements.push_back(instance.toWorld);
        for (const Matrix4& placement : placements)
            for (int corner = 0; corner < 8; ++corner) {
                Vec3d c(corner & 1 ? proto.hi.x : proto.lo.x, corner & 2 ? proto.hi.y : proto.lo.y,
                        corner & 4 ? proto.hi.z : proto.lo.z);
                Vec3f p(placement.transformPoint(c));
                lo = vmin(lo, p);
                hi = vmax(hi, p);
            }
    }
    for (const auto& light : lights_)
        if (std::optional<LightBounds> b = light->bounds()) {
            lo = vmin(lo, b->lo);
            hi = vmax(hi, b->hi);
        }
    if (lo.x <= hi.x) {
        bounds_.centre = (lo + hi) * 0.5f;
        bounds_.radius = std::max(0.5f * length(hi - lo), 1e-3f);
    }

    rtcCommitScene(embree_->surfaces);
    rtcCommitScene(embree_->lightShapes);
    throwOnEmbreeError(embree_->device, "building the scene");
    if (!lightShapeToLight_.empty()) {
        RTCBounds b;
        rtcGetSceneBounds(embree_->lightShapes, &b);
        const Vec3f shapesLo(b.lower_x, b.lower_y, b.lower_z), shapesHi(b.upper_x, b.upper_y, b.upper_z);
        // Far more than the rounding of a hit point on a shape (a few ULPs of its coordinates).
        const float pad =
            1e-4f * (maxComponent(shapesHi - shapesLo) + maxComponent(vmax(shapesHi, -shapesLo))) + 1e-20f;
        embree_->lightShapesLo = shapesLo - Vec3f(pad);
        embree_->lightShapesHi = shapesHi + Vec3f(pad);
        const int first = lightShapeToLight_.front();
        if (std::all_of(lightShapeToLight_.begin(), lightShapeToLight_.end(), [&](int l) { return l == first; }))
            embree_->lightOfEveryShape = first;
    }

    std::vector<double> powers;
    for (const auto& l : lights_) powers.push_back(std::max(0.0f, l->power(bounds_)));
    lightSelection_ = DiscreteDistribution(powers);
    // Next-event estimation leaves a constant dome to BSDF and phase sampling unless told to sample
    // it (render/dome_light_sampling.h), or unless its light passes surfaces (shadows off, shadow
    // links), which only next-event estimation finds (render/shadow_rays.cpp); the power-based
    // selection keeps every light.
    std::vector<bool> chosenByNextEvent(lights_.size(), true);
    if (scene.domeLightSampling == DomeLightSampling::Auto)
        for (std::size_t i = 0; i < lights_.size(); ++i)
            chosenByNextEvent[i] = !lights_[i]->constantRadiance() || lightPassesSurfaces(int(i));
    lightTree_ = LightTree(lights_, bounds_, chosenByNextEvent);
    stats_.lights = lights_.size();
}

RenderScene::~RenderScene() = default;

RTCScene RenderScene::embreeSurfaces() const { return embree_->surfaces; }

std::vector<RenderScene::SurfaceTriangle> RenderScene::surfaceTriangles() const {
    std::vector<SurfaceTriangle> out;
    auto addMesh = [&](const Mesh& mesh, const Instance* instance) {
        auto world = [&](std::uint32_t i) {
            return instance ? Vec3f(instance->toWorld.transformPoint(Vec3d(mesh.positions[i]))) : mesh.positions[i];
        };
        for (std::size_t c = 0; c + 2 < mesh.indices.size(); c += 3) {
            RGB albedo = mesh.cornerColors.empty()
                             ? mesh.diffuse
                             : (mesh.cornerColors[c] + mesh.cornerColors[c + 1] + mesh.cornerColors[c + 2]) / 3.0f;
            const RGB emission =
                mesh.texturedEmission ? mesh.texturedEmission->mean(static_cast<unsigned>(c / 3)) : mesh.emission;
            out.push_back(
                {world(mesh.indices[c]), world(mesh.indices[c + 1]), world(mesh.indices[c + 2]), albedo, emission});
        }
    };
    for (int m : surfaceMeshes_)
        if (m >= 0) addMesh(meshes_[m], nullptr);
    for (const Instance& instance : instances_)
        for (int m : prototypes_[instance.prototype].meshes)
            if (m >= 0) addMesh(meshes_[m], &instance);
    return out;
}

void RenderScene::addMaterialShaders() {
    bool textured = std::any_of(materials_.begin(), materials_.end(), [](const MaterialDesc& m) {
        bool reads = false;
        for (const InputBinding& b : m.bindings)
            forEachSource(b, [&](const InputBinding& s) { reads = reads || s.texture; });
        return reads;
    });
    if (textured && !textures_) textures_ = std::make_shared<texture::TextureSystem>(color::ColorManagement::load());
    shaders_.reserve(materials_.size());
    for (const MaterialDesc& m : materials_) shaders_.emplace_back(m, textures_.get(), warnings_);
}

void RenderScene::addVolumes(const std::vector<VolumeDesc>& volumes) {
    std::vector<std::unique_ptr<media::Medium>> media;
    for (const VolumeDesc& v : volumes) {
        if (!v.density) continue;
        try {
            volumes::FloatVdbGrid density(v.density->file, v.density->gridName, v.density->gridIndex, v.transform);
            std::optional<volumes::FloatVdbGrid> temperature;
            if (v.temperature)
                temperature.emplace(v.temperature->file, v.temperature->gridName, v.temperature->gridIndex,
                                    v.transform);
            std::optional<volumes::Vec3VdbGrid> color;
            if (v.color) color.emplace(v.color->file, v.color->gridName, v.color->gridIndex, v.transform);
            media.push_back(std::make_unique<volumes::GridMedium>(std::move(density), v.params, std::move(temperature),
                                                                  std::move(color)));
        } catch (const std::exception& e) {
            throw std::invalid_argument(v.name + ": " + e.what());
        }
    }
    if (!media.empty()) medium_ = std::make_unique<media::MediumUnion>(std::move(media));
}

void RenderScene::addInteriors() {
    materialInterior_.assign(materials_.size(), -1);
    for (std::size_t m = 0; m < materials_.size(); ++m) {
        const std::optional<media::MediumProperties>& interior = materials_[m].interior;
        if (!interior) continue;
        bool valid = isFinite(interior->sigmaA + interior->sigmaS) && std::abs(interior->g) < 1.0f;
        for (int c = 0; c < 3; ++c) valid = valid && interior->sigmaA[c] >= 0.0f && interior->sigmaS[c] >= 0.0f;
        if (!valid)
            throw std::invalid_argument(materials_[m].name +
                                        ": interior medium coefficients must be finite and >= 0, with |g| < 1");
        materialInterior_[m] = static_cast<int>(interiors_.size());
        interiorMedia_.push_back(std::make_unique<media::HomogeneousMedium>(*interior));
        if (medium_)
            interiors_.push_back(std::make_unique<media::MediumUnion>(
                std::vector<const media::Medium*>{interiorMedia_.back().get(), medium_.get()}));
        else
            interiors_.push_back(std::make_unique<media::HomogeneousMedium>(*interior));
    }
}

void RenderScene::addPresenceFilter(RTCGeometryTy* geometry, int meshIndex) {
    const Mesh& mesh = meshes_[meshIndex];
    if (mesh.material < 0 || !shaders_[mesh.material].mayBeTransparent()) return;
    presenceTests_.push_back(std::make_unique<MeshPresence>(MeshPresence{&shaders_[mesh.material], mesh.slots.data()}));
    rtcSetGeometryUserData(geometry, presenceTests_.back().get());
    rtcSetGeometryIntersectFilterFunction(geometry, presenceFilter);
    rtcSetGeometryOccludedFilterFunction(geometry, presenceFilter);
    rtcCommitGeometry(geometry);
}

int RenderScene::storeMesh(const MeshDesc& desc, const std::vector<MaterialDesc>& materials, std::uint32_t objectName,
                           std::shared_ptr<const LightShaping> shaping) {
    if (desc.indices.size() % 3 != 0)
        throw std::invalid_argument(desc.name + ": triangle index count is not a multiple of 3");
    for (std::uint32_t i : desc.indices)
        if (i >= desc.positions.size()) throw std::invalid_argument(desc.name + ": triangle index out of range");
    std::size_t triangles = desc.indices.size() / 3;
    if (!desc.cornerNormals.empty() && desc.cornerNormals.size() != triangles * 3)
        throw std::invalid_argument(desc.name + ": expected one normal per triangle corner");
    if (!desc.cornerColors.empty() && desc.cornerColors.size() != triangles * 3)
        throw std::invalid_argument(desc.name + ": expected one colour per triangle corner");
    if (desc.material >= static_cast<int>(materials.size()))
        throw std::invalid_argument(desc.name + ": material index out of range");
    for (const CornerPrimvar& p : desc.primvars)
        if (p.components < 1 || p.components > 4 || p.values.size() != triangles * 3 * std::size_t(p.components))
            throw std::invalid_argument(desc.name + ": primvar " + p.name + " needs 1 to 4 values per triangle corner");
    checkMotionPositions(desc.name, desc.motionPositions, desc.positions.size());

    Mesh mesh;
    mesh.name = desc.name;
    mesh.positions = desc.positions;
    mesh.indices = desc.indices;
    mesh.cornerNormals = desc.cornerNormals;
    mesh.cornerColors = desc.cornerColors;
    mesh.primvars = desc.primvars;
    mesh.motionPositions = desc.motionPositions;
    if (desc.material >= 0)
        for (const std::string& name : shaders_[desc.material].primvarSlots()) {
            auto found = std::find_if(mesh.primvars.begin(), mesh.primvars.end(),
                                      [&](const CornerPrimvar& p) { return !name.empty() && p.name == name; });
            mesh.slots.push_back(found == mesh.primvars.end() ? nullptr : &*found);
        }
    MaterialDesc material = desc.material >= 0 ? materials[desc.material] : MaterialDesc{};
    mesh.material = desc.material;
    mesh.objectName = objectName;
    mesh.materialName = desc.material >= 0 ? materialNames_.add(material.name) : kNoName;
    mesh.diffuse = material.diffuse;
    mesh.emission = material.emission;
    if (desc.light) {
        mesh.emission = desc.light->radiance;
        mesh.emittingSides = EmittingSides::Front;
        mesh.reflects = desc.light->materialResponse;
        mesh.meshLight = true;
        mesh.linkId = desc.light->linkId;
        if (desc.light->shaping) {
            mesh.shaping = shaping ? std::move(shaping)
                                   : std::make_shared<const LightShaping>(*desc.light->shaping, ShapingFrame().axis,
                                                                          Matrix4::identity());
            mesh.shapingToWorld = desc.light->lightToWorld;
        }
    }
    mesh.linkGroup = desc.linkGroup;
    stats_.meshes += 1;
    stats_.triangles += triangles;
    meshes_.push_back(std::move(mesh));
    return static_cast<int>(meshes_.size()) - 1;
}

void RenderScene::orientSolid(Mesh& mesh) {
    if (mesh.material < 0) return;
    const MaterialDesc& material = materials_[static_cast<std::size_t>(mesh.material)];
    if (!fillsItsInside(material) ||
        orientClosedMeshOutward(mesh.positions, {mesh.indices, mesh.cornerNormals, mesh.cornerColors, mesh.primvars}))
        return;
    if (material.subsurface > 0.0f)
        warnings_.push_back({mesh.name,
                             "subsurface on a mesh that is not closed: it has no inside for light to "
                             "scatter in, so walks leave through its open edges"});
}

void RenderScene::addMesh(const MeshDesc& desc, const std::vector<MaterialDesc>& materials, std::uint32_t objectName,
                          std::shared_ptr<const LightShaping> shaping) {
    int index = storeMesh(desc, materials, objectName, std::move(shaping));
    Mesh& mesh = meshes_[index];
    orientSolid(mesh);
    if (mesh.motionPositions.empty()) {
        mesh.unitNormals.resize(mesh.indices.size() / 3);
        for (std::size_t t = 0; t < mesh.unitNormals.size(); ++t) {
            const Triangle c = triangleAt(mesh, static_cast<unsigned>(t), 0.0f);
            mesh.unitNormals[t] = unitTriangleNormal(cross(c.p1 - c.p0, c.p2 - c.p0));
        }
    }
    if (!desc.light && mesh.material >= 0 && shaders_[mesh.material].drives(MaterialInput::Emission))
        mesh.texturedEmission = std::make_unique<TexturedEmission>(shaders_[mesh.material], mesh.positions,
                                                                   mesh.indices, mesh.slots.data(), filterCamera_);
    if (!isBlack(mesh.emission) || mesh.texturedEmission) {
        std::size_t triangles = mesh.indices.size() / 3;
        mesh.firstLight = static_cast<int>(lights_.size());
        for (std::size_t t = 0; t < triangles; ++t) {
            std::unique_ptr<Light> light = triangleLight(mesh, mesh.positions, static_cast<unsigned>(t));
            if (!mesh.motionPositions.empty()) {  // sampled where it is at a ray's time (lightAt)
                std::vector<LightBounds> places;
                for (const std::vector<Vec3f>& step : mesh.motionPositions)
                    places.push_back(*triangleLight(mesh, step, static_cast<unsigned>(t))->bounds());
                light = std::make_unique<SweptLight>(std::move(light), unionOfLightBounds(places));
                movingLights_.resize(lights_.size() + 1);
                movingLights_.back().mesh = index;
            }
            lights_.push_back(std::move(light));
        }
        stats_.emissiveTriangles += triangles;
    }
    RTCGeometry geom = triangleGeometry(embree_->device, mesh.positions, mesh.indices, mesh.motionPositions);
    addPresenceFilter(geom, index);
    rtcAttachGeometryByID(embree_->surfaces, geom, static_cast<unsigned>(surfaceMeshes_.size()));
    rtcReleaseGeometry(geom);
    throwOnEmbreeError(embree_->device, ("adding mesh " + desc.name).c_str());
    surfaceMeshes_.push_back(index);
    surfaceInstances_.push_back(-1);
    surfacePoints_.push_back(-1);
}

int RenderScene::storePoints(const PointsDesc& desc, const std::vector<MaterialDesc>& materials,
                             std::uint32_t objectName, RTCSceneTy* scene, unsigned geomID) {
    validatePoints(desc);
    const int index = storeMesh(pointShadingMesh(desc), materials, objectName);
    stats_.meshes -= 1;  // its shading mesh is not a surface
    stats_.triangles -= desc.positions.size();
    RTCGeometry geom = pointGeometry(embree_->device, desc);
    rtcAttachGeometryByID(scene, geom, geomID);
    rtcReleaseGeometry(geom);
    throwOnEmbreeError(embree_->device, ("adding points " + desc.name).c_str());
    stats_.pointSets += 1;
    stats_.points += desc.positions.size();
    return index;
}

void RenderScene::addPoints(const PointsDesc& desc, const std::vector<MaterialDesc>& materials) {
    const auto geomID = static_cast<unsigned>(surfaceMeshes_.size());
    const int index = storePoints(desc, materials, objectNames_.add(desc.name), embree_->surfaces, geomID);
    surfaceMeshes_.push_back(-1);
    surfaceInstances_.push_back(-1);
    surfacePoints_.push_back(index);
}

void RenderScene::storeCurves(CurveGeometry& geometry, const CurvesDesc& desc,
                              const std::vector<MaterialDesc>& materials, std::uint32_t objectName, RTCSceneTy* scene,
                              unsigned geomID) {
    const std::uint32_t materialName = desc.material >= 0 && desc.material < static_cast<int>(materials.size())
                                           ? materialNames_.add(materials[static_cast<std::size_t>(desc.material)].name)
                                           : kNoName;
    geometry.add(embree_->device, scene, geomID, desc, materials, shaders_, objectName, materialName);
    throwOnEmbreeError(embree_->device, ("adding curves " + desc.name).c_str());
    stats_.curves += 1;
    stats_.curveSegments += desc.segments.size();
}

void RenderScene::addCurves(const CurvesDesc& desc, const std::vector<MaterialDesc>& materials) {
    storeCurves(curves_, desc, materials, objectNames_.add(desc.name), embree_->surfaces,
                static_cast<unsigned>(surfaceMeshes_.size()));
    surfaceMeshes_.push_back(-1);
    surfaceInstances_.push_back(-1);
    surfacePoints_.push_back(-1);
}

void RenderScene::addPrototypes(const SceneDescription& scene) {
    for (const PrototypeDesc& desc : scene.prototypes) {
        Prototype proto;
        RTCScene rtcScene = rtcNewScene(embree_->device);
        embree_->prototypes.push_back(rtcScene);
        rtcSetSceneBuildQuality(rtcScene, RTC_BUILD_QUALITY_HIGH);
        rtcSetSceneFlags(rtcScene, RTC_SCENE_FLAG_ROBUST);
        for (std::size_t i = 0; i < desc.meshes.size(); ++i) {
            const MeshDesc& meshDesc = desc.meshes[i];
            if (emits(meshDesc, scene.materials)) {
                proto.emissiveMeshes.push_back({static_cast<int>(i), surfaceArea(meshDesc), nullptr});
                continue;
            }
            int index = storeMesh(meshDesc, scene.materials, kNoName);  // hits are named by their instance
            orientSolid(meshes_[index]);
            const Mesh& mesh = meshes_[index];
            for (const Vec3f& p : mesh.positions) {
                proto.lo = vmin(proto.lo, p);
                proto.hi = vmax(proto.hi, p);
            }
            for (const std::vector<Vec3f>& step : mesh.motionPositions)
                for (const Vec3f& p : step) {
                    proto.lo = vmin(proto.lo, p);
                    proto.hi = vmax(proto.hi, p);
                }
            RTCGeometry geom = triangleGeometry(embree_->device, mesh.positions, mesh.indices, mesh.motionPositions);
            addPresenceFilter(geom, index);
            rtcAttachGeometryByID(rtcScene, geom, static_cast<unsigned>(proto.meshes.size()));
            rtcReleaseGeometry(geom);
            proto.meshes.push_back(index);
            proto.points.push_back(-1);
        }
        // Hits on curves and points are named by their instance, as hits on meshes are.
        for (const CurvesDesc& curves : desc.curves) {
            storeCurves(*proto.curves, curves, scene.materials, kNoName, rtcScene,
                        static_cast<unsigned>(proto.meshes.size()));
            proto.meshes.push_back(-1);
            proto.points.push_back(-1);
        }
        proto.curves->growBounds(proto.lo, proto.hi);
        for (const PointsDesc& points : desc.points) {
            const int index =
                storePoints(points, scene.materials, kNoName, rtcScene, static_cast<unsigned>(proto.meshes.size()));
            // Where the points are at the frame and at each motion step (deforming inside the prototype).
            for (std::size_t s = 0; s <= points.motionPositions.size(); ++s) {
                const std::vector<Vec3f>& at = s == 0 ? points.positions : points.motionPositions[s - 1];
                const std::vector<float>& radii =
                    s == 0 || points.motionRadii.empty() ? points.radii : points.motionRadii[s - 1];
                for (std::size_t i = 0; i < at.size(); ++i) {
                    const Vec3f r(radii.empty() ? 0.0f : radii[i]);
                    proto.lo = vmin(proto.lo, at[i] - r);
                    proto.hi = vmax(proto.hi, at[i] + r);
                }
            }
            proto.meshes.push_back(-1);
            proto.points.push_back(index);
        }
        rtcCommitScene(rtcScene);
        throwOnEmbreeError(embree_->device, ("building prototype " + desc.name).c_str());
        prototypes_.push_back(std::move(proto));
    }
    for (const InstanceDesc& desc : scene.instances) {
        if (desc.prototype < 0 || desc.prototype >= static_cast<int>(prototypes_.size()))
            throw std::invalid_argument("instance of prototype " + std::to_string(desc.prototype) +
                                        ": index out of range");
        Prototype& proto = prototypes_[desc.prototype];
        const std::uint32_t objectName = desc.name.empty() ? kNoName : objectNames_.add(desc.name);
        for (Prototype::EmissiveMesh& emissive : proto.emissiveMeshes) {
            const MeshDesc& local = scene.prototypes[desc.prototype].meshes[emissive.mesh];
            MeshDesc placed = transformMesh(local, desc.transform);
            for (const Matrix4& step : desc.motionTransforms)  // a moving instance: its copy moves with it
                placed.motionPositions.push_back(transformMesh(local, step).positions);
            if (desc.linkGroup != 0) placed.linkGroup = desc.linkGroup;
            if (placed.light && placed.light->normalized)  // per unit of its placed area
                if (const float area = surfaceArea(placed); area > 0.0f) placed.light->radiance *= emissive.area / area;
            addMesh(placed, scene.materials, objectName, emissive.shaping);
            emissive.shaping = meshes_.back().shaping;
        }
        if (proto.meshes.empty()) continue;
        RTCGeometry geom = rtcNewGeometry(embree_->device, RTC_GEOMETRY_TYPE_INSTANCE);
        rtcSetGeometryInstancedScene(geom, embree_->prototypes[desc.prototype]);
        if (desc.motionTransforms.size() == 1)
            throw std::invalid_argument(desc.name + ": motion needs at least two time steps");
        setInstanceTransforms(geom, desc.transform, desc.motionTransforms);
        rtcCommitGeometry(geom);
        rtcAttachGeometryByID(embree_->surfaces, geom, static_cast<unsigned>(surfaceMeshes_.size()));
        rtcReleaseGeometry(geom);
        throwOnEmbreeError(embree_->device, ("adding an instance of " + scene.prototypes[desc.prototype].name).c_str());
        surfaceMeshes_.push_back(-1);
        surfaceInstances_.push_back(static_cast<int>(instances_.size()));
        surfacePoints_.push_back(-1);
        instances_.push_back({desc.prototype, desc.transform, normalMatrixOf(desc.transform), objectName,
                              desc.motionTransforms, desc.linkGroup});
        stats_.instances += 1;
        for (int m : proto.meshes)
            if (m >= 0) stats_.instancedTriangles += meshes_[m].indices.size() / 3;
    }
}

void RenderScene::addLight(const LightDesc& desc) {
    int index = static_cast<int>(lights_.size());
    std::unique_ptr<Light> made = makeLight(desc);
    const LightMotion* motion = nullptr;
    if (!desc.motionTransforms.empty()) {  // sampled where it is at a ray's time (lightAt)
        if (desc.motionTransforms.size() < 2)
            throw std::invalid_argument(desc.name + ": motion needs at least two time steps");
        motion = &lightMotions_.emplace_back(desc.transform, desc.motionTransforms);
        movingLights_.resize(lights_.size() + 1);
        movingLights_.back() = {made.get(), motion, -1};
        const std::optional<LightBounds> still = made->bounds();
        made = std::make_unique<SweptLight>(std::move(made), still ? motion->sweptBounds(*still) : LightBounds{});
    }
    lights_.push_back(std::move(made));
    const Light& light = *lights_.back();
    if (light.atInfinity()) lightsAtInfinity_.push_back(index);
    if (light.atInfinity() && desc.visibleToCamera) lightsAtInfinitySeenByCamera_.push_back(index);
    if (!desc.castsShadows) {
        shadowless_.resize(lights_.size());
        shadowless_[std::size_t(index)] = true;
    }
    const LightSurface surface = light.surface();
    RTCGeometry shape = motion && surface.kind != LightSurface::Kind::None
                            ? movingShapes_.emplace_back(surface, *motion).newGeometry(embree_->device)
                            : lightSurfaceGeometry(embree_->device, surface);  // committed
    if (!shape) return;
    if (surface.kind == LightSurface::Kind::Quad && !motion) {
        rtcSetGeometryUserData(shape, &quadLightFronts_.emplace_back(surface.front));
        rtcSetGeometryIntersectFilterFunction(shape, frontSideFilter);
        rtcCommitGeometry(shape);
    }
    if (surface.kind == LightSurface::Kind::Sphere && !motion) {
        rtcSetGeometryIntersectFilterFunction(shape, outerSideFilter);
        rtcCommitGeometry(shape);
    }
    rtcAttachGeometryByID(embree_->lightShapes, shape, static_cast<unsigned>(lightShapeToLight_.size()));
    rtcReleaseGeometry(shape);
    lightShapeToLight_.push_back(index);
    lightShapeNames_.push_back(objectNames_.add(desc.name));
    throwOnEmbreeError(embree_->device, ("adding light " + desc.name).c_str());
}

std::optional<SurfaceHit> RenderScene::intersect(const Ray& ray) const { return shade(trace(ray), ray); }

TracedHit RenderScene::trace(const Ray& ray) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit surface, shape;
    storeRayHit(surface, ray.origin, ray.direction, ray.tMin, ray.tMax, ray.time);
    rtcIntersect1(embree_->surfaces, &context, &surface);

    shape.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    const bool nearLightShapes =
        !lightShapeToLight_.empty() && segmentMeetsBox(ray.origin, ray.direction, ray.tMin, surface.ray.tfar,
                                                       embree_->lightShapesLo, embree_->lightShapesHi);
    if (nearLightShapes) {
        storeRayHit(shape, ray.origin, ray.direction, ray.tMin, surface.ray.tfar, ray.time);
        rtcIntersect1(embree_->lightShapes, &context, &shape);
    }

    TracedHit traced;
    traced.lightShape = shape.hit.geomID != RTC_INVALID_GEOMETRY_ID;
    const RTCRayHit& met = traced.lightShape ? shape : surface;
    if (met.hit.geomID == RTC_INVALID_GEOMETRY_ID) return traced;
    traced.geomID = met.hit.geomID;
    traced.primID = met.hit.primID;
    traced.instID = met.hit.instID[0];
    traced.u = met.hit.u;
    traced.v = met.hit.v;
    traced.t = met.ray.tfar;
    traced.ng = Vec3f(met.hit.Ng_x, met.hit.Ng_y, met.hit.Ng_z);
    return traced;
}

std::optional<SurfaceHit> RenderScene::shade(const TracedHit& traced, const Ray& ray) const {
    if (!traced.met()) return std::nullopt;
    if (traced.lightShape) return shadeLightShape(traced.geomID, ray, traced.t, traced.ng);
    const float u = traced.u, v = traced.v, t = traced.t;
    const unsigned geomID = traced.geomID, primID = traced.primID;
    if (traced.instID == TracedHit::kNone && curves_.contains(geomID))
        return curves_.shade(geomID, primID, u, ray, t, traced.ng);
    if (traced.instID == TracedHit::kNone && surfacePoints_[geomID] >= 0) {
        std::optional<SurfaceHit> hit = shadeMesh(surfacePoints_[geomID], primID, 0.0f, 0.0f, t, -1, ray);
        placeOnPoint(*hit, ray, t, traced.ng);
        return hit;
    }
    if (traced.instID == TracedHit::kNone) return shadeMesh(surfaceMeshes_[geomID], primID, u, v, t, -1, ray);
    const int instance = surfaceInstances_[traced.instID];
    const Prototype& proto = prototypes_[instances_[instance].prototype];
    const Vec3f& ng = traced.ng;  // Embree gives an instanced geometry's normal in the prototype's space
    if (proto.curves->contains(geomID))
        return shadeInstancedCurve(*proto.curves, instance, geomID, primID, u, ray, t, ng);
    if (const int points = proto.points[geomID]; points >= 0) {
        std::optional<SurfaceHit> hit = shadeMesh(points, primID, 0.0f, 0.0f, t, instance, ray);
        std::optional<Instance> moved;
        placeOnPoint(*hit, ray, t,
                     Vec3f(instanceAt(instance, ray.time, moved)->normalToWorld.transformVector(Vec3d(ng))));
        return hit;
    }
    return shadeMesh(proto.meshes[geomID], primID, u, v, t, instance, ray);
}

std::optional<SurfaceHit> RenderScene::shadeInstancedCurve(const CurveGeometry& curves, int instanceIndex,
                                                           unsigned geomID, unsigned primID, float u, const Ray& ray,
                                                           float t, const Vec3f& ng) const {
    std::optional<Instance> moved;
    const Instance& instance = *instanceAt(instanceIndex, ray.time, moved);
    // Shaded on the prototype's curve with the ray in prototype space (its direction not
    // normalised, so that t stays the world ray's), then moved to world space.
    const std::optional<Matrix4> toPrototype = instance.toWorld.inverse();
    if (!toPrototype) return std::nullopt;
    Ray local = ray;
    local.origin = Vec3f(toPrototype->transformPoint(Vec3d(ray.origin)));
    local.direction = Vec3f(toPrototype->transformVector(Vec3d(ray.direction)));
    std::optional<SurfaceHit> hit = curves.shade(geomID, primID, u, local, t, ng);
    auto normalToWorld = [&](const Vec3f& n) {
        const Vec3f world(instance.normalToWorld.transformVector(Vec3d(n)));
        return lengthSquared(world) > 0.0f ? normalize(world) : n;
    };
    hit->point = ray.origin + ray.direction * t;
    hit->geometricNormal = hit->shadingNormal = normalToWorld(hit->geometricNormal);
    const Vec3f tangent(instance.toWorld.transformVector(Vec3d(hit->tangent)));
    if (lengthSquared(tangent) > 0.0f) hit->tangent = normalize(tangent);
    // The side of the axis the ray met, measured in world space: a mirroring placement flips it.
    if (instance.toWorld.determinant3x3() < 0.0) hit->material.hair->offset = -hit->material.hair->offset;
    hit->time = ray.time;
    hit->instance = instanceIndex;
    hit->objectName = instance.objectName;
    if (instance.linkGroup != 0) hit->linkGroup = instance.linkGroup;
    return hit;
}

// The hit's record is never a default-constructed std::optional: libstdc++ 12's default
// constructor zeroes the whole storage (a union's padding), 332 bytes per hit, which took a third
// of this function's time in perf. Each arm of newMeshHit's conditional initialises it in place,
// and it is returned as it is (no copy of the large record).
std::optional<SurfaceHit> RenderScene::shadeMesh(int meshIndex, unsigned primID, float u, float v, float t,
                                                 int instanceIndex, const Ray& ray) const {
    const Mesh& mesh = meshes_[meshIndex];
    const std::size_t corner = 3 * std::size_t(primID);
    const Triangle corners = triangleAt(mesh, primID, ray.time);
    const float w = 1.0f - u - v;
    std::optional<SurfaceHit> result = newMeshHit(mesh);
    SurfaceHit& hit = *result;
    hit.t = t;
    hit.time = ray.time;
    hit.mesh = meshIndex;
    hit.instance = instanceIndex;
    hit.linkGroup = mesh.linkGroup;
    hit.triangle = primID;
    hit.b1 = u;
    hit.b2 = v;
    hit.point = corners.p0 * w + corners.p1 * u + corners.p2 * v;
    Vec3f e1 = corners.p1 - corners.p0, e2 = corners.p2 - corners.p0;
    const Vec3f ng = cross(e1, e2);
    // Stored from a local into both: copying the one member into the other read back 8 bytes of two
    // 4-byte stores in flight, which the processor cannot forward (a stall on every hit).
    const Vec3f unitNormal = mesh.unitNormals.empty() ? unitTriangleNormal(ng) : mesh.unitNormals[primID];
    hit.geometricNormal = unitNormal;
    hit.shadingNormal = unitNormal;
    if (!mesh.cornerNormals.empty()) {
        const Vec3f n =
            mesh.cornerNormals[corner] * w + mesh.cornerNormals[corner + 1] * u + mesh.cornerNormals[corner + 2] * v;
        if (lengthSquared(n) > 0.0f) hit.shadingNormal = normalize(n);
    }
    hit.objectName = mesh.objectName;
    if (instanceIndex >= 0) placeInWorld(hit, instanceIndex, e1, e2);
    if (mesh.reflects) shadeMaterial(mesh, hit, corner, w, u, v, e1, e2);
    // A mesh light's front is its triangles' own side (emissive meshes are never instanced: ng is
    // in world space). A camera ray sees a mesh light whose material responds (materialSyncMode
    // other than noMaterialResponse) as its material shades it, as Arnold's light_visible off,
    // hdPrman and Storm show it (docs/USDLUX.md): no emission, no light. Under noMaterialResponse
    // there is no material to see, and the camera sees the light itself, as it sees a canonical light.
    const bool lightSeen = !(mesh.meshLight && mesh.reflects && ray.fromCamera);
    const bool seesEmission = lightSeen && (mesh.emittingSides == EmittingSides::Both || meetsFront(ray.direction, ng));
    if (dot(hit.shadingNormal, hit.geometricNormal) < 0.0f) hit.geometricNormal = -hit.geometricNormal;
    hit.emission = !seesEmission           ? RGB(0.0f)
                   : mesh.texturedEmission ? mesh.texturedEmission->at(primID, u, v)
                                           : mesh.emission;
    // A shaped mesh light's surface is seen shaped, as its triangles' light samples are: its
    // triangle's light gives the emission, in the shaping frame it holds (where it is at the ray's
    // time; a moving mesh's lightAt builds that light, frame included, per call). A mesh whose
    // emission is black has no triangle lights (firstLight -1) and stays black.
    if (mesh.shaping && seesEmission && mesh.firstLight >= 0 && lengthSquared(ng) > 0.0f)
        hit.emission = lightAt(std::size_t(mesh.firstLight) + primID, ray.time)
                           .emitted({hit.point, hit.geometricNormal}, -ray.direction);
    hit.interior =
        mesh.reflects && mesh.material >= 0 ? materialInterior_[static_cast<std::size_t>(mesh.material)] : -1;
    hit.light = mesh.firstLight >= 0 && lightSeen ? mesh.firstLight + static_cast<int>(primID) : -1;
    hit.materialName = mesh.materialName;
    return result;
}

std::optional<SurfaceHit> RenderScene::newMeshHit(const Mesh& mesh) const {
    return !mesh.reflects       ? std::optional<SurfaceHit>(std::in_place, lambertianParams(RGB(0.0f)))
           : mesh.material >= 0 ? std::optional<SurfaceHit>(std::in_place, materials_[std::size_t(mesh.material)])
                                : std::optional<SurfaceHit>(std::in_place, lambertianParams(mesh.diffuse));
}

void RenderScene::placeInWorld(SurfaceHit& hit, int instanceIndex, Vec3f& e1, Vec3f& e2) const {
    std::optional<Instance> moved;  // only made for a moving instance (instanceAt)
    const Instance& instance = *instanceAt(instanceIndex, hit.time, moved);
    auto normalToWorld = [&](const Vec3f& n) {
        Vec3f world(instance.normalToWorld.transformVector(Vec3d(n)));
        return lengthSquared(world) > 0.0f ? normalize(world) : n;
    };
    hit.point = Vec3f(instance.toWorld.transformPoint(Vec3d(hit.point)));
    hit.geometricNormal = normalToWorld(hit.geometricNormal);
    hit.shadingNormal = normalToWorld(hit.shadingNormal);
    e1 = Vec3f(instance.toWorld.transformVector(Vec3d(e1)));
    e2 = Vec3f(instance.toWorld.transformVector(Vec3d(e2)));
    if (instance.linkGroup != 0) hit.linkGroup = instance.linkGroup;
    hit.objectName = instance.objectName;
}

void RenderScene::shadeMaterial(const Mesh& mesh, SurfaceHit& hit, std::size_t corner, float w, float u, float v,
                                const Vec3f& e1, const Vec3f& e2) const {
    if (!mesh.cornerColors.empty())
        hit.material.diffuse =
            mesh.cornerColors[corner] * w + mesh.cornerColors[corner + 1] * u + mesh.cornerColors[corner + 2] * v;
    if (mesh.material < 0) return;
    if (!shaders_[mesh.material].hasBindings()) {
        // The authored parameters, unless vertex colours changed them: the BSDF made with the scene
        // is the hit's (render/material_tables.h).
        if (mesh.cornerColors.empty()) hit.bsdf = &materialBsdfs_[std::size_t(mesh.material)];
        return;
    }
    ShadingPatch patch{corner, w, u, v, e1, e2, {}};
    if (filterCamera_)
        patch.footprint = pixelFootprint(hit.point, hit.geometricNormal, filterCamera_->position(),
                                         filterCamera_->pixelsPerUnitAt(hit.point));
    Vec3f mapped = hit.shadingNormal;
    shaders_[mesh.material].evaluate(patch, mesh.slots.data(), hit.material, mapped, hit.tangent);
    // A normal map may not tip the shading normal across the surface.
    if (dot(mapped, hit.geometricNormal) * dot(hit.shadingNormal, hit.geometricNormal) > 0.0f)
        hit.shadingNormal = mapped;
}

int RenderScene::primvarAt(const SurfaceHit& hit, const std::string& name, float out[4]) const {
    if (hit.mesh < 0) return 0;
    for (const CornerPrimvar& pv : meshes_[static_cast<std::size_t>(hit.mesh)].primvars) {
        if (pv.name != name) continue;
        const std::size_t k = static_cast<std::size_t>(pv.components);
        const float* corner = pv.values.data() + 3 * std::size_t(hit.triangle) * k;
        const float w = 1.0f - hit.b1 - hit.b2;
        for (std::size_t c = 0; c < k; ++c)
            out[c] = w * corner[c] + hit.b1 * corner[k + c] + hit.b2 * corner[2 * k + c];
        return pv.components;
    }
    return 0;
}

std::optional<SurfaceHit> RenderScene::shadeLightShape(unsigned geomID, const Ray& ray, float t,
                                                       const Vec3f& ng) const {
    std::optional<SurfaceHit> result(std::in_place);
    SurfaceHit& hit = *result;
    hit.t = t;
    hit.time = ray.time;
    hit.point = ray.origin + ray.direction * t;
    hit.geometricNormal = lengthSquared(ng) > 0.0f ? normalize(ng) : -ray.direction;
    hit.shadingNormal = hit.geometricNormal;
    hit.light = lightShapeToLight_[geomID];
    hit.lightShape = true;
    hit.objectName = lightShapeNames_[geomID];
    return result;
}

bool RenderScene::occluded(const Vec3f& origin, const Vec3f& direction, float distance, float time) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay r;
    storeRay(r, origin, direction, 0.0f, distance * (1.0f - kShadowRayShortening), time);
    rtcOccluded1(embree_->surfaces, &context, &r);
    return r.tfar < 0.0f;
}

bool RenderScene::meetsOtherLightShape(int light, const Vec3f& origin, const Vec3f& direction, float distance,
                                       float time) const {
    const float end = distance * (1.0f - kShadowRayShortening);
    if (lightShapeToLight_.empty() || (light >= 0 && light == embree_->lightOfEveryShape) ||
        !segmentMeetsBox(origin, direction, 0.0f, end, embree_->lightShapesLo, embree_->lightShapesHi))
        return false;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    // `light`'s own shape is stepped over (a ray meets a closed shape at most twice).
    for (float start = 0.0f; start < end;) {
        RTCRayHit shape;
        storeRayHit(shape, origin, direction, start, end, time);
        rtcIntersect1(embree_->lightShapes, &context, &shape);
        if (shape.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
        if (lightShapeToLight_[shape.hit.geomID] != light) return true;
        start = std::nextafter(shape.ray.tfar, std::numeric_limits<float>::infinity());
    }
    return false;
}

}  // namespace fluence::render

namespace fluence::render {

RenderScene::Triangle RenderScene::triangleAt(const Mesh& mesh, unsigned triangle, float time) const {
    const std::uint32_t* corner = &mesh.indices[3 * std::size_t(triangle)];
    if (mesh.motionPositions.empty())
        return {mesh.positions[corner[0]], mesh.positions[corner[1]], mesh.positions[corner[2]]};
    return {positionAt(mesh.motionPositions, corner[0], time), positionAt(mesh.motionPositions, corner[1], time),
            positionAt(mesh.motionPositions, corner[2], time)};
}

TriangleLight RenderScene::triangleLight(const Mesh& mesh, std::string name, const Triangle& c, unsigned triangle) {
    TriangleLight light = mesh.texturedEmission
                              ? TriangleLight(std::move(name), c.p0, c.p1, c.p2, *mesh.texturedEmission, triangle)
                              : TriangleLight(std::move(name), c.p0, c.p1, c.p2, mesh.emission, mesh.emittingSides);
    if (mesh.shaping) light.shape(*mesh.shaping, mesh.shapingToWorld);
    return light;
}

std::unique_ptr<TriangleLight> RenderScene::triangleLight(const Mesh& mesh, const std::vector<Vec3f>& positions,
                                                          unsigned triangle) const {
    const std::uint32_t* corner = &mesh.indices[3 * std::size_t(triangle)];
    return std::make_unique<TriangleLight>(
        triangleLight(mesh, mesh.name, {positions[corner[0]], positions[corner[1]], positions[corner[2]]}, triangle));
}

LightAtTime RenderScene::lightAt(std::size_t i, float time) const {
    if (i >= movingLights_.size()) return LightAtTime(*lights_[i]);
    const MovingLight& moving = movingLights_[i];
    if (moving.motion) return LightAtTime(*moving.frame, moving.motion->at(time));
    if (moving.mesh < 0) return LightAtTime(*lights_[i]);
    // The triangle where its mesh is at `time`, made for the call (unnamed: the scene's light(i) has the name).
    const Mesh& mesh = meshes_[static_cast<std::size_t>(moving.mesh)];
    const auto triangle = static_cast<unsigned>(static_cast<int>(i) - mesh.firstLight);
    return LightAtTime(triangleLight(mesh, {}, triangleAt(mesh, triangle, time), triangle));
}

const RenderScene::Instance* RenderScene::instanceAt(int index, float time, std::optional<Instance>& moved) const {
    if (index < 0) return nullptr;
    const Instance& instance = instances_[static_cast<std::size_t>(index)];
    if (instance.motionTransforms.empty()) return &instance;
    const Matrix4 toWorld = transformAt(instance.motionTransforms, time);
    moved.emplace(
        Instance{instance.prototype, toWorld, normalMatrixOf(toWorld), instance.objectName, {}, instance.linkGroup});
    return &*moved;
}

Vec3f RenderScene::pointAt(const SurfaceHit& hit, float time) const {
    if (hit.curveGeometry >= 0) {
        const auto geomID = static_cast<unsigned>(hit.curveGeometry);
        return hit.point + curves_.centreAt(geomID, hit.triangle, hit.b1, time) -
               curves_.centreAt(geomID, hit.triangle, hit.b1, hit.time);
    }
    if (hit.mesh < 0) return hit.point;
    const Triangle corners = triangleAt(meshes_[static_cast<std::size_t>(hit.mesh)], hit.triangle, time);
    const Vec3f p = corners.p0 * (1.0f - hit.b1 - hit.b2) + corners.p1 * hit.b1 + corners.p2 * hit.b2;
    std::optional<Instance> moved;
    const Instance* instance = instanceAt(hit.instance, time, moved);
    return instance ? Vec3f(instance->toWorld.transformPoint(Vec3d(p))) : p;
}

}  // namespace fluence::render
