// The time samples of a clip set (scene/value_clips.h), after USD's Usd_Clip and Usd_ClipSet.
#include "scene/value_clips.h"

#include <algorithm>

#include "scene/prim_composer.h"

namespace fluence::usd::detail {

const AttributeSpec* ClipLayer::attribute(const std::string& primPath, const std::string& name) const {
    if (!specs) return nullptr;
    SpecRef spec = specs->find(primPath);
    return spec.prim ? spec.prim->attribute(name) : nullptr;
}

namespace {

bool hasSamples(const AttributeSpec* attribute) { return attribute && !attribute->timeSamples.empty(); }

// Whether the closed interval [a, b] meets [start, end).
bool meets(double a, double b, double start, double end) {
    double lo = std::max(a, start), hi = std::min(b, end);
    return lo < hi || (lo == hi && hi < end);
}

// The point of a straight segment at `x`, its ends given exactly.
double along(double x, double x1, double y1, double x2, double y2) {
    if (x1 == x2 || x == x1) return y1;
    if (x == x2) return y2;
    return (y2 - y1) / (x2 - x1) * (x - x1) + y1;
}

}  // namespace

ClipSet::TimeMapping ClipSet::segmentEnd(std::size_t i) const {
    // A segment ending at the left side of a jump runs to the jump's stage time (USD keeps the
    // mapping exact there rather than ending a safe step early).
    TimeMapping end = times[i];
    if (end.jump) end.stage = times[i + 1].stage;
    return end;
}

double ClipSet::toClipTime(double stageTime) const {
    if (times.empty()) return stageTime;
    std::size_t second;
    if (stageTime <= times.front().stage)
        second = 1;
    else if (stageTime >= times.back().stage)
        second = times.size() - 1;
    else
        second = static_cast<std::size_t>(std::lower_bound(times.begin(), times.end(), stageTime,
                                                           [](const TimeMapping& m, double t) { return m.stage < t; }) -
                                          times.begin());
    const TimeMapping& first = times[second - 1];
    TimeMapping end = segmentEnd(second);
    return along(stageTime, first.stage, first.clip, end.stage, end.clip);
}

double ClipSet::toStageTime(double clipTime, std::size_t segment) const {
    const TimeMapping& first = times[segment];
    TimeMapping end = segmentEnd(segment + 1);
    return along(clipTime, first.clip, first.stage, end.clip, end.stage);
}

void ClipSet::addSampleTimes(const Clip& clip, const AttributeSpec* attribute, std::vector<double>& out) const {
    auto add = [&](double t) {
        if (clip.start <= t && t < clip.end) out.push_back(t);
    };
    if (hasSamples(attribute) && times.empty()) {
        for (const auto& sample : attribute->timeSamples) add(sample.first);
    } else if (hasSamples(attribute)) {
        // The mapping may be many-to-one: each clip sample is mapped through every segment of the
        // curve, within the stage times where this clip is active, that reaches its clip time.
        auto from = std::lower_bound(times.begin(), times.end(), clip.start,
                                     [](const TimeMapping& m, double t) { return m.stage < t; });
        std::size_t first = from == times.begin() ? 0 : static_cast<std::size_t>(from - times.begin()) - 1;
        for (std::size_t i = first; i + 1 < times.size() && times[i].stage < clip.end; ++i) {
            const TimeMapping& a = times[i];
            const TimeMapping& b = times[i + 1];
            if (a.jump || !meets(a.stage, b.stage, clip.start, clip.end)) continue;
            const TimeSamples& clipSamples = attribute->timeSamples;
            auto sample = std::lower_bound(clipSamples.begin(), clipSamples.end(), std::min(a.clip, b.clip),
                                           [](const auto& s, double t) { return s.first < t; });
            for (; sample != clipSamples.end() && sample->first <= std::max(a.clip, b.clip); ++sample) {
                double t = sample->first;
                if (a.clip == b.clip) {
                    add(a.stage);
                    add(b.stage);
                } else {
                    add(toStageTime(t, i));
                }
            }
        }
    }
    for (const TimeMapping& m : times) add(m.stage);
    add(clip.authoredStart);
}

std::optional<TimeSamples> ClipSet::samples(const std::string& primPath, const std::string& attribute,
                                            std::vector<std::pair<std::string, std::string>>* assets) const {
    const std::string clipPath = clipPrim + primPath.substr(sourcePrim.size());
    auto inClip = [&](const Clip& clip) { return clip.layer.attribute(clipPath, attribute); };

    // The manifest declares the attribute (a generated one: the first clip with samples for it).
    const AttributeSpec* declared = manifest.attribute(clipPath, attribute);
    if (generatedManifest)
        for (const Clip& clip : clips)
            if (!declared && hasSamples(inClip(clip))) declared = inClip(clip);
    if (!declared || declared->uniform) return std::nullopt;
    const AttributeSpec* fallback = generatedManifest ? nullptr : declared;  // the manifest's default
    bool hasFallback = fallback && fallback->hasDefault && !fallback->defaultValue.isBlocked();

    // A value block at a clip's activation time in the manifest says the clip has no samples.
    auto declaredEmpty = [&](const Clip& clip) {
        if (!fallback) return false;
        const TimeSamples& marks = fallback->timeSamples;
        auto at =
            std::find_if(marks.begin(), marks.end(), [&](const auto& s) { return s.first == clip.authoredStart; });
        return at != marks.end() && at->second.isBlocked();
    };
    // Whether a clip gives values. Without interpolateMissing all do: a clip without samples gives
    // the manifest's default, else a value block. With it, clips without samples are bridged.
    auto contributes = [&](const Clip& clip) {
        if (!interpolateMissing || (fallback && fallback->hasDefault)) return true;
        return !declaredEmpty(clip) && hasSamples(inClip(clip));
    };
    std::vector<double> stageTimes;
    for (const Clip& clip : clips)
        if (contributes(clip)) addSampleTimes(clip, inClip(clip), stageTimes);
    if (stageTimes.empty()) stageTimes.push_back(clips.front().authoredStart);
    std::sort(stageTimes.begin(), stageTimes.end());
    stageTimes.erase(std::unique(stageTimes.begin(), stageTimes.end()), stageTimes.end());

    TimeSamples out;
    out.reserve(stageTimes.size());
    for (double t : stageTimes) {
        const Clip& active = *(
            std::upper_bound(clips.begin(), clips.end(), t, [](double time, const Clip& c) { return time < c.start; }) -
            1);
        const AttributeSpec* inActive = inClip(active);
        if (hasSamples(inActive))
            out.emplace_back(
                t, anchorAssets(valueAtTime(inActive->timeSamples, toClipTime(t)), *active.layer.layer, assets));
        else if (hasFallback)
            out.emplace_back(t, anchorAssets(fallback->defaultValue, *manifest.layer, assets));
        else
            out.emplace_back(t, Value{});  // a value block
    }
    return out;
}

}  // namespace fluence::usd::detail
