#include "media/medium_union.h"

#include <algorithm>

namespace fluence::media {

MediumUnion::MediumUnion(std::vector<std::unique_ptr<Medium>> media) : owned_(std::move(media)) {
    for (const auto& medium : owned_) media_.push_back(medium.get());
}

MediumUnion::MediumUnion(std::vector<const Medium*> borrowed) : media_(std::move(borrowed)) {}

MediumProperties MediumUnion::at(const Vec3f& p) const {
    MediumProperties sum;
    RGB emitted(0.0f);
    float gWeighted = 0.0f, scattering = 0.0f;
    for (const Medium* medium : media_) {
        MediumProperties m = medium->at(p);
        sum.sigmaA += m.sigmaA;
        sum.sigmaS += m.sigmaS;
        emitted += m.sigmaA * m.emission;
        float s = luminance(m.sigmaS);
        gWeighted += s * m.g;
        scattering += s;
    }
    for (int c = 0; c < 3; ++c) sum.emission[c] = sum.sigmaA[c] > 0.0f ? emitted[c] / sum.sigmaA[c] : 0.0f;
    sum.g = scattering > 0.0f ? gWeighted / scattering : 0.0f;
    return sum;
}

void MediumUnion::majorants(const Vec3f& origin, const Vec3f& direction, float tMin, float tMax,
                            FunctionRef<bool(const MajorantSegment&)> visit) const {
    if (media_.size() == 1) {
        media_[0]->majorants(origin, direction, tMin, tMax, visit);
        return;
    }
    std::vector<MajorantSegment> segments;
    std::vector<float> cuts;
    for (const Medium* medium : media_)
        medium->majorants(origin, direction, tMin, tMax, [&](const MajorantSegment& s) {
            segments.push_back(s);
            cuts.push_back(s.tMin);
            cuts.push_back(s.tMax);
            return true;
        });
    std::sort(cuts.begin(), cuts.end());
    cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
        MajorantSegment piece{cuts[i], cuts[i + 1], RGB(0.0f), RGB(0.0f)};
        bool covered = false;
        for (const MajorantSegment& s : segments)
            if (s.tMin <= piece.tMin && piece.tMax <= s.tMax) {
                piece.sigmaMaj += s.sigmaMaj;
                piece.sigmaMin += s.sigmaMin;
                covered = true;
            }
        if (covered && !visit(piece)) return;
    }
}

}  // namespace fluence::media
