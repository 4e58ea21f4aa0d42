// render/embree_ray.h: storeRay and storeRayHit write every field Embree reads, with the values
// the field-by-field form wrote (time 0, all mask bits, id and flags 0) and an empty hit; and a
// ray so written hits what it should.
#include <gtest/gtest.h>

#include <embree3/rtcore.h>

#include <algorithm>
#include <cstring>

#include "render/embree_ray.h"

namespace fluence::render {
namespace {

TEST(EmbreeRay, StoreRayWritesEveryFieldEmbreeReads) {
    RTCRayHit h;
    std::memset(&h, 0xAB, sizeof h);  // garbage, as on the stack
    storeRayHit(h, Vec3f(1.0f, -2.0f, 3.5f), Vec3f(0.0f, 0.6f, -0.8f), 0.25f, 7.0f);
    EXPECT_EQ(h.ray.org_x, 1.0f);
    EXPECT_EQ(h.ray.org_y, -2.0f);
    EXPECT_EQ(h.ray.org_z, 3.5f);
    EXPECT_EQ(h.ray.tnear, 0.25f);
    EXPECT_EQ(h.ray.dir_x, 0.0f);
    EXPECT_EQ(h.ray.dir_y, 0.6f);
    EXPECT_EQ(h.ray.dir_z, -0.8f);
    EXPECT_EQ(h.ray.time, 0.0f);
    EXPECT_EQ(h.ray.tfar, 7.0f);
    EXPECT_EQ(h.ray.mask, 0xffffffffu);
    EXPECT_EQ(h.ray.id, 0u);
    EXPECT_EQ(h.ray.flags, 0u);
    EXPECT_EQ(h.hit.geomID, RTC_INVALID_GEOMETRY_ID);
    EXPECT_EQ(h.hit.instID[0], RTC_INVALID_GEOMETRY_ID);
}

TEST(EmbreeRay, StoredRaysHitAndMissAsTheyShould) {
    RTCDevice device = rtcNewDevice(nullptr);
    RTCScene scene = rtcNewScene(device);
    RTCGeometry quad = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);  // z = 0, [-1, 1]^2
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(quad, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 12, 4));
    const float corners[12] = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0};
    std::copy(corners, corners + 12, v);
    auto* index =
        static_cast<unsigned*>(rtcSetNewGeometryBuffer(quad, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 12, 2));
    const unsigned triangles[6] = {0, 1, 2, 0, 2, 3};
    std::copy(triangles, triangles + 6, index);
    rtcCommitGeometry(quad);
    rtcAttachGeometry(scene, quad);
    rtcReleaseGeometry(quad);
    rtcCommitScene(scene);
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);

    RTCRayHit h;
    storeRayHit(h, Vec3f(0.2f, 0.3f, 2.0f), Vec3f(0.0f, 0.0f, -1.0f), 0.0f, 10.0f);
    rtcIntersect1(scene, &context, &h);
    EXPECT_NE(h.hit.geomID, RTC_INVALID_GEOMETRY_ID);
    EXPECT_NEAR(h.ray.tfar, 2.0f, 1e-6f);
    storeRayHit(h, Vec3f(0.2f, 0.3f, 2.0f), Vec3f(0.0f, 0.0f, -1.0f), 0.0f, 1.5f);  // stops short
    rtcIntersect1(scene, &context, &h);
    EXPECT_EQ(h.hit.geomID, RTC_INVALID_GEOMETRY_ID);

    RTCRay r;
    storeRay(r, Vec3f(0.2f, 0.3f, 2.0f), Vec3f(0.0f, 0.0f, -1.0f), 0.0f, 3.0f);
    rtcOccluded1(scene, &context, &r);
    EXPECT_LT(r.tfar, 0.0f) << "occluded";
    storeRay(r, Vec3f(2.0f, 0.3f, 2.0f), Vec3f(0.0f, 0.0f, -1.0f), 0.0f, 3.0f);  // beside the quad
    rtcOccluded1(scene, &context, &r);
    EXPECT_EQ(r.tfar, 3.0f) << "clear";
    rtcReleaseScene(scene);
    rtcReleaseDevice(device);
}

}  // namespace
}  // namespace fluence::render
