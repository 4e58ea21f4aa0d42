// make_smoke: writes a procedural smoke plume as an OpenVDB file with two float grids, "density"
// and "temperature" (usd_samples/smoke/smoke.vdb was made by `make_smoke usd_samples/smoke/smoke.vdb`).
//
//   make_smoke OUT.vdb [--seed N] [--voxel-size S]      (defaults: seed 1, voxel size 0.02)
//
// THE PLUME, in the grid's space (Y up, voxel (i, j, k) at S * (i, j, k), the base at y = 0):
// 3 units tall; its axis rises from the origin, leaning towards +X and swaying in a slow spiral; its
// radius grows from 0.12 at the base to 0.75 at the top. Density is a soft radial profile whose
// radius is displaced by fractal value noise (5 octaves), times a second, finer noise for detail,
// faded in over the first 0.15 units and out over the top quarter, and thinning with height;
// values in [0, 1]. Temperature
// (unitless, in [0, 1]: a material scales it to kelvin) is hot in the core near the base and cools
// with height and distance from the axis. Values below 0.01 are not stored.
//
// DETERMINISM. The noise lattice is hashed from the seed and the lattice point with SplitMix64's
// finaliser (core/random.h), with no library random numbers, so a seed always gives the same grids
// (the files differ only in the random UUID OpenVDB writes into every header).
#include <openvdb/openvdb.h>
#include <openvdb/tools/Statistics.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <sstream>
#include <string>

#include "core/random.h"

namespace {

constexpr double kHeight = 3.0, kBaseRadius = 0.12, kTopRadius = 0.75;

double smoothstep(double e0, double e1, double x) {
    double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
    return t * t * (3.0 - 2.0 * t);
}

// Value noise in [-1, 1]: random values at integer lattice points, interpolated with a smoothstep fade.
class ValueNoise {
public:
    explicit ValueNoise(std::uint64_t seed) : seed_(fluence::mix64(seed)) {}

    double operator()(double x, double y, double z) const {
        double fx = std::floor(x), fy = std::floor(y), fz = std::floor(z);
        double u = fade(x - fx), v = fade(y - fy), w = fade(z - fz);
        auto ix = std::int64_t(fx), iy = std::int64_t(fy), iz = std::int64_t(fz);
        double sum = 0.0;
        for (int corner = 0; corner < 8; ++corner) {
            int dx = corner & 1, dy = corner >> 1 & 1, dz = corner >> 2 & 1;
            double weight = (dx ? u : 1.0 - u) * (dy ? v : 1.0 - v) * (dz ? w : 1.0 - w);
            sum += weight * lattice(ix + dx, iy + dy, iz + dz);
        }
        return sum;
    }

    // Fractal sum of `octaves` octaves, each of double frequency and half amplitude, normalised to [-1, 1].
    double fbm(double x, double y, double z, int octaves) const {
        double sum = 0.0, amplitude = 1.0, norm = 0.0;
        for (int o = 0; o < octaves; ++o) {
            sum += amplitude * (*this)(x, y, z);
            norm += amplitude;
            amplitude *= 0.5;
            x = 2.0 * x + 17.3;  // offsets decorrelate the octaves
            y = 2.0 * y + 5.1;
            z = 2.0 * z + 11.7;
        }
        return sum / norm;
    }

private:
    static double fade(double t) { return t * t * (3.0 - 2.0 * t); }
    double lattice(std::int64_t x, std::int64_t y, std::int64_t z) const {
        std::uint64_t h = fluence::mix64(seed_ ^ fluence::mix64(std::uint64_t(x) * 0x9e3779b97f4a7c15ull ^
                                                                std::uint64_t(y) * 0xc2b2ae3d27d4eb4full ^
                                                                std::uint64_t(z) * 0x165667b19e3779f9ull));
        return fluence::toUnitFloat(h) * 2.0 - 1.0;
    }

    std::uint64_t seed_;
};

struct Sample {
    double density, temperature;
};

class Plume {
public:
    explicit Plume(std::uint64_t seed) : shape_(seed), detail_(seed + 1), heat_(seed + 2) {}

    Sample at(double x, double y, double z) const {
        double h = y / kHeight;
        if (h < 0.0 || h > 1.0) return {0.0, 0.0};
        // The axis: a lean towards +X and a slow spiral sway, both growing with height.
        double angle = 2.0 * std::numbers::pi * 1.3 * h;
        double ax = 0.35 * h * h + 0.12 * h * std::sin(angle), az = 0.12 * h * std::cos(angle) - 0.06 * h;
        double radius = kBaseRadius + (kTopRadius - kBaseRadius) * std::pow(h, 0.8);
        double rho = std::hypot(x - ax, z - az) / radius;
        if (rho > 2.0) return {0.0, 0.0};
        double bumps = shape_.fbm(2.5 * x, 2.5 * y, 2.5 * z, 5);
        double profile = smoothstep(1.0 + 0.8 * bumps, 0.2, rho);
        double texture = std::clamp(0.4 + 1.4 * detail_.fbm(7.0 * x, 7.0 * y, 7.0 * z, 4), 0.0, 1.3);
        double envelope = smoothstep(0.0, 0.15, y) * (1.0 - smoothstep(0.75 * kHeight, kHeight, y)) * (1.0 - 0.45 * h);
        double density = std::clamp(profile * texture * envelope, 0.0, 1.0);
        double core =
            smoothstep(0.9, 0.0, rho) * std::exp(-y / 0.7) * (0.8 + 0.4 * heat_.fbm(4.0 * x, 4.0 * y, 4.0 * z, 3));
        return {density, std::clamp(core, 0.0, 1.0) * (density > 0.0 ? 1.0 : 0.0)};
    }

private:
    ValueNoise shape_, detail_, heat_;
};

int usage() {
    std::fprintf(stderr, "usage: make_smoke OUT.vdb [--seed N] [--voxel-size S]\n");
    return 2;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) return usage();
    std::string out = argv[1];
    std::uint64_t seed = 1;
    double voxel = 0.02;
    for (int i = 2; i < argc; ++i) {
        std::string flag = argv[i];
        if (i + 1 >= argc) return usage();
        if (flag == "--seed")
            seed = std::stoull(argv[++i]);
        else if (flag == "--voxel-size")
            voxel = std::stod(argv[++i]);
        else
            return usage();
    }
    if (!(voxel > 0.0)) return usage();

    openvdb::initialize();
    openvdb::FloatGrid::Ptr density = openvdb::FloatGrid::create(0.0f), temperature = openvdb::FloatGrid::create(0.0f);
    for (auto [grid, name] : {std::pair{density, "density"}, std::pair{temperature, "temperature"}}) {
        grid->setName(name);
        grid->setGridClass(openvdb::GRID_FOG_VOLUME);
        grid->setTransform(openvdb::math::Transform::createLinearTransform(voxel));
        grid->insertMeta("generator",
                         openvdb::StringMetadata("fluence tools/make_smoke --seed " + std::to_string(seed)));
    }
    Plume plume(seed);
    auto d = density->getAccessor();
    auto t = temperature->getAccessor();
    const int half = int(std::ceil(1.6 / voxel)), top = int(std::ceil(kHeight / voxel));
    for (int i = -half; i <= half; ++i)
        for (int j = 0; j <= top; ++j)
            for (int k = -half; k <= half; ++k) {
                Sample s = plume.at(i * voxel, j * voxel, k * voxel);
                if (s.density < 0.01) continue;
                d.setValue({i, j, k}, float(s.density));
                if (s.temperature >= 0.01) t.setValue({i, j, k}, float(s.temperature));
            }

    openvdb::io::File file(out);
    file.write({density, temperature});
    file.close();
    std::printf("wrote %s (%.2f MB): voxel size %g, seed %llu\n", out.c_str(),
                double(std::filesystem::file_size(out)) / 1e6, voxel, (unsigned long long)seed);
    for (const auto& grid : {density, temperature}) {
        openvdb::math::MinMax<float> range = openvdb::tools::minMax(grid->tree());
        std::ostringstream box;
        box << grid->evalActiveVoxelBoundingBox();
        std::printf("  %-11s %8llu active voxels, index box %s, values %.3f..%.3f\n", grid->getName().c_str(),
                    (unsigned long long)grid->activeVoxelCount(), box.str().c_str(), range.min(), range.max());
    }
    return 0;
}
