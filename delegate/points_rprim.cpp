#include "delegate/points_rprim.h"

#include "delegate/material_binding.h"
#include "delegate/material_adapter.h"
#include "delegate/motion_samples.h"
#include "delegate/points_adapter.h"

namespace fluence::delegate {

render::PointsDesc objectSpacePoints(const SyncContext& context, const usd::PrimSpec& prim) {
    render::PointsDesc points = pointsFromPrim(PrimReader(prim, context.time), context.convertColor,
                                               [&](const std::string& message) { context.warn(prim.path, message); });
    moveByVelocities(context.stage, prim, context.time, context.velocityFrame, Matrix4::identity(), points.positions);
    return points;
}

void PointsRprim::syncData(const SyncContext& context, const usd::PrimSpec* prim, std::uint32_t bits) {
    if (!prim || (bits & ~std::uint32_t(kDirtyTransform)) == 0) return;  // moved points keep their object-space data
    objectSpace_ = objectSpacePoints(context, *prim);
    materialPath_ = boundMaterialPath(context.stage, *prim);
}

render::PointsDesc PointsRprim::worldPoints() const { return pointsToWorld(objectSpace_, world()); }

}  // namespace fluence::delegate
