#include "media/majorant_check.h"

#include <algorithm>
#include <cstddef>
#include <cmath>
#include <sstream>
#include <vector>

namespace fluence::media {
namespace {

constexpr int kMaxReported = 8;

// a > b beyond the tolerance, in any channel.
bool exceeds(const RGB& a, const RGB& b) {
    for (int c = 0; c < 3; ++c)
        if (a[c] > b[c] + kMajorantTolerance * std::max(std::abs(a[c]), std::abs(b[c]))) return true;
    return false;
}

std::ostream& operator<<(std::ostream& os, const RGB& v) {
    return os << '(' << v.x << ", " << v.y << ", " << v.z << ')';
}

bool finiteAndNonNegative(const RGB& v) { return isFinite(v) && v.x >= 0.0f && v.y >= 0.0f && v.z >= 0.0f; }

class Checker {
public:
    Checker(const Medium& medium, const MediumRay& ray, int points) : medium_(medium), ray_(ray), points_(points) {}

    template <typename... Parts>
    void fail(const Parts&... parts) {
        check_.bound = false;
        if (failures_++ >= kMaxReported) return;
        std::ostringstream line;
        (line << ... << parts);
        check_.report += line.str() + "\n";
    }

    // Calls `test(t)` at the start of [a, b) and at points_ evenly spaced points in it (at the
    // start only if b is infinite).
    template <typename Test>
    void samplePoints(float a, float b, const Test& test) {
        if (!(a < b)) return;
        test(a);
        if (std::isinf(b)) return;
        for (int i = 0; i < points_; ++i) test(a + (i + 0.5f) / points_ * (b - a));
    }

    void checkGap(float a, float b) {
        samplePoints(a, b, [&](float t) {
            RGB sigmaT = sigmaTAt(t);
            if (exceeds(sigmaT, RGB(0.0f)))
                fail("gap [", a, ", ", b, "): at t = ", t, " sigmaT = ", sigmaT, " but no segment covers it");
        });
    }

    void checkSegment(std::size_t index, const MajorantSegment& s) {
        const auto name = [&] {
            std::ostringstream os;
            os << "segment " << index << " [" << s.tMin << ", " << s.tMax << ")";
            return os.str();
        }();
        if (!finiteAndNonNegative(s.sigmaMaj) || !finiteAndNonNegative(s.sigmaMin) || exceeds(s.sigmaMin, s.sigmaMaj))
            fail(name, ": needs 0 <= sigmaMin ", s.sigmaMin, " <= sigmaMaj ", s.sigmaMaj);
        samplePoints(std::max(s.tMin, 0.0f), std::min(s.tMax, ray_.tMax), [&](float t) {
            RGB sigmaT = sigmaTAt(t);
            if (exceeds(sigmaT, s.sigmaMaj))
                fail(name, ": at t = ", t, " sigmaT = ", sigmaT, " > sigmaMaj = ", s.sigmaMaj);
            if (exceeds(s.sigmaMin, sigmaT))
                fail(name, ": at t = ", t, " sigmaT = ", sigmaT, " < sigmaMin = ", s.sigmaMin);
        });
    }

    MajorantCheck run() {
        std::vector<MajorantSegment> segments;
        medium_.majorants(ray_.origin, ray_.direction, 0.0f, ray_.tMax, [&](const MajorantSegment& s) {
            segments.push_back(s);
            return true;
        });
        float covered = 0.0f;  // the end of the previous segment
        for (std::size_t i = 0; i < segments.size(); ++i) {
            const MajorantSegment& s = segments[i];
            if (s.tMin > s.tMax || exceeds(RGB(covered), RGB(s.tMin)))
                fail("segment ", i, " [", s.tMin, ", ", s.tMax,
                     ") runs backwards or overlaps the previous one (which ended at ", covered, ")");
            checkGap(covered, std::min(s.tMin, ray_.tMax));
            checkSegment(i, s);
            covered = std::max(covered, s.tMax);
        }
        checkGap(covered, ray_.tMax);

        int visits = 0;
        medium_.majorants(ray_.origin, ray_.direction, 0.0f, ray_.tMax, [&](const MajorantSegment&) {
            ++visits;
            return false;
        });
        if (visits > 1) fail("majorants() went on visiting after visit returned false");
        return check_;
    }

private:
    RGB sigmaTAt(float t) const {
        MediumProperties m = medium_.at(ray_.at(t));
        return m.sigmaA + m.sigmaS;
    }

    const Medium& medium_;
    const MediumRay& ray_;
    int points_;
    int failures_ = 0;
    MajorantCheck check_;
};

}  // namespace

MajorantCheck majorantsBound(const Medium& medium, const MediumRay& ray, int pointsPerStretch) {
    return Checker(medium, ray, pointsPerStretch).run();
}

}  // namespace fluence::media
