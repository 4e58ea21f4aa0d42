// Each sample's cost (integrators/sample_cost.h), as the render loop adds it to its pixel in the
// film: over the image, the costs add up to what the render counted (its rays by kind, its medium
// lookups and its guided random-walk steps, at their weights); a scene without media draws no medium
// lookups and takes no walk steps, and a subsurface interior's random walks do both and make its
// pixels cost more. A bounce ray costs more than a shadow ray; an exact flight's start is charged,
// even where it walks no cell.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "integrators/path_tracer.h"
#include "integrators/renderer.h"
#include "integrators/sample_cost.h"
#include "tests/integrators/render_support.h"
#include "tests/integrators/smoke_cube.h"
#include "tests/support/scenes.h"
#include "tests/support/subsurface_material.h"

namespace fluence::integrators {
namespace {

constexpr int kSize = 12;

double filmCost(const Film& film) {
    double sum = 0.0;
    for (int y = 0; y < film.height(); ++y)
        for (int x = 0; x < film.width(); ++x) sum += film.cost(x, y);
    return sum;
}

test_support::RenderedFilm renderFourSamples(const render::SceneDescription& desc,
                                             const IntegratorSettings& integrator = {}) {
    RenderSettings settings;
    settings.samplesPerPixel = 4;
    return test_support::renderFilm(PathTracer(integrator), desc, kSize, settings);
}

// The film's cost less the counters' at their weights: each missed sample is charged
// kMissedCameraRayCost instead of its camera ray's kCameraRayCost.
double missedSamplesCharge(const test_support::RenderedFilm& r) {
    return filmCost(r.film) - countedCost(r.stats.counters);
}

// The samples whose camera ray hit nothing: in these scenes (no media) each traced that ray only.
double missedSamples(const Film& film) {
    const Image image = film.resolve();
    double sum = 0.0;
    for (int y = 0; y < film.height(); ++y)
        for (int x = 0; x < film.width(); ++x)
            sum += film.samples(x, y) * (1.0 - image.pixel(x, y)[image.channelIndex("A")]);
    return std::round(sum);
}

void expectCostsAddUpToTheCounters(const test_support::RenderedFilm& r) {
    const double counted = countedCost(r.stats.counters);
    EXPECT_NEAR(missedSamplesCharge(r), (kMissedCameraRayCost - kCameraRayCost) * missedSamples(r.film),
                1e-12 * counted);
}

// The ray kinds cost what they do (sample_cost.h's fit): a bounce ray leads to a shading point, a
// shadow ray only tests occlusion, so two samples that trace as many rays cost differently when
// their kinds differ; weighting every ray 1 charged the Cornell box's corners (more bounces) less
// than their CPU.
TEST(SampleCost, ABounceRayCostsMoreThanAShadowRay) {
    const RenderCounters before;
    RenderCounters bouncing = before, shadowing = before;
    bouncing.camera = shadowing.camera = 1;
    bouncing.bounce = 3;
    shadowing.shadow = 3;
    EXPECT_EQ(bouncing.rays(), shadowing.rays());
    const double bounce = sampleCost(before, bouncing, true), shadow = sampleCost(before, shadowing, true);
    EXPECT_DOUBLE_EQ(bounce - shadow, 3.0 * (kBounceRayCost - kShadowRayCost));
    EXPECT_GT(bounce, 2.0 * shadow);
}

// A sample that is its camera ray, meeting nothing, is charged kMissedCameraRayCost; the same ray
// hitting a surface that ends the path (nothing further traced) costs a camera ray.
TEST(SampleCost, AMissedSampleIsChargedAsMissed) {
    const RenderCounters before;
    RenderCounters one = before;
    one.camera = 1;
    EXPECT_EQ(sampleCost(before, one, false), kMissedCameraRayCost);
    EXPECT_EQ(sampleCost(before, one, true), kCameraRayCost);
}

// A missed sample whose camera ray started an exact flight (through a grid volume's bounds,
// walking no cell) is charged the flight too: the smoke's background samples took 209 ns against
// the subsurface scene's 92 ns (sample_cost.h), which no other counter told apart.
TEST(SampleCost, AMissedSampleIsChargedTheExactFlightsItStarted) {
    const RenderCounters before;
    RenderCounters plain = before;
    plain.camera = 1;
    RenderCounters throughAVolume = plain;
    throughAVolume.exactFlights = 1;
    EXPECT_DOUBLE_EQ(sampleCost(before, throughAVolume, false), kMissedCameraRayCost + kExactFlightCost);
    EXPECT_GT(sampleCost(before, throughAVolume, false), 1.5 * sampleCost(before, plain, false));
}

TEST(Renderer, EachSamplesCostIsItsRaysOnSurfaces) {
    const test_support::RenderedFilm r = renderFourSamples(test::litSphereUnderASky());
    EXPECT_EQ(r.stats.counters.mediumCollisions, 0u);
    expectCostsAddUpToTheCounters(r);
    // A sky pixel's sample traces its camera ray only, which meets nothing.
    EXPECT_EQ(r.film.cost(0, 0), 4.0 * kMissedCameraRayCost);
}

TEST(Renderer, EachSamplesCostCountsTheStepsOfAGuidedSubsurfaceWalk) {
    render::SceneDescription surface = test::litSphereUnderASky(), walk = surface;
    walk.materials[0] = test::subsurfaceMaterial("/mat", RGB(0.8f, 0.6f, 0.4f), RGB(0.3f, 0.2f, 0.1f));
    walk.materials[0].subsurfaceMethod = render::SubsurfaceMethod::RandomWalkGuided;
    const test_support::RenderedFilm opaque = renderFourSamples(surface), translucent = renderFourSamples(walk);
    EXPECT_GT(translucent.stats.counters.walkSteps, 0u);
    EXPECT_EQ(opaque.stats.counters.walkSteps, 0u);
    expectCostsAddUpToTheCounters(translucent);
    const int centre = kSize / 2;
    std::printf("[ measured ] centre pixel's cost per sample: %.1f opaque, %.1f subsurface\n",
                opaque.film.cost(centre, centre) / 4, translucent.film.cost(centre, centre) / 4);
    EXPECT_GT(translucent.film.cost(centre, centre), opaque.film.cost(centre, centre));
}

// kWalkStepCost was fitted on the guided walk only: the classic walk's steps (and any other
// interior medium's, such as tinted glass) are charged by their medium collisions alone.
TEST(Renderer, AClassicSubsurfaceWalkIsChargedByItsMediumLookupsOnly) {
    render::SceneDescription walk = test::litSphereUnderASky();
    walk.materials[0] = test::subsurfaceMaterial("/mat", RGB(0.8f, 0.6f, 0.4f), RGB(0.3f, 0.2f, 0.1f));
    walk.materials[0].subsurfaceMethod = render::SubsurfaceMethod::RandomWalk;
    const test_support::RenderedFilm translucent = renderFourSamples(walk);
    EXPECT_GT(translucent.stats.counters.mediumCollisions, 0u);
    EXPECT_EQ(translucent.stats.counters.walkSteps, 0u);
    expectCostsAddUpToTheCounters(translucent);
}

// Exact flights (--exact-flights 1: the camera ray's) walk grid cells, charged at
// kExactCellCost each, not as medium lookups; the flights after the first stay tracked and are
// charged by their lookups. At level 0 no cell is walked. (In a medium, a camera ray that leaves
// without scattering may count as missing the scene, alpha below 1, so the missed samples are not
// read from the alpha channel as above: the film's cost is the counters' sum plus a whole number of
// missed samples' difference, kMissedCameraRayCost - kCameraRayCost each.)
void expectCostsAddUpToTheCountersWithSomeMissed(const test_support::RenderedFilm& r) {
    const double missed = missedSamplesCharge(r) / (kMissedCameraRayCost - kCameraRayCost);
    EXPECT_NEAR(missed, std::round(missed), 1e-6)
        << countedCost(r.stats.counters) << " counted, " << filmCost(r.film) << " on the film";
    EXPECT_GE(std::round(missed), 0.0);
    EXPECT_LE(std::round(missed), double(r.stats.counters.camera));
}

TEST(Renderer, EachSamplesCostChargesTheCellsOfExactFlightsAsCells) {
    test::TempDir dir("sample_cost_exact");
    render::SceneDescription smoke = test::smokeUnderAWhiteSky(test::writeSmokeCube(dir), 2.0f, RGB(0.9f));
    smoke.camera->transform = Matrix4::translate(Vec3d(1.0, 1.0, 5.0));  // looking down -z through the cube
    IntegratorSettings cameraRayOnly;
    cameraRayOnly.parameters["exact-flights"] = 1;
    const test_support::RenderedFilm exact = renderFourSamples(smoke, cameraRayOnly);
    EXPECT_GT(exact.stats.counters.exactCells, 0u);
    EXPECT_GT(exact.stats.counters.mediumCollisions, 0u);
    expectCostsAddUpToTheCountersWithSomeMissed(exact);
    EXPECT_EQ(exact.stats.counters.exactFlights, exact.stats.counters.camera);  // level 1: the camera rays'
    IntegratorSettings tracked;
    tracked.parameters["exact-flights"] = 0;
    const test_support::RenderedFilm tracking = renderFourSamples(smoke, tracked);
    EXPECT_EQ(tracking.stats.counters.exactCells, 0u);
    EXPECT_EQ(tracking.stats.counters.exactFlights, 0u);
    expectCostsAddUpToTheCountersWithSomeMissed(tracking);
}

// A camera looking away from the smoke cube: each camera ray starts an exact flight through the
// scene's volume and walks no cell (the smoke peer's background), so each sample is charged as a
// missed sample and its flight, above a missed sample of a scene without a volume.
TEST(Renderer, EachSamplesCostChargesAnExactFlightThatWalksNoCell) {
    test::TempDir dir("sample_cost_flight");
    render::SceneDescription smoke = test::smokeUnderAWhiteSky(test::writeSmokeCube(dir), 2.0f, RGB(0.9f));
    smoke.camera->transform = Matrix4::translate(Vec3d(1.0, 1.0, -5.0));  // looking down -z, the cube behind
    IntegratorSettings cameraRayOnly;
    cameraRayOnly.parameters["exact-flights"] = 1;
    const test_support::RenderedFilm away = renderFourSamples(smoke, cameraRayOnly);
    EXPECT_EQ(away.stats.counters.exactCells, 0u);
    EXPECT_EQ(away.stats.counters.exactFlights, away.stats.counters.camera);
    EXPECT_EQ(away.stats.counters.rays(), away.stats.counters.camera);
    EXPECT_DOUBLE_EQ(away.film.cost(0, 0), 4.0 * (kMissedCameraRayCost + kExactFlightCost));
    EXPECT_GT(away.film.cost(0, 0), renderFourSamples(test::litSphereUnderASky()).film.cost(0, 0));
}

}  // namespace
}  // namespace fluence::integrators
