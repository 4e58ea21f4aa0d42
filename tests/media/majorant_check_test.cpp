// The majorant checker (media/majorant_check.h) accepts media that keep the contract of
// media/medium.h and catches each way of breaking it: a majorant below sigmaT, a minorant above
// it, density where no segment covers the ray, overlapping segments, and a medium that keeps
// visiting after being told to stop.
#include "media/majorant_check.h"

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "media/homogeneous_medium.h"
#include "tests/media/test_media.h"

namespace fluence::media {
namespace {

const MediumRay kAlongX{Vec3f(-0.5f, 0.0f, 0.0f), Vec3f(1.0f, 0.0f, 0.0f), 4.0f};

// A homogeneous sigmaT that reports the segments it is given, whatever the ray.
class ScriptedMedium final : public Medium {
public:
    explicit ScriptedMedium(std::vector<MajorantSegment> segments, bool ignoresStop = false)
        : segments_(std::move(segments)), ignoresStop_(ignoresStop) {}
    MediumProperties at(const Vec3f&) const override { return {RGB(0.5f), RGB(0.5f)}; }
    void majorants(const Vec3f&, const Vec3f&, float, float,
                   FunctionRef<bool(const MajorantSegment&)> visit) const override {
        for (const MajorantSegment& s : segments_)
            if (!visit(s) && !ignoresStop_) return;
    }

private:
    std::vector<MajorantSegment> segments_;
    bool ignoresStop_;
};

void expectCaught(const Medium& medium, const MediumRay& ray, const char* expectedWords) {
    MajorantCheck check = majorantsBound(medium, ray);
    EXPECT_FALSE(check.bound);
    EXPECT_NE(check.report.find(expectedWords), std::string::npos) << check.report;
}

TEST(MajorantCheck, AcceptsMediaThatKeepTheContract) {
    HomogeneousMedium fog({RGB(0.1f, 0.2f, 0.3f), RGB(1.0f)});
    test::RampMedium ramp(RGB(0.2f, 1.0f, 2.0f), RGB(0.8f, 0.0f, -0.5f), 3.0f, 7, true, RGB(0.5f));
    test::RescaledBoundsMedium loose(ramp, 1.5f, 0.0f);
    const MediumRay oblique{Vec3f(-1.0f, 0.5f, 0.0f), normalize(Vec3f(1.0f, -0.3f, 0.2f)), 6.0f};
    for (const Medium* medium :
         {static_cast<const Medium*>(&fog), static_cast<const Medium*>(&ramp), static_cast<const Medium*>(&loose)})
        for (const MediumRay& ray : {kAlongX, oblique}) {
            MajorantCheck check = majorantsBound(*medium, ray);
            EXPECT_TRUE(check.bound) << check.report;
        }
    ScriptedMedium adjacent({{0.0f, 1.0f, RGB(1.0f)}, {1.0f, 2.0f, RGB(1.0f), RGB(1.0f)}});
    EXPECT_TRUE(majorantsBound(adjacent, {Vec3f(0.0f), Vec3f(0.0f, 0.0f, 1.0f), 2.0f}).bound);
}

TEST(MajorantCheck, CatchesAMajorantBelowSigmaT) {
    test::RampMedium ramp(RGB(0.2f), RGB(0.8f), 3.0f, 7, false);
    test::RescaledBoundsMedium low(ramp, 0.97f, 0.0f);
    expectCaught(low, kAlongX, "> sigmaMaj");
    HomogeneousMedium fog({RGB(0.0f), RGB(1.0f, 2.0f, 3.0f)});
    test::RescaledBoundsMedium halved(fog, 0.5f, 0.0f);
    expectCaught(halved, kAlongX, "> sigmaMaj");
}

TEST(MajorantCheck, CatchesAMinorantAboveSigmaT) {
    test::RampMedium ramp(RGB(0.2f), RGB(0.8f), 3.0f, 7, true);
    test::RescaledBoundsMedium high(ramp, 1.0f, 1.2f);
    expectCaught(high, kAlongX, "< sigmaMin");
}

TEST(MajorantCheck, CatchesDensityNoSegmentCovers) {
    ScriptedMedium partial({{0.0f, 1.0f, RGB(1.0f)}, {1.5f, 2.0f, RGB(1.0f)}});
    expectCaught(partial, {Vec3f(0.0f), Vec3f(0.0f, 0.0f, 1.0f), 2.0f}, "no segment covers");
}

TEST(MajorantCheck, CatchesOverlappingSegmentsAndBadBounds) {
    ScriptedMedium overlapping({{0.0f, 1.5f, RGB(1.0f)}, {1.0f, 2.0f, RGB(1.0f)}});
    expectCaught(overlapping, {Vec3f(0.0f), Vec3f(0.0f, 0.0f, 1.0f), 2.0f}, "overlaps");
    ScriptedMedium crossed({{0.0f, 2.0f, RGB(1.0f), RGB(2.0f)}});
    expectCaught(crossed, {Vec3f(0.0f), Vec3f(0.0f, 0.0f, 1.0f), 2.0f}, "needs 0 <= sigmaMin");
}

TEST(MajorantCheck, CatchesAMediumThatDoesNotStop) {
    ScriptedMedium endless({{0.0f, 1.0f, RGB(1.0f)}, {1.0f, 2.0f, RGB(1.0f)}}, true);
    expectCaught(endless, {Vec3f(0.0f), Vec3f(0.0f, 0.0f, 1.0f), 2.0f}, "went on visiting");
}

}  // namespace
}  // namespace fluence::media
