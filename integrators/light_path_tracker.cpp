#include "integrators/light_path_tracker.h"

namespace fluence::integrators {

namespace {

// Per channel, part / whole, 0 where the whole is 0 (no throughput left there to share).
RGB shareOf(const RGB& part, const RGB& whole) {
    RGB share;
    for (int c = 0; c < 3; ++c) share[c] = whole[c] > 0.0f ? part[c] / whole[c] : 0.0f;
    return share;
}

}  // namespace

VertexEvents::VertexEvents(bool transmitted, const render::LobeSplit& split) : count_(0) {
    const RGB f = split.diffuse + split.glossy;
    const EventType type = transmitted ? EventType::Transmission : EventType::Reflection;
    if (!isBlack(split.diffuse)) {
        events_[count_] = PathEvent{type, Scattering::Diffuse};
        shares_[count_++] = shareOf(split.diffuse, f);
    }
    if (!isBlack(split.glossy)) {
        events_[count_] = PathEvent{type, Scattering::Glossy};
        shares_[count_++] = shareOf(split.glossy, f);
    }
}

LightPathTracker::LightPathTracker(std::span<const LightPathAov> aovs) : aovs_(aovs) {
    if (aovs_.empty()) return;
    entries_.reserve(2 * aovs_.size());
    next_.reserve(2 * aovs_.size());
    const PathEvent camera{EventType::Camera};
    for (int i = 0; i < int(aovs_.size()); ++i) {
        const LightPathExpression& e = aovs_[std::size_t(i)].expression;
        const int state = e.next(e.start(), camera);
        if (state != LightPathExpression::kDead) entries_.push_back({i, state, RGB(1.0f)});
    }
}

void LightPathTracker::scatter(const VertexEvents& vertex) {
    if (entries_.empty()) return;
    scatterHistories(
        aovs_, vertex, &Entry::state, LightPathExpression::kDead,
        [](const LightPathExpression& e, int state, const PathEvent& event) { return e.next(state, event); }, entries_,
        next_);
}

void LightPathTracker::reach(const PathEvent& light, const RGB& radiance, FilmSample& out) const {
    for (const Entry& entry : entries_) {
        const LightPathExpression& e = aovs_[std::size_t(entry.aov)].expression;
        if (e.accepts(e.next(entry.state, light))) out.addLightPath(std::size_t(entry.aov), radiance * entry.share);
    }
}

void LightPathTracker::connect(const VertexEvents& vertex, const PathEvent& light, const RGB& radiance,
                               FilmSample& out) const {
    for (const Entry& entry : entries_) {
        const LightPathExpression& e = aovs_[std::size_t(entry.aov)].expression;
        for (int k = 0; k < vertex.size(); ++k)
            if (e.accepts(e.next(e.next(entry.state, vertex.event(k)), light)))
                out.addLightPath(std::size_t(entry.aov), radiance * entry.share * vertex.share(k));
    }
}

void LightPathTracker::join(std::span<const VertexEvents> vertices, const PathEvent& light, const RGB& radiance,
                            FilmSample& out) const {
    if (entries_.empty()) return;
    LightPathTracker joined(*this);
    for (const VertexEvents& vertex : vertices) joined.scatter(vertex);
    joined.reach(light, radiance, out);
}

}  // namespace fluence::integrators
