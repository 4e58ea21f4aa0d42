// A UsdGeomBasisCurves or NurbsCurves prim in the render index (delegate/render_index.h): its
// curves read in object space (delegate/curves_adapter.h) and its bound material. A move
// (kDirtyTransform alone) re-reads nothing; any other edit re-reads the prim.
#pragma once

#include <string>

#include "delegate/render_index.h"
#include "render/curves_description.h"

namespace fluence::delegate {

// The curves of `prim` in its own space at context.time: points that are not time-sampled moved by
// their velocities at a motion step (context.velocityFrame), as a mesh's are.
render::CurvesDesc objectSpaceCurves(const SyncContext& context, const usd::PrimSpec& prim);

class CurvesRprim final : public RenderPrim {
public:
    explicit CurvesRprim(std::string path) : RenderPrim(Kind::Curves, std::move(path)) {}
    const std::string& materialPath() const { return materialPath_; }  // "" when none is bound
    // The curves in world space.
    render::CurvesDesc worldCurves() const;

private:
    void syncData(const SyncContext& context, const usd::PrimSpec* prim, std::uint32_t bits) override;
    render::CurvesDesc objectSpace_;
    std::string materialPath_;
};

}  // namespace fluence::delegate
