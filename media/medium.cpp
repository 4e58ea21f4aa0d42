// Medium's default exact-extinction sums: media/exact_depth.h's visitors over extinctionPieces().
#include "media/medium.h"

#include "media/exact_depth.h"

namespace fluence::media {

OpticalDepth Medium::exactOpticalDepth(const Vec3f& origin, const Vec3f& direction, float tMin, float tMax) const {
    OpticalDepthSum sum;
    extinctionPieces(origin, direction, tMin, tMax, [&](const ExtinctionPiece& piece) { return sum(piece); });
    return sum.depth;
}

DepthCrossing Medium::exactDepthCrossing(const Vec3f& origin, const Vec3f& direction, float tMin, float tMax, int hero,
                                         double target) const {
    DepthCrossingSearch search{hero, target, {}};
    extinctionPieces(origin, direction, tMin, tMax, [&](const ExtinctionPiece& piece) { return search(piece); });
    return search.crossing;
}

}  // namespace fluence::media
