// Screen-space dicing rates: segments per edge follow the edge's size in pixels.
#include "delegate/dicing.h"

#include <gtest/gtest.h>

namespace fluence::delegate {
namespace {

// A camera at the origin looking down -Z, 100 pixels across a 90-degree field of view: one scene
// unit at distance d spans 50 / d pixels.
render::Camera testCamera() {
    render::CameraDesc d;
    d.focalLength = 10;
    d.horizontalAperture = d.verticalAperture = 20;
    d.nearClip = 0.1f;
    return render::Camera(d, 100, 100);
}

TEST(Dicing, SegmentsFollowPixelLengthAndRate) {
    render::Camera camera = testCamera();
    DicingSettings settings;
    // A 2-unit edge 10 units away (in view) spans 10 pixels; a 2-unit edge at 50 units spans 2.
    std::vector<std::pair<Vec3f, Vec3f>> edges = {{Vec3f(-1, 0, -10), Vec3f(1, 0, -10)},
                                                  {Vec3f(-1, 0, -50), Vec3f(1, 0, -50)}};
    EXPECT_EQ(edgeSegments(camera, settings, 1.0f, edges), (std::vector<int>{10, 2}));
    EXPECT_EQ(edgeSegments(camera, settings, 4.0f, edges), (std::vector<int>{3, 1})) << "ceil(10/4), at least one";
    EXPECT_EQ(edgeSegments(camera, settings, 1.0f, edges, 0.5f), (std::vector<int>{5, 1})) << "budget scale";
}

TEST(Dicing, OffscreenEdgesAreCoarserAndCountsAreClamped) {
    render::Camera camera = testCamera();
    DicingSettings settings;
    // Behind the camera, 10 units away: 10 pixels by distance, divided by the off-screen factor 8.
    std::vector<std::pair<Vec3f, Vec3f>> behind = {{Vec3f(-1, 0, 10), Vec3f(1, 0, 10)}};
    EXPECT_EQ(edgeSegments(camera, settings, 1.0f, behind), std::vector<int>{2});
    // An edge whose ends are off-screen but whose middle is in view counts as in view.
    std::vector<std::pair<Vec3f, Vec3f>> across = {{Vec3f(-40, 0, -10), Vec3f(40, 0, -10)}};
    EXPECT_EQ(edgeSegments(camera, settings, 1.0f, across), std::vector<int>{settings.maxSegments})
        << "400 px, clamped";
    settings.maxSegments = 1000;
    EXPECT_EQ(edgeSegments(camera, settings, 1.0f, across), std::vector<int>{400});
    std::vector<std::pair<Vec3f, Vec3f>> degenerate = {{Vec3f(0, 0, -1), Vec3f(0, 0, -1)}};
    EXPECT_EQ(edgeSegments(camera, settings, 1.0f, degenerate), std::vector<int>{1});
}

}  // namespace
}  // namespace fluence::delegate
