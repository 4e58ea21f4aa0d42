#include "delegate/curves_rprim.h"

#include "delegate/material_binding.h"
#include "delegate/curves_adapter.h"
#include "delegate/motion_samples.h"

namespace fluence::delegate {

render::CurvesDesc objectSpaceCurves(const SyncContext& context, const usd::PrimSpec& prim) {
    const std::unique_ptr<usd::PrimSpec> moved =
        withPointsMovedByVelocities(context.stage, prim, context.time, context.velocityFrame);
    return curvesFromPrim(PrimReader(moved ? *moved : prim, context.time), context.convertColor,
                          [&](const std::string& message) { context.warn(prim.path, message); });
}

void CurvesRprim::syncData(const SyncContext& context, const usd::PrimSpec* prim, std::uint32_t bits) {
    if (!prim || (bits & ~std::uint32_t(kDirtyTransform)) == 0) return;  // a move keeps the object-space curves
    objectSpace_ = objectSpaceCurves(context, *prim);
    materialPath_ = boundMaterialPath(context.stage, *prim);
}

render::CurvesDesc CurvesRprim::worldCurves() const { return transformCurves(objectSpace_, world()); }

}  // namespace fluence::delegate
