#include "scene/time_samples.h"

#include <algorithm>
#include <cmath>

namespace fluence::usd {

namespace {

bool interpolates(const Value& a, const Value& b) {
    // Integers and bools are held; every floating-point type interpolates (point3f[] among them:
    // its name holds "int", which once held every point array).
    const std::string scalar = a.typeName.substr(0, a.typeName.find('['));
    const bool integral =
        scalar.starts_with("int") || scalar.starts_with("uint") || scalar == "uchar" || scalar == "bool";
    return a.isNumeric() && b.isNumeric() && a.numbers.size() == b.numbers.size() && !integral;
}

}  // namespace

Value valueAtTime(const TimeSamples& samples, double time) {
    auto after = std::lower_bound(samples.begin(), samples.end(), time,
                                  [](const std::pair<double, Value>& s, double t) { return s.first < t; });
    if (after == samples.begin()) return after->second;
    if (after == samples.end()) return samples.back().second;
    if (after->first == time) return after->second;
    const auto& [loTime, lo] = *(after - 1);
    const auto& [hiTime, hi] = *after;
    if (!interpolates(lo, hi)) return lo;  // held
    // A neighbour at an infinite time (Sdf reads inf and -inf times): the interpolation tends to
    // the finite neighbour's value, where the formula below would give inf/inf.
    if (std::isinf(hiTime)) return lo;
    if (std::isinf(loTime)) return hi;
    double a = (time - loTime) / (hiTime - loTime);
    std::vector<double> mixed(lo.numbers.size());
    for (std::size_t i = 0; i < mixed.size(); ++i) mixed[i] = lo.numbers[i] + a * (hi.numbers[i] - lo.numbers[i]);
    Value out = lo;
    out.numbers = std::move(mixed);
    return out;
}

}  // namespace fluence::usd
