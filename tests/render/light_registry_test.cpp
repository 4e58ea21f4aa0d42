// The light table (render/lights/light_registry.h): every LightType has a row, each description
// makes the light it names, isDeltaLight agrees with the delta flag of the light's own samples,
// and only emissive mesh triangles are surface emitters.
#include <gtest/gtest.h>

#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "render/lights/light_registry.h"
#include "render/lights/triangle_light.h"

namespace fluence::render {
namespace {

LightDesc descOf(LightType type) {
    LightDesc d;
    d.name = "/light";
    d.type = type;
    d.radiance = RGB(2.0f);
    d.angleDegrees = 1.0f;                                                      // Distant: a disk, not a delta light
    d.transform = Matrix4::translate({0.0, 3.0, 0.0}) * Matrix4::rotateX(-90);  // emitting downwards (-Y)
    return d;
}

// Whether the light's sample towards a point below it is a delta sample.
bool samplesDelta(const Light& light) {
    std::optional<LightSample> s = light.sample(Vec3f(0.1f, 0.0f, 0.2f), Vec2f(0.3f, 0.6f));
    EXPECT_TRUE(s.has_value()) << light.name();
    return s && s->delta;
}

TEST(LightRegistry, EveryTypeMakesALightWhoseDeltaFlagIsKnownBeforehand) {
    std::vector<LightDesc> descs;
    for (LightType type : {LightType::Rect, LightType::Disk, LightType::Sphere, LightType::Cylinder, LightType::Distant,
                           LightType::Dome})
        descs.push_back(descOf(type));
    LightDesc point = descOf(LightType::Sphere), line = descOf(LightType::Cylinder), sun = descOf(LightType::Distant);
    point.treatAsPoint = true;
    line.treatAsLine = true;
    sun.angleDegrees = 0.0f;
    descs.insert(descs.end(), {point, line, sun});
    int deltas = 0;
    for (const LightDesc& d : descs) {
        std::unique_ptr<Light> light = makeLight(d);
        ASSERT_NE(light, nullptr);
        EXPECT_EQ(light->name(), d.name);
        EXPECT_EQ(isDeltaLight(d), samplesDelta(*light)) << "type " << static_cast<int>(d.type);
        EXPECT_FALSE(light->isSurfaceEmitter());
        deltas += isDeltaLight(d);
    }
    EXPECT_EQ(deltas, 3);
}

TEST(LightRegistry, SurfacesMatchWhatRaysCanHit) {
    EXPECT_EQ(makeLight(descOf(LightType::Rect))->surface().kind, LightSurface::Kind::Quad);
    EXPECT_EQ(makeLight(descOf(LightType::Disk))->surface().kind, LightSurface::Kind::Analytic);
    EXPECT_EQ(makeLight(descOf(LightType::Sphere))->surface().kind, LightSurface::Kind::Sphere);
    EXPECT_EQ(makeLight(descOf(LightType::Cylinder))->surface().kind, LightSurface::Kind::Analytic);
    EXPECT_EQ(makeLight(descOf(LightType::Distant))->surface().kind, LightSurface::Kind::None);
    EXPECT_EQ(makeLight(descOf(LightType::Dome))->surface().kind, LightSurface::Kind::None);
    LightDesc point = descOf(LightType::Sphere);
    point.treatAsPoint = true;
    EXPECT_EQ(makeLight(point)->surface().kind, LightSurface::Kind::None);
}

TEST(LightRegistry, OnlyMeshTrianglesAreSurfaceEmitters) {
    TriangleLight triangle("/mesh", {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, RGB(1.0f));
    EXPECT_TRUE(triangle.isSurfaceEmitter());
    EXPECT_EQ(triangle.surface().kind, LightSurface::Kind::None);
}

TEST(LightRegistry, ATypeWithoutARowIsRefused) {
    LightDesc d = descOf(static_cast<LightType>(99));
    EXPECT_THROW(makeLight(d), std::invalid_argument);
    EXPECT_THROW(isDeltaLight(d), std::invalid_argument);
}

}  // namespace
}  // namespace fluence::render
