// Several media filling space together (a scene's volumes, which may overlap): their coefficients
// add, and so do their majorants and minorants, segment by segment.
//
// at(p): sigmaA and sigmaS are the sums; the emission is the sigmaA-weighted mean of the media's
// Le (so that sigmaA Le adds up); the Henyey-Greenstein g is the sigmaS-weighted mean of theirs —
// exact where one medium scatters alone, an approximation where two scatter at one point (a
// mixture of two HG lobes is not an HG lobe).
// majorants(): with one medium, its own segments; with several, each medium's segments over the
// range are gathered and cut at every segment end, and each piece carries the sum of the bounds
// of the segments covering it (pieces that no segment covers are left out, as gaps).
// Exact extinction (media/medium.h) is offered by a union of one medium that offers it (its own
// pieces); a union of several is tracked only.
// A union either owns its media (a scene's volumes) or borrows them (the interior of a closed
// surface together with those volumes, render/render_scene.h): borrowed media must outlive it.
#pragma once

#include <memory>
#include <vector>

#include "media/medium.h"

namespace fluence::media {

class MediumUnion final : public Medium {
public:
    explicit MediumUnion(std::vector<std::unique_ptr<Medium>> media);
    explicit MediumUnion(std::vector<const Medium*> borrowed);

    MediumProperties at(const Vec3f& p) const override;
    void majorants(const Vec3f& origin, const Vec3f& direction, float tMin, float tMax,
                   FunctionRef<bool(const MajorantSegment&)> visit) const override;
    bool hasExactExtinction() const override { return media_.size() == 1 && media_[0]->hasExactExtinction(); }
    void extinctionPieces(const Vec3f& origin, const Vec3f& direction, float tMin, float tMax,
                          FunctionRef<bool(const ExtinctionPiece&)> visit) const override {
        if (hasExactExtinction()) media_[0]->extinctionPieces(origin, direction, tMin, tMax, visit);
    }
    OpticalDepth exactOpticalDepth(const Vec3f& origin, const Vec3f& direction, float tMin, float tMax) const override {
        return hasExactExtinction() ? media_[0]->exactOpticalDepth(origin, direction, tMin, tMax) : OpticalDepth{};
    }
    DepthCrossing exactDepthCrossing(const Vec3f& origin, const Vec3f& direction, float tMin, float tMax, int hero,
                                     double target) const override {
        return hasExactExtinction() ? media_[0]->exactDepthCrossing(origin, direction, tMin, tMax, hero, target)
                                    : DepthCrossing{};
    }

    std::size_t size() const { return media_.size(); }

private:
    std::vector<std::unique_ptr<Medium>> owned_;
    std::vector<const Medium*> media_;  // owned_'s, or borrowed
};

}  // namespace fluence::media
