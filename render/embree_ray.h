// Writing a ray into Embree 3's RTCRay / RTCRayHit for rtcIntersect1 and rtcOccluded1.
//
// Embree reads the ray with 16-byte loads: (org_x, org_y, org_z, tnear), (dir_x, dir_y, dir_z,
// time), (tfar, mask, id, flags). A load cannot be forwarded from several narrower stores still in
// flight, so a ray written field by field stalls each call until those stores retire (in profiles
// of the Cornell box this was the largest self cost of RenderScene::intersect,
// bench/results/2026-11-27-throughput-s6.md). These write each group as one 16-byte store.
// Conventions: the ray's time (0 unless given), every mask bit set, id and flags 0; storeRayHit also marks the hit empty
// (geomID and instID[0] invalid), as Embree requires; the other hit fields are left for Embree.
#pragma once

#include <embree3/rtcore.h>
#include <immintrin.h>

#include <bit>
#include <cstddef>

#include "core/vec.h"

namespace fluence::render {

inline void storeRay(RTCRay& r, const Vec3f& origin, const Vec3f& direction, float tNear, float tFar,
                     float time = 0.0f) {
    static_assert(offsetof(RTCRay, tnear) == 12 && offsetof(RTCRay, time) == 28 && offsetof(RTCRay, flags) == 44);
    _mm_store_ps(&r.org_x, _mm_setr_ps(origin.x, origin.y, origin.z, tNear));
    _mm_store_ps(&r.dir_x, _mm_setr_ps(direction.x, direction.y, direction.z, time));
    _mm_store_ps(&r.tfar, _mm_castsi128_ps(_mm_setr_epi32(std::bit_cast<int>(tFar), -1, 0, 0)));
}

inline void storeRayHit(RTCRayHit& h, const Vec3f& origin, const Vec3f& direction, float tNear, float tFar,
                        float time = 0.0f) {
    storeRay(h.ray, origin, direction, tNear, tFar, time);
    h.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    h.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
}

// An Embree user geometry's intersect callback reporting its hit at distance t with geometric
// normal `normal` (u and v 0, the callback's primitive, geometry and instance ids).
inline void storeUserHit(const RTCIntersectFunctionNArguments* args, float t, const Vec3f& normal) {
    auto* rayHit = reinterpret_cast<RTCRayHit*>(args->rayhit);
    rayHit->ray.tfar = t;
    rayHit->hit.Ng_x = normal.x;
    rayHit->hit.Ng_y = normal.y;
    rayHit->hit.Ng_z = normal.z;
    rayHit->hit.u = rayHit->hit.v = 0.0f;
    rayHit->hit.primID = args->primID;
    rayHit->hit.geomID = args->geomID;
    rayHit->hit.instID[0] = args->context->instID[0];
}

}  // namespace fluence::render
