// LightPathTracker: the light path expression AOVs of one camera sample, followed as an integrator
// extends the path (`path` does, integrators/path_tracer.cpp; so does bdpt's camera subpath, whose
// joins go on through the light subpath's events, join(), integrators/bdpt_events.h; and sppm's
// eye path, whose gathers join photons that carry their own events' summary, gather(),
// integrators/photon_light_paths.h).
//
// A path's throughput is shared among the histories of lobe kinds it could have been labelled
// with: at a vertex whose BSDF mixes kinds (render/bsdf.h, THE LOBE SPLIT) the part f_D / f of the
// throughput went through a diffuse bounce and f_G / f through a glossy one, per channel. For each
// expression the tracker keeps the automaton states (integrators/light_path_expression.h) the path
// can be in, each with the fraction (RGB) of the throughput that is in it. Light the path collects
// -- emission it reaches, or a light sampled from a vertex (split by that vertex's kinds for the
// light's direction) -- goes to every expression that accepts once the light's event is appended,
// weighted by the fraction. Fractions never add up to more than the throughput (histories that no
// continuation can match are dropped), so disjoint expressions that together match every path
// split the beauty exactly: their layers sum to it sample by sample, up to float rounding. The
// tracker draws no random numbers, so the beauty is bit-identical with and without LPE AOVs.
//
// Events Fluence produces, from the camera to the light:
//   C                       the camera
//   <R|T  D|G|S>            a surface reflection or transmission (R or T by the side wi leaves on),
//                           by the kind of lobe: D diffuse, G glossy, S a delta lobe
//   <V D>                   scattering in a medium (phase functions count as diffuse); inside a
//                           subsurface material's interior, and the jump of diffusion subsurface
//                           scattering, labelled 'subsurface'
//   <L . 'name'>            a light (dome lights included), labelled with its prim's name
//   <O>                     an emissive surface (a material's emission) or an emitting volume
#pragma once

#include <span>
#include <string>
#include <vector>

#include "core/film.h"
#include "integrators/light_path_expression.h"
#include "render/bsdf.h"

namespace fluence::integrators {

// A named light path expression AOV: `name` is the EXR layer, `expression` what it collects.
struct LightPathAov {
    std::string name;
    LightPathExpression expression;
};

// One vertex of a path as events: one event, or, at a BSDF that mixes kinds, one per kind with
// the share of the throughput that went through it.
class VertexEvents {
public:
    // A vertex that is one event: a delta lobe, a medium scattering, a one-kind BSDF.
    explicit VertexEvents(const PathEvent& event) : events_{event, event}, shares_{RGB(1.0f), RGB(0.0f)}, count_(1) {}
    // A non-delta surface scattering whose value f is `split` by kind (f is their sum;
    // `transmitted`: wi leaves on the other side of the surface than wo).
    VertexEvents(bool transmitted, const render::LobeSplit& split);

    int size() const { return count_; }
    const PathEvent& event(int i) const { return events_[i]; }
    const RGB& share(int i) const { return shares_[i]; }

private:
    PathEvent events_[2];
    RGB shares_[2];
    int count_;
};

// One vertex's step of a set of histories, each an expression `aov`, a key (what the automaton
// knows of it) and the `share` of the throughput that went that way: per event k of the vertex, a
// history goes to key step(expression, key, event k) with share * vertex.share(k); histories that
// reach the same key merge, those reaching `dead` or left with no share are dropped. `next` is
// scratch space. Shared by the tracker (the key: an automaton state) and by photons (a set of
// states, integrators/photon_light_paths.h).
template <class History, class Key, class Step>
void scatterHistories(std::span<const LightPathAov> aovs, const VertexEvents& vertex, Key History::*key, Key dead,
                      Step&& step, std::vector<History>& histories, std::vector<History>& next) {
    next.clear();
    for (const History& history : histories) {
        const LightPathExpression& e = aovs[std::size_t(history.aov)].expression;
        for (int k = 0; k < vertex.size(); ++k) {
            const Key to = step(e, history.*key, vertex.event(k));
            const RGB share = history.share * vertex.share(k);
            if (to == dead || isBlack(share)) continue;
            History* same = nullptr;
            for (History& n : next)
                if (n.aov == history.aov && n.*key == to) same = &n;
            if (same) {
                same->share += share;
            } else {
                History added = history;
                added.*key = to;
                added.share = share;
                next.push_back(added);
            }
        }
    }
    histories.swap(next);
}

class LightPathTracker {
public:
    // Starts at the camera event. No AOVs: every call does nothing.
    explicit LightPathTracker(std::span<const LightPathAov> aovs);

    bool active() const { return !aovs_.empty(); }
    std::size_t layers() const { return aovs_.size(); }  // the AOVs' count: a FilmSample's light path layers
    // The path scatters at `vertex` and goes on.
    void scatter(const VertexEvents& vertex);
    // The path reaches `light` (emission reached by a ray), contributing `radiance` to the beauty.
    void reach(const PathEvent& light, const RGB& radiance, FilmSample& out) const;
    // A light sampled from `vertex` (next-event estimation) contributes `radiance` to the beauty.
    void connect(const VertexEvents& vertex, const PathEvent& light, const RGB& radiance, FilmSample& out) const;
    // The path goes on through `vertices` (a subpath joined to it, integrators/bdpt_events.h) to
    // `light`, contributing `radiance` to the beauty; this tracker stays where it is.
    void join(std::span<const VertexEvents> vertices, const PathEvent& light, const RGB& radiance,
              FilmSample& out) const;
    // The path ends at `vertex`, joined to light whose own events (a photon's, integrators/
    // photon_light_paths.h) the caller knows only through accepted(aov, state): the fraction (RGB)
    // of that light expression `aov` accepts from `state`, the state after the vertex's event.
    // Calls add(aov, fraction) with the fraction of the joined light each expression collects.
    template <class Accepted, class Add>
    void gather(const VertexEvents& vertex, Accepted&& accepted, Add&& add) const {
        for (const Entry& entry : entries_) {
            const LightPathExpression& e = aovs_[std::size_t(entry.aov)].expression;
            for (int k = 0; k < vertex.size(); ++k) {
                const int state = e.next(entry.state, vertex.event(k));
                if (state != LightPathExpression::kDead)
                    add(entry.aov, entry.share * vertex.share(k) * accepted(entry.aov, state));
            }
        }
    }

private:
    struct Entry {
        int aov;
        int state;
        RGB share;  // the fraction of the path's throughput in this state
    };
    std::span<const LightPathAov> aovs_;
    std::vector<Entry> entries_, next_;
};

}  // namespace fluence::integrators
