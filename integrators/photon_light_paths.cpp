#include "integrators/photon_light_paths.h"

namespace fluence::integrators {

namespace {

// { q : next(q, event) in states }: the states from which `event`, then a path accepted from
// `states`, is accepted.
std::uint64_t statesBefore(const LightPathExpression& e, std::uint64_t states, const PathEvent& event) {
    std::uint64_t before = 0;
    for (int q = 0; q < e.stateCount(); ++q) {
        const int after = e.next(q, event);
        if (after != LightPathExpression::kDead && ((states >> after) & 1u)) before |= std::uint64_t(1) << q;
    }
    return before;
}

}  // namespace

std::string photonLightPathProblem(const LightPathExpression& expression) {
    if (expression.stateCount() <= kMaxPhotonLpeStates) return "";
    return "'" + expression.text() + "' needs " + std::to_string(expression.stateCount()) +
           " automaton states; sppm's photons carry expressions of at most " + std::to_string(kMaxPhotonLpeStates);
}

PhotonLightPaths::PhotonLightPaths(std::span<const LightPathAov> aovs, const PathEvent& light) : aovs_(aovs) {
    for (int i = 0; i < int(aovs_.size()); ++i) {
        const LightPathExpression& e = aovs_[std::size_t(i)].expression;
        std::uint64_t accepting = 0;
        for (int q = 0; q < e.stateCount(); ++q)
            if (e.accepts(e.next(q, light))) accepting |= std::uint64_t(1) << q;
        if (accepting) histories_.push_back({accepting, RGB(1.0f), i});
    }
}

void PhotonLightPaths::scatter(const VertexEvents& vertex) {
    if (histories_.empty()) return;
    scatterHistories(aovs_, vertex, &PhotonHistory::states, std::uint64_t(0), statesBefore, histories_, next_);
}

void PhotonHistoryTable::add(std::span<const PhotonHistory> histories) {
    histories_.insert(histories_.end(), histories.begin(), histories.end());
    start_.push_back(std::uint32_t(histories_.size()));
}

void PhotonHistoryTable::append(const PhotonHistoryTable& other) {
    const std::uint32_t offset = start_.back();
    for (std::size_t i = 1; i < other.start_.size(); ++i) start_.push_back(offset + other.start_[i]);
    histories_.insert(histories_.end(), other.histories_.begin(), other.histories_.end());
}

RGB PhotonHistoryTable::accepted(std::uint32_t photon, int aov, int state) const {
    RGB share(0.0f);
    for (std::uint32_t h = start_[photon]; h < start_[photon + 1]; ++h)
        if (histories_[h].aov == aov && ((histories_[h].states >> state) & 1u)) share += histories_[h].share;
    return share;
}

}  // namespace fluence::integrators
