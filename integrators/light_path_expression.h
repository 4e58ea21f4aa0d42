// Light path expressions (LPEs): OSL's regular expressions over the events of a light path, which
// pick the part of a pixel's light that an AOV collects ("only the diffuse reflection seen
// directly", "only what the key light gives").
//
// A path is read from the camera to the light, one PathEvent per vertex: the camera, each
// scattering (its type and how it scatters), and the light, emissive object or background the path
// ends on. An expression matches a WHOLE path (it is anchored at both ends). It is compiled once
// into a deterministic automaton: a tracer keeps one int state per expression, starts at start(),
// calls next() at each vertex (a table lookup) and, where the path picks up emission, adds the
// contribution to the AOV when accepts() holds for the state after the emitting event. kDead means
// no continuation of the path can match: the tracer may stop tracking that expression.
//
// Events Fluence produces (integrators/light_path_tracker.h follows them):
//   C  the camera, always first
//   R  reflection off a surface, T transmission through one, each D diffuse, G glossy or S
//      singular (a delta lobe: mirror, clear glass)
//   V  scattering in a participating medium, with scattering D; labelled 'subsurface' inside a
//      subsurface material (and for the jump of diffusion subsurface scattering)
//   L  a light, dome lights included, labelled with its light group (delegate/light_groups.h)
//      or else its prim's name
//   O  an emissive surface (object) or emitting volume, an emissive mesh labelled like a light
// The language also has B (background) and s (straight: passing through unchanged) from OSL;
// Fluence produces neither (its environment is a dome light).
//
// Grammar (whitespace between tokens and inside brackets is ignored):
//   expression  := sequence ('|' sequence)*
//   sequence    := repeated+
//   repeated    := atom ('*' | '+' | '?' | '{n}' | '{n,m}' | '{n,}')*
//   atom        := '(' expression ')' | event | letter | '.' | label | '[' '^'? item+ ']'
//   event       := '<' position? position? position? '>'   positions: type, scattering, label
//   position    := '.' | item | '[' '^'? item+ ']'
//   item        := letter | label
//   label       := "'" characters other than "'" "'"        a custom label, compared exactly
// Letters are case-sensitive: types C R T V L O B, scatterings D G S s. Omitted trailing positions
// of an event are wildcards, and a label (or a set of labels) may come early: <L'key'> is
// <L.'key'>, <'key'> is <..'key'>; nothing follows the label. Outside brackets a type letter means
// that type with any scattering and label, a scattering letter that scattering with any type, '.'
// any single event and 'name' any event labelled name; a set [..] of these matches an event
// matching any of them, [^..] one matching none. Repetition bounds are at most 1000. Anything else
// is an LpeSyntaxError whose what() is "column N: ..." (N 1-based into the text); an expression
// whose automaton would need more than kMaxStates states is "too complex".
//
// Examples:
//   C<RD>L           diffuse reflection lit directly (direct diffuse)
//   C<RD>.+L         diffuse reflection lit indirectly
//   C<RS>.*L         everything seen in mirrors
//   C<TS>.*L         everything seen through clear glass
//   CD+L             light over diffuse bounces only
//   C[^S]*L          paths with no singular event
//   C<V>+L           light scattered in media only
//   C<.D'subsurface'>*L   light through subsurface walks only
//   C.*<L'key'>      all light from the light named key
//   C(D|G){2}L       two bounces, each diffuse or glossy
//   C.*[LO]          everything, from lights and emissive surfaces
//
// Compilation: a parse tree of events and operators; a Thompson NFA over event predicates; the
// finite alphabet of 7 types x 5 scatterings x (the expression's labels + any other label), merged
// into classes of symbols no predicate tells apart; subset construction; Hopcroft minimisation,
// which merges the states that cannot reach acceptance into one dead state, dropped (kDead).
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace fluence::integrators {

// The kinds of event along a light path, listed from the camera to the light.
enum class EventType : std::uint8_t { Camera, Reflection, Transmission, Volume, Light, Object, Background };
// How an event scatters (None for camera, light, object and background events).
enum class Scattering : std::uint8_t { None, Diffuse, Glossy, Singular, Straight };

struct PathEvent {
    EventType type;
    Scattering scattering = Scattering::None;
    std::string_view label = {};  // custom label ("" for none): a light's name, "subsurface", ...
};

// A syntax error: what() is "column N: <what is wrong>" (1-based column into the expression).
class LpeSyntaxError : public std::invalid_argument {
public:
    using std::invalid_argument::invalid_argument;
};

class LightPathExpression {
public:
    explicit LightPathExpression(std::string_view text);  // throws LpeSyntaxError
    const std::string& text() const { return text_; }

    static constexpr int kDead = -1;  // no continuation can match
    static constexpr int kMaxStates = 4096;
    int start() const { return start_; }                 // the state before any event (kDead if nothing can match)
    int next(int state, const PathEvent& event) const {  // kDead stays kDead
        if (state == kDead) return kDead;
        return transitions_[static_cast<std::size_t>(state) * classCount_ + symbolClass_[symbolOf(event)]];
    }
    bool accepts(int state) const { return state != kDead && accepting_[static_cast<std::size_t>(state)] != 0; }
    int stateCount() const { return static_cast<int>(accepting_.size()); }

private:
    // The alphabet index of an event: (type, scattering, label), the label being the index of the
    // expression's label it equals, or labels_.size() for any other (or no) label.
    std::size_t symbolOf(const PathEvent& event) const {
        std::size_t label = 0;
        while (label < labels_.size() && labels_[label] != event.label) ++label;
        const std::size_t kinds = static_cast<std::size_t>(event.type) * 5 + static_cast<std::size_t>(event.scattering);
        return kinds * (labels_.size() + 1) + label;
    }

    std::string text_;
    std::vector<std::string> labels_;         // the custom labels the expression mentions, sorted
    std::vector<std::uint32_t> symbolClass_;  // alphabet symbol -> class
    std::size_t classCount_ = 0;
    std::vector<int> transitions_;         // [state * classCount_ + class] -> state or kDead
    std::vector<std::uint8_t> accepting_;  // per state
    int start_ = kDead;
};

}  // namespace fluence::integrators
