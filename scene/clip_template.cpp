#include "scene/clip_template.h"

#include <cmath>
#include <cstdio>

#include "scene/asset_path.h"

namespace fluence::usd::detail {

namespace {

// Times are stepped as USD does: in units of 1/10000, so that fractional strides add up exactly.
constexpr double kPromotion = 10000.0;
// Bounds that keep a template from running away: times must fit an int (USD prints them as one),
// and one template names at most this many files.
constexpr double kLargestTime = 1e9;
constexpr std::size_t kMostClips = 100'000;

std::vector<std::string> split(const std::string& text, char separator) {
    std::vector<std::string> parts;
    for (std::size_t start = 0; start <= text.size();) {
        std::size_t end = std::min(text.find(separator, start), text.size());
        if (end > start) parts.push_back(text.substr(start, end - start));  // as TfStringTokenize
        start = end + 1;
    }
    return parts;
}

bool allHashes(const std::string& token) { return token.find_first_not_of('#') == std::string::npos; }

std::string padded(double time, std::size_t digits) {
    char text[64];
    std::snprintf(text, sizeof text, "%0*d", static_cast<int>(digits), static_cast<int>(time));
    return text;
}

std::string fraction(double time, std::size_t digits) {
    char text[128];
    std::snprintf(text, sizeof text, "%.*f", static_cast<int>(std::min<std::size_t>(digits, 60)), time);
    std::string all = text;
    std::size_t dot = all.find('.');
    return dot == std::string::npos ? "" : all.substr(dot + 1);
}

}  // namespace

std::optional<ClipTemplate> deriveClipTemplate(const std::string& pattern, const std::string& layerIdentifier,
                                               double start, double end, double stride,
                                               std::optional<double> activeOffset, std::string& problem) {
    if (!(stride > 0)) {
        problem = "templateStride must be greater than 0";
        return std::nullopt;
    }
    if (activeOffset && !(std::abs(*activeOffset) <= stride)) {
        problem = "templateActiveOffset must not exceed templateStride";
        return std::nullopt;
    }
    std::size_t slash = pattern.rfind('/');
    std::string folder = slash == std::string::npos ? "" : pattern.substr(0, slash + 1);
    std::vector<std::string> tokens = split(pattern.substr(folder.size()), '.');
    std::vector<std::size_t> groups;
    for (std::size_t i = 0; i < tokens.size(); ++i)
        if (allHashes(tokens[i])) groups.push_back(i);
    if (groups.empty() || groups.size() > 2 || (groups.size() == 2 && groups[1] != groups[0] + 1)) {
        problem = "templateAssetPath '" + pattern + "' must look like path/name.###.usd or path/name.###.###.usd";
        return std::nullopt;
    }
    if (!(std::abs(start) <= kLargestTime && std::abs(end) <= kLargestTime)) {
        problem = "templateStartTime and templateEndTime must lie within +-1e9";
        return std::nullopt;
    }
    if (start > end) {
        problem = "templateStartTime is later than templateEndTime";
        return std::nullopt;
    }
    if ((end - start) / stride >= static_cast<double>(kMostClips)) {
        problem = "the template names more than " + std::to_string(kMostClips) + " clip files";
        return std::nullopt;
    }

    const std::size_t integerDigits = tokens[groups.front()].size();
    const std::size_t fractionDigits = groups.size() == 2 ? tokens[groups.back()].size() : 0;
    ClipTemplate out;
    const double reach = activeOffset ? std::abs(*activeOffset) : 0.0;
    if (activeOffset) out.times.emplace_back(start - reach, start - reach);
    const double step = stride * kPromotion;
    for (double t = start * kPromotion; t <= end * kPromotion && t + step > t; t += step) {
        const double time = t / kPromotion;
        tokens[groups.front()] = padded(time, integerDigits);
        if (fractionDigits) tokens[groups.back()] = fraction(time, fractionDigits);
        std::string name = folder;
        for (std::size_t i = 0; i < tokens.size(); ++i) name += (i ? "." : "") + tokens[i];
        std::string resolved = anchorAssetPath(layerIdentifier, name);
        if (!assetExists(resolved)) continue;
        out.active.emplace_back(activeOffset ? (t + *activeOffset * kPromotion) / kPromotion : time,
                                static_cast<double>(out.assets.size()));
        out.assets.push_back({name, resolved});
        out.times.emplace_back(time, time);
    }
    if (activeOffset) out.times.emplace_back(end + reach, end + reach);
    return out;
}

}  // namespace fluence::usd::detail
