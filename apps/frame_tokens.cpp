#include "apps/frame_tokens.h"

#include <charconv>
#include <cmath>
#include <cstdlib>

namespace fluence::app {

namespace {

std::string padded(long long frame, int width) {
    std::string digits = std::to_string(std::llabs(frame));
    if (int(digits.size()) < width) digits.insert(0, std::size_t(width) - digits.size(), '0');
    return (frame < 0 ? "-" : "") + digits;
}

std::string shortest(double time) {
    char buffer[32];
    auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, time);
    return error == std::errc() ? std::string(buffer, end) : std::to_string(time);
}

// Calls `token(at, length, expansion)` for every frame token of `pattern`, in order.
template <typename Visit>
void forEachToken(const std::string& pattern, double time, Visit&& token) {
    const long long frame = std::llround(time);
    for (std::size_t i = 0; i < pattern.size(); ++i) {
        if (pattern.compare(i, 3, "$FF") == 0) {
            token(i, 3, shortest(time));
        } else if (pattern.compare(i, 2, "$F") == 0) {
            const bool width = i + 2 < pattern.size() && pattern[i + 2] >= '1' && pattern[i + 2] <= '9';
            token(i, width ? 3 : 2, padded(frame, width ? pattern[i + 2] - '0' : 0));
        } else if (pattern[i] == '%') {
            std::size_t j = i + 1;
            int width = 0;
            while (j < pattern.size() && pattern[j] >= '0' && pattern[j] <= '9')
                width = width * 10 + (pattern[j++] - '0');
            if (j < pattern.size() && pattern[j] == 'd' && width <= 32) token(i, j + 1 - i, padded(frame, width));
        }
    }
}

}  // namespace

bool hasFrameToken(const std::string& pattern) {
    bool found = false;
    forEachToken(pattern, 0.0, [&](std::size_t, std::size_t, const std::string&) { found = true; });
    return found;
}

std::string expandFrameTokens(const std::string& pattern, double time) {
    std::string out;
    std::size_t copied = 0;
    forEachToken(pattern, std::isnan(time) ? 0.0 : time,
                 [&](std::size_t at, std::size_t length, const std::string& expansion) {
                     if (at < copied) return;  // inside a token already replaced
                     out += pattern.substr(copied, at - copied) + expansion;
                     copied = at + length;
                 });
    return out + pattern.substr(copied);
}

}  // namespace fluence::app
