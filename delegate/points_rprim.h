// The render prim of a UsdGeomPoints prim: its points in object space and bound material, read
// at sync (delegate/points_adapter.h), placed in world space when the scene is described.
#pragma once

#include <string>

#include "delegate/render_index.h"
#include "render/points_description.h"

namespace fluence::delegate {

// The points of `prim` in its own space at context.time, moved by their velocities at a motion
// step (context.velocityFrame) when their positions are not time-sampled.
render::PointsDesc objectSpacePoints(const SyncContext& context, const usd::PrimSpec& prim);

class PointsRprim final : public RenderPrim {
public:
    explicit PointsRprim(std::string path) : RenderPrim(Kind::Points, std::move(path)) {}
    // The points in world space, their material not yet resolved (material -1).
    render::PointsDesc worldPoints() const;
    const std::string& materialPath() const { return materialPath_; }

private:
    void syncData(const SyncContext& context, const usd::PrimSpec* prim, std::uint32_t bits) override;

    render::PointsDesc objectSpace_;
    std::string materialPath_;
};

}  // namespace fluence::delegate
