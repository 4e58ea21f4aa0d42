// Lights: the interface every emitter in the render core implements.
//
// Conventions (all quantities in world space, radiance in the rendering space):
//   sample(p, u)       picks a direction wi from reference point p towards the light; returns
//                      the radiance Li arriving at p along -wi (before visibility), the distance
//                      to the light (infinity for lights at infinity) and the density of wi in
//                      solid angle. Delta lights, which no ray can hit, set `delta` and pdf = 1,
//                      and Li is then irradiance on a surface facing wi: exactly for a distant
//                      light of angle 0 and a point light (SphereLight treatAsPoint), and as a
//                      one-sample estimate over the line for a line light (treatAsLine).
//   pdf(p, wi, hit)    the solid-angle density sample() picks wi with, for a ray from p that
//                      reached the light at `hit` (hit.point/normal ignored by lights at infinity);
//                      0 for delta lights.
//   emitted(hit, wo)   radiance leaving the light's surface at `hit` towards wo.
//   escaped(dir)       radiance from a light at infinity along a ray that left the scene in dir.
//   power(bounds)      approximate emitted power (luminance-weighted), used to choose which
//                      light to sample.
//   bounds()           where and in which directions a light not at infinity emits, for the
//                      light tree (render/light_tree.h); nullopt for lights at infinity.
//   name()             the light's prim path, given to the base's constructor.
//   constantRadiance() whether the light is at infinity and sends the same radiance from every
//                      direction (a dome without texture): BSDF and phase sampling are then its
//                      ideal importance samplers, and next-event estimation may leave it to them
//                      (render/dome_light_sampling.h).
// Lights at infinity (distant, dome) derive from InfiniteLight (render/lights/infinite_light.h),
// which answers atInfinity(), bounds() and hasEmissionSampling() for them.
//   surface()          the surface camera and BSDF rays can hit, which RenderScene puts in the
//                      ray-tracing scene (LightSurface); none for lights at infinity, delta
//                      lights and emissive mesh triangles (their mesh is in the scene already).
//   isSurfaceEmitter() whether the light is a triangle of an emissive mesh (an object that emits,
//                      render/lights/triangle_light.h) rather than a UsdLux light.
//   sampleEmission(uPosition, uDirection, scene)  emission sampling, for light subpaths (bdpt):
//                      a point on the light and a direction light leaves it in, with the
//                      radiance carried (EmissionSample); emissionDensity(point, direction, scene)
//                      the densities it draws them with. hasEmissionSampling() says whether a
//                      light offers them (default: no).
// Each light lives in one file pair of render/lights/ (its sampling and emission together); lights
// described by a LightDesc are made by the table in render/lights/light_registry.cpp.
// Every light's sample/pdf pair is checked by the chi-square and consistency tests in
// tests/render/light*_test.cpp.
#pragma once

#include <array>
#include <limits>
#include <optional>
#include <string>
#include <utility>

#include "core/rgb.h"

namespace fluence::render {

struct LightSample {
    RGB Li;
    Vec3f wi;
    float distance = std::numeric_limits<float>::infinity();
    float pdf = 0.0f;
    bool delta = false;
};

struct LightHit {
    Vec3f point;
    Vec3f normal;  // geometric normal of the light surface at the hit
};

struct SceneBounds {
    Vec3f centre;
    float radius = 1.0f;
};

// A conservative bound on a light's emission (Conty Estevez & Kulla 2018): every emitting point
// lies in the box [lo, hi]; every emitting surface normal lies within theta_o of `axis`, and
// light leaves at most theta_e away from its normal. Light that leaves in a cone of directions
// (a shaped point light) has theta_o = the cone and theta_e = 0. Each angle is kept as its cosine.
struct LightBounds {
    Vec3f lo, hi;
    float phi = 0.0f;  // power, as power() returns it; a shaped light's unshaped power times the
                       // shaping's peak factor (LightShaping::narrow)
    Vec3f axis{0.0f, 0.0f, 1.0f};
    float cosThetaO = -1.0f;  // -1: normals in every direction
    float cosThetaE = 0.0f;   // 0: up to 90 degrees from the normal (a cosine emitter)
    bool twoSided = false;    // also emits from the back of each normal (emissive triangles)
};

// Densities of Light::sampleEmission: of the point, per unit area (per unit area of the disk for
// a light at infinity; 1 for a point light, a delta), and of the direction, per unit solid
// angle (1 for a delta distant light); and `cosine`, |cos| between the light's normal at the point
// and the direction (1 for lights without a surface).
struct EmissionDensity {
    float position = 0.0f;
    float direction = 0.0f;
    float cosine = 1.0f;
};

// A point and direction drawn by Light::sampleEmission. For a light at infinity the point lies on
// a disk of the scene's bounding radius, outside the scene and facing `direction`, and `Le` is
// the radiance along it (the irradiance for a delta distant light); for a point light `Le` is the
// intensity towards `direction`.
struct EmissionSample {
    Vec3f point;
    Vec3f direction;  // unit, the way light leaves
    Vec3f normal;     // of the light's surface at `point` (for lights without one, `direction`)
    RGB Le;
    EmissionDensity density;  // with the cosine at the light
    bool delta = false;       // a point light or an angle-0 distant light, which no ray can hit
};

class AnalyticLightShape;  // render/light_shape.h

// The surface of a light that camera and BSDF rays can hit (Light::surface): none, a quad (corners
// counter-clockwise seen from behind, as RectLight::corners), a sphere, or a shape RenderScene
// traces as Embree user geometry through its exact intersection (render/light_shape.h).
struct LightSurface {
    enum class Kind { None, Quad, Sphere, Analytic };
    Kind kind = Kind::None;
    std::array<Vec3f, 4> corners{};             // Quad
    Vec3f front;                                // Quad: its emitting direction (rays along it meet its back)
    Vec3f centre;                               // Sphere
    float radius = 0.0f;                        // Sphere
    const AnalyticLightShape* shape = nullptr;  // Analytic

    static LightSurface quad(const std::array<Vec3f, 4>& corners, const Vec3f& front) {
        return {Kind::Quad, corners, front, {}, 0.0f, nullptr};
    }
    static LightSurface sphere(const Vec3f& centre, float radius) {
        return {Kind::Sphere, {}, {}, centre, radius, nullptr};
    }
    static LightSurface analytic(const AnalyticLightShape& shape) { return {Kind::Analytic, {}, {}, {}, 0.0f, &shape}; }
};

class Light {
public:
    explicit Light(std::string name) : name_(std::move(name)) {}
    virtual ~Light() = default;

    virtual std::optional<LightSample> sample(const Vec3f& p, Vec2f u) const = 0;
    virtual float pdf(const Vec3f& p, const Vec3f& wi, const LightHit& hit) const = 0;
    virtual RGB emitted(const LightHit& hit, const Vec3f& wo) const { return RGB(0.0f); }
    virtual bool atInfinity() const { return false; }
    virtual RGB escaped(const Vec3f& direction) const { return RGB(0.0f); }
    virtual bool constantRadiance() const { return false; }
    virtual float power(const SceneBounds& bounds) const = 0;
    virtual std::optional<LightBounds> bounds() const = 0;
    // The light's prim path (an emissive triangle's: its mesh's), for warnings and light path expressions.
    const std::string& name() const { return name_; }
    virtual LightSurface surface() const { return {}; }
    virtual bool isSurfaceEmitter() const { return false; }
    virtual bool hasEmissionSampling() const { return false; }
    virtual std::optional<EmissionSample> sampleEmission(Vec2f /*uPosition*/, Vec2f /*uDirection*/,
                                                         const SceneBounds& /*scene*/) const {
        return std::nullopt;
    }
    virtual EmissionDensity emissionDensity(const Vec3f& /*point*/, const Vec3f& /*direction*/,
                                            const SceneBounds& /*scene*/) const {
        return {};
    }

private:
    std::string name_;
};

}  // namespace fluence::render
