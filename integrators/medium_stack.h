// The media a path is in: the scene's volumes everywhere, and inside closed surfaces the interior
// media of their materials (render::MaterialDesc::interior).
//
// A path starts outside every closed surface (a camera inside glass or liquid is not detected).
// When it crosses a surface whose hit has an interior (SurfaceHit::interior >= 0), that is, when
// the direction it leaves by is on the other side of the geometric normal from the one it came
// from, it enters the interior if it leaves against the normal and leaves it otherwise. Closed
// meshes face outwards: the render scene turns those wound inward (or mirrored) outward by their
// signed volume (render/solid_orientation.h). Interiors nest, as a stack (an ice cube in a drink): the innermost one,
// together with the volumes, fills the space the path is in. Leaving removes the innermost entry
// of that interior wherever it is in the stack, so surfaces that intersect (a liquid whose surface
// pokes through its glass) still come out right when the path leaves both. Crossings of surfaces
// without interiors, and holes cut by opacity, change nothing. Beyond kDepth nested interiors a
// further entry is ignored.
#pragma once

#include <array>

#include "core/vec.h"
#include "media/medium.h"
#include "render/render_scene.h"

namespace fluence::integrators {

class MediumStack {
public:
    static constexpr int kDepth = 4;

    explicit MediumStack(const render::RenderScene& scene) : scene_(&scene) {}

    // The medium the path's next ray travels through, or nullptr when it crosses empty space.
    const media::Medium* medium() const {
        return size_ > 0 ? scene_->mediumInside(interiors_[size_ - 1]) : scene_->medium();
    }

    // The stack of the ray leaving `hit` along wi, for the path that arrived along -wo.
    MediumStack after(const render::SurfaceHit& hit, const Vec3f& wo, const Vec3f& wi) const {
        MediumStack next = *this;
        next.cross(hit, wo, wi);
        return next;
    }
    // This stack made after(hit, wo, wi), in place (no copy of the stack).
    void cross(const render::SurfaceHit& hit, const Vec3f& wo, const Vec3f& wi) {
        const float in = dot(wo, hit.geometricNormal), out = dot(wi, hit.geometricNormal);
        if (hit.interior < 0 || in * out >= 0.0f) return;  // a reflection: still on the same side
        if (out < 0.0f) {
            if (size_ < kDepth) {
                subsurface_[size_] = hit.material.subsurface > 0.0f;
                interiors_[size_++] = hit.interior;
            }
            return;
        }
        for (int i = size_ - 1; i >= 0; --i)
            if (interiors_[i] == hit.interior) {
                for (int j = i; j + 1 < size_; ++j) {
                    interiors_[j] = interiors_[j + 1];
                    subsurface_[j] = subsurface_[j + 1];
                }
                --size_;
                break;
            }
    }

    int depth() const { return size_; }
    // Whether the innermost interior is that of a subsurface material (entered through a surface
    // whose material has subsurface > 0): its scatterings are subsurface scattering.
    bool inSubsurface() const { return size_ > 0 && subsurface_[size_ - 1]; }

private:
    const render::RenderScene* scene_;
    std::array<int, kDepth> interiors_{};
    std::array<bool, kDepth> subsurface_{};
    int size_ = 0;
};

}  // namespace fluence::integrators
