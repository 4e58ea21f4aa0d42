// USDA parsing benchmark: parse throughput, Stage::open time and peak memory on a large,
// production-like layer generated in memory (deterministically), written to a temporary file.
//
//   usda_parse_bench [--meshes N] [--grid WxH] [--runs N] [--keep FILE]
//   usda_parse_bench --file LAYER.usda [--runs N]     (an existing layer instead of the generated one)
//   usda_parse_bench --file LAYER.usda --parse-once   (one parse and nothing else: for profilers,
//                                                      e.g. valgrind --tool=callgrind)
//
// The generated layer (defaults: 2,000 meshes of a 32x40-vertex grid, 2.56 M points):
//   /Assets      2,000 Xform "Prop_NNNN" > Mesh "geo": points, vertex normals, faceVarying indexed
//                primvars:st (+ :indices), faceVertexCounts/Indices, extent, displayColor,
//                a material:binding relationship; kind and apiSchemas metadata
//   /World/Looks 64 Materials, each a UsdPreviewSurface <- UsdUVTexture <- UsdPrimvarReader_float2
//                network wired with .connect, plus inputs with constant values
//   /World/Set   2,000 Xform instances with `prepend references = </Assets/Prop_NNNN>` (internal
//                references), translate/rotate/scale ops; every 8th instance has 48 time samples
//                on its translate and rotateXYZ
// Figures (see bench/results/2026-11-27-usda-parse.md for the targets):
//   parse    usd::parseUsdaString on text already in memory: best and median of --runs, MB/s
//   open     usd::Stage::open on the file (read + parse + composition, where the Stage composes)
//   memory   in a fresh child process (this executable again), VmHWM before and after
//            Stage::open, and after parseUsdaString of text already read, against the bytes of the
//            parsed values' payloads (numbers at 8 bytes each, string characters); and the payload
//            the composed layer holds of its own (numbers it shares with the root layer left out)
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <unordered_set>
#include <vector>

#include "bench/process_status.h"
#include "scene/stage.h"
#include "scene/usda_parser.h"

namespace {

using namespace fluence::usd;
using Clock = std::chrono::steady_clock;

// ---- Deterministic layer generator ---------------------------------------------------------------

struct Options {
    int meshes = 2000;
    int gridW = 32, gridH = 40;
    int runs = 5;
    int materials = 64;
    std::string keep;  // write the generated layer here and keep it
    std::string file;  // benchmark this existing layer instead
    bool parseOnce = false;
};

class Random {  // xorshift64*: the same stream on every machine
public:
    explicit Random(std::uint64_t seed) : state_(seed ? seed : 1) {}
    double uniform() {  // [0, 1)
        state_ ^= state_ >> 12, state_ ^= state_ << 25, state_ ^= state_ >> 27;
        return static_cast<double>((state_ * 2685821657736338717ull) >> 11) * 0x1.0p-53;
    }

private:
    std::uint64_t state_;
};

class Writer {
public:
    std::string text;
    Writer& operator<<(std::string_view s) {
        text.append(s);
        return *this;
    }
    Writer& operator<<(char c) {
        text.push_back(c);
        return *this;
    }
    Writer& operator<<(int v) { return number(v); }
    // Floats as USD writes them: the shortest text that round-trips the float32 value.
    Writer& f(float v) {
        char buffer[32];
        auto end = std::to_chars(buffer, buffer + sizeof buffer, v).ptr;
        text.append(buffer, end);
        return *this;
    }
    Writer& d(double v) {
        char buffer[32];
        auto end = std::to_chars(buffer, buffer + sizeof buffer, v).ptr;
        text.append(buffer, end);
        return *this;
    }
    Writer& number(long v) {
        char buffer[24];
        auto end = std::to_chars(buffer, buffer + sizeof buffer, v).ptr;
        text.append(buffer, end);
        return *this;
    }
    Writer& tuple(std::initializer_list<float> values) {
        text.push_back('(');
        bool first = true;
        for (float v : values) {
            if (!first) text.append(", ");
            first = false;
            f(v);
        }
        text.push_back(')');
        return *this;
    }
};

std::string padded(int i, int width = 4) {
    std::string s = std::to_string(i);
    return std::string(width > static_cast<int>(s.size()) ? width - s.size() : 0, '0') + s;
}

void writeMesh(Writer& w, int index, const Options& o, Random& random) {
    const int W = o.gridW, H = o.gridH;
    const float size = 10.0f + 90.0f * static_cast<float>(random.uniform());
    const float bump = 0.05f + 0.5f * static_cast<float>(random.uniform());
    const float phase = 6.2831853f * static_cast<float>(random.uniform());
    auto height = [&](float u, float v) {
        return bump * size * std::sin(3.0f * u + phase) * std::cos(2.0f * v - phase);
    };
    std::vector<float> px, py, pz, nx, ny, nz;
    for (int j = 0; j < H; ++j) {
        for (int i = 0; i < W; ++i) {
            float u = static_cast<float>(i) / static_cast<float>(W - 1);
            float v = static_cast<float>(j) / static_cast<float>(H - 1);
            float jitter = 0.001f * size * static_cast<float>(random.uniform() - 0.5);
            px.push_back((u - 0.5f) * size + jitter);
            py.push_back(height(u, v));
            pz.push_back((v - 0.5f) * size - jitter);
            float du = (height(u + 1e-3f, v) - height(u - 1e-3f, v)) / (2e-3f * size);
            float dv = (height(u, v + 1e-3f) - height(u, v - 1e-3f)) / (2e-3f * size);
            float len = std::sqrt(du * du + 1.0f + dv * dv);
            nx.push_back(-du / len), ny.push_back(1.0f / len), nz.push_back(-dv / len);
        }
    }
    const int faces = (W - 1) * (H - 1);
    std::string name = "Prop_" + padded(index);
    w << "    def Xform \"" << name << "\" (\n        kind = \"component\"\n    )\n    {\n";
    w << "        def Mesh \"geo\" (\n            prepend apiSchemas = [\"MaterialBindingAPI\"]\n"
      << "        )\n        {\n";
    float minY = *std::min_element(py.begin(), py.end()), maxY = *std::max_element(py.begin(), py.end());
    w << "            float3[] extent = [";
    w.tuple({-0.5f * size, minY, -0.5f * size}) << ", ";
    w.tuple({0.5f * size, maxY, 0.5f * size}) << "]\n";
    w << "            int[] faceVertexCounts = [";
    for (int f = 0; f < faces; ++f) w << (f ? ", 4" : "4");
    w << "]\n            int[] faceVertexIndices = [";
    for (int j = 0, f = 0; j < H - 1; ++j) {
        for (int i = 0; i < W - 1; ++i, ++f) {
            int a = j * W + i;
            if (f) w << ", ";
            w << a << ", " << a + 1 << ", " << a + W + 1 << ", " << a + W;
        }
    }
    w << "]\n            rel material:binding = </World/Looks/Mat_" << padded(index % o.materials, 3) << ">\n";
    w << "            normal3f[] normals = [";
    for (std::size_t k = 0; k < nx.size(); ++k) {
        if (k) w << ", ";
        w.tuple({nx[k], ny[k], nz[k]});
    }
    w << "] (\n                interpolation = \"vertex\"\n            )\n";
    w << "            point3f[] points = [";
    for (std::size_t k = 0; k < px.size(); ++k) {
        if (k) w << ", ";
        w.tuple({px[k], py[k], pz[k]});
    }
    w << "]\n            color3f[] primvars:displayColor = [";
    w.tuple({static_cast<float>(random.uniform()), static_cast<float>(random.uniform()),
             static_cast<float>(random.uniform())});
    w << "] (\n                interpolation = \"constant\"\n            )\n";
    w << "            texCoord2f[] primvars:st = [";
    for (int j = 0; j < H; ++j) {
        for (int i = 0; i < W; ++i) {
            if (i || j) w << ", ";
            w.tuple(
                {static_cast<float>(i) / static_cast<float>(W - 1), static_cast<float>(j) / static_cast<float>(H - 1)});
        }
    }
    w << "] (\n                interpolation = \"faceVarying\"\n            )\n";
    w << "            int[] primvars:st:indices = [";
    for (int j = 0, f = 0; j < H - 1; ++j) {
        for (int i = 0; i < W - 1; ++i, ++f) {
            int a = j * W + i;
            if (f) w << ", ";
            w << a << ", " << a + 1 << ", " << a + W + 1 << ", " << a + W;
        }
    }
    w << "]\n            uniform token subdivisionScheme = \"none\"\n        }\n    }\n\n";
}

void writeMaterial(Writer& w, int index, Random& random) {
    std::string name = "Mat_" + padded(index, 3);
    std::string path = "/World/Looks/" + name;
    w << "        def Material \"" << name << "\"\n        {\n"
      << "            token outputs:surface.connect = <" << path << "/Surface.outputs:surface>\n\n"
      << "            def Shader \"Surface\"\n            {\n"
      << "                uniform token info:id = \"UsdPreviewSurface\"\n"
      << "                color3f inputs:diffuseColor.connect = <" << path << "/Texture.outputs:rgb>\n"
      << "                float inputs:metallic = ";
    w.f(static_cast<float>(random.uniform() < 0.2)) << "\n                float inputs:roughness = ";
    w.f(static_cast<float>(random.uniform())) << "\n                color3f inputs:emissiveColor = ";
    w.tuple({0.0f, 0.0f, 0.0f}) << "\n"
                                << "                token outputs:surface\n            }\n\n"
                                << "            def Shader \"Texture\"\n            {\n"
                                << "                uniform token info:id = \"UsdUVTexture\"\n"
                                << "                asset inputs:file = @textures/" << name << "_diffuse.png@\n"
                                << "                token inputs:sourceColorSpace = \"sRGB\"\n"
                                << "                float2 inputs:st.connect = <" << path << "/Reader.outputs:result>\n"
                                << "                float3 outputs:rgb\n            }\n\n"
                                << "            def Shader \"Reader\"\n            {\n"
                                << "                uniform token info:id = \"UsdPrimvarReader_float2\"\n"
                                << "                string inputs:varname = \"st\"\n"
                                << "                float2 outputs:result\n            }\n        }\n\n";
}

void writeInstance(Writer& w, int index, Random& random) {
    std::string name = "Inst_" + padded(index);
    w << "        def Xform \"" << name << "\" (\n"
      << "            prepend references = </Assets/Prop_" << padded(index) << ">\n        )\n        {\n";
    float x = static_cast<float>(2000.0 * (random.uniform() - 0.5));
    float z = static_cast<float>(2000.0 * (random.uniform() - 0.5));
    float angle = static_cast<float>(360.0 * random.uniform());
    if (index % 8 == 0) {
        w << "            double3 xformOp:translate.timeSamples = {\n";
        for (int t = 1; t <= 48; ++t) {
            w << "                " << t << ": (";
            w.d(x + 0.5 * t) << ", 0, ";
            w.d(z - 0.25 * t) << "),\n";
        }
        w << "            }\n            float3 xformOp:rotateXYZ.timeSamples = {\n";
        for (int t = 1; t <= 48; ++t) {
            w << "                " << t << ": ";
            w.tuple({0.0f, angle + 7.5f * static_cast<float>(t), 0.0f}) << ",\n";
        }
        w << "            }\n";
    } else {
        w << "            double3 xformOp:translate = (";
        w.d(x) << ", 0, ";
        w.d(z) << ")\n            float3 xformOp:rotateXYZ = ";
        w.tuple({0.0f, angle, 0.0f}) << "\n";
    }
    w << "            float3 xformOp:scale = ";
    float s = static_cast<float>(0.5 + random.uniform());
    w.tuple({s, s, s}) << "\n"
                       << "            uniform token[] xformOpOrder = [\"xformOp:translate\", \"xformOp:rotateXYZ\", "
                          "\"xformOp:scale\"]\n        }\n\n";
}

std::string generateLayer(const Options& o) {
    Random random(20261127);
    Writer w;
    w.text.reserve(static_cast<std::size_t>(o.meshes) * o.gridW * o.gridH * 110 + (1 << 20));
    w << "#usda 1.0\n(\n    defaultPrim = \"World\"\n    doc = \"usda_parse_bench: generated, "
         "production-like layer\"\n    endTimeCode = 48\n    framesPerSecond = 24\n"
         "    metersPerUnit = 0.01\n    startTimeCode = 1\n    timeCodesPerSecond = 24\n"
         "    upAxis = \"Y\"\n)\n\n";
    w << "def Scope \"Assets\"\n{\n";
    for (int i = 0; i < o.meshes; ++i) writeMesh(w, i, o, random);
    w << "}\n\ndef Xform \"World\" (\n    kind = \"assembly\"\n)\n{\n    def Scope \"Looks\"\n    {\n";
    for (int i = 0; i < o.materials; ++i) writeMaterial(w, i, random);
    w << "    }\n\n    def Xform \"Set\"\n    {\n";
    for (int i = 0; i < o.meshes; ++i) writeInstance(w, i, random);
    w << "    }\n}\n";
    return std::move(w.text);
}

// ---- Measuring -----------------------------------------------------------------------------------

struct LayerStats {
    std::size_t prims = 0, attributes = 0, relationships = 0, values = 0, timeSamples = 0;
    std::size_t numbers = 0, stringBytes = 0, strings = 0;
    std::size_t numberCapacity = 0;  // doubles allocated (vector capacity), for the overhead
    // The number arrays counted: a value whose numbers are already counted (an array shared with
    // another value: usd::NumberArray) adds none.
    std::unordered_set<const double*> arrays;
    std::size_t sharedArrays = 0;
    std::size_t payloadBytes() const { return numbers * sizeof(double) + stringBytes; }
};

void count(const Value& value, LayerStats& s) {
    ++s.values;
    if (!value.numbers.empty() && !s.arrays.insert(value.numbers.data()).second) {
        ++s.sharedArrays;
    } else {
        s.numbers += value.numbers.size();
        s.numberCapacity += value.numbers.vector().capacity();
    }
    s.strings += value.strings.size();
    for (const std::string& str : value.strings) s.stringBytes += str.size();
    for (const Value& item : value.items) count(item, s);
    if (value.dictionary) {
        for (const auto& [key, entry] : *value.dictionary) {
            s.stringBytes += key.size();
            count(entry, s);
        }
    }
}

void count(const Metadata& metadata, LayerStats& s) {
    for (const MetadataEntry& entry : metadata) count(entry.value, s);
}

void count(const std::vector<std::unique_ptr<PrimSpec>>& prims, LayerStats& s);

void countProperties(const std::vector<AttributeSpec>& attributes, const std::vector<RelationshipSpec>& relationships,
                     LayerStats& s) {
    for (const AttributeSpec& a : attributes) {
        ++s.attributes;
        if (a.hasDefault) count(a.defaultValue, s);
        for (const auto& [time, value] : a.timeSamples) {
            ++s.timeSamples;
            count(value, s);
        }
        for (const std::string& c : a.connections) s.stringBytes += c.size(), ++s.strings;
        count(a.metadata, s);
    }
    for (const RelationshipSpec& r : relationships) {
        ++s.relationships;
        for (const std::string& t : r.targets) s.stringBytes += t.size(), ++s.strings;
        count(r.metadata, s);
    }
}

// Variant sets, and those nested in variants where VariantSpec keeps them.
template <class Set>
void countVariantSets(const std::vector<Set>& sets, LayerStats& s) {
    for (const Set& set : sets) {
        for (const auto& variant : set.variants) {
            count(variant.metadata, s);
            countProperties(variant.attributes, variant.relationships, s);
            count(variant.children, s);
            if constexpr (requires { variant.variantSets; }) countVariantSets(variant.variantSets, s);
        }
    }
}

void count(const std::vector<std::unique_ptr<PrimSpec>>& prims, LayerStats& s) {
    for (const auto& prim : prims) {
        ++s.prims;
        count(prim->metadata, s);
        countProperties(prim->attributes, prim->relationships, s);
        countVariantSets(prim->variantSets, s);
        count(prim->children, s);
    }
}

// `counted`: the statistics of layers whose arrays are not to be counted again.
LayerStats statsOf(const Layer& layer, const LayerStats* counted = nullptr) {
    LayerStats s;
    if (counted) s.arrays = counted->arrays;
    count(layer.metadata, s);
    count(layer.rootPrims, s);
    return s;
}

std::string readFile(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    if (!file) throw std::runtime_error("cannot read " + path);
    std::ostringstream text;
    text << file.rdbuf();
    return text.str();
}

double seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

// The payload the stage's composed (flattened) layer holds of its own, beside the numbers it
// shares with the root layer `root`.
std::size_t composedPayload(const Stage& stage, const LayerStats& root) {
    return statsOf(stage.composedLayer(), &root).payloadBytes();
}

// The child process of the memory measurement: prints "key value" lines on stdout.
int memoryChild(const std::string& mode, const std::string& path) {
    if (mode == "open") {
        long rss0 = fluence::bench::statusKiB("VmRSS"), hwm0 = fluence::bench::statusKiB("VmHWM");
        auto stage = Stage::open(path);
        long rss1 = fluence::bench::statusKiB("VmRSS"), hwm1 = fluence::bench::statusKiB("VmHWM");
        LayerStats s = statsOf(stage->rootLayer());
        std::printf("rss0 %ld\nhwm0 %ld\nrss1 %ld\nhwm1 %ld\npayload %zu\ncomposed %zu\n", rss0, hwm0, rss1, hwm1,
                    s.payloadBytes(), composedPayload(*stage, s));
    } else {  // "parse": the text is read first; only the parse is measured
        std::string text = readFile(path);
        long rss0 = fluence::bench::statusKiB("VmRSS"), hwm0 = fluence::bench::statusKiB("VmHWM");
        auto layer = parseUsdaString(text, path);
        long rss1 = fluence::bench::statusKiB("VmRSS"), hwm1 = fluence::bench::statusKiB("VmHWM");
        LayerStats s = statsOf(*layer);
        std::printf("rss0 %ld\nhwm0 %ld\nrss1 %ld\nhwm1 %ld\npayload %zu\n", rss0, hwm0, rss1, hwm1, s.payloadBytes());
    }
    return 0;
}

struct MemoryFigures {
    long rss0 = 0, hwm0 = 0, rss1 = 0, hwm1 = 0;
    std::size_t payload = 0;
    std::size_t composed = 0;  // the composed layer's payload not shared with the root layer
};

MemoryFigures measureMemory(const std::string& mode, const std::string& path) {
    // Re-run this executable: a fresh process, so VmHWM holds nothing of the generator's.
    char exe[4096];
    ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
    if (n <= 0) throw std::runtime_error("cannot find this executable (/proc/self/exe)");
    exe[n] = '\0';
    std::string command = std::string("'") + exe + "' --memory-child " + mode + " '" + path + "'";
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) throw std::runtime_error("cannot run " + command);
    MemoryFigures m;
    char key[32];
    long long value;
    while (std::fscanf(pipe, "%31s %lld", key, &value) == 2) {
        std::string k = key;
        if (k == "rss0")
            m.rss0 = value;
        else if (k == "hwm0")
            m.hwm0 = value;
        else if (k == "rss1")
            m.rss1 = value;
        else if (k == "hwm1")
            m.hwm1 = value;
        else if (k == "payload")
            m.payload = static_cast<std::size_t>(value);
        else if (k == "composed")
            m.composed = static_cast<std::size_t>(value);
    }
    int status = pclose(pipe);
    if (status != 0) throw std::runtime_error("memory measurement failed: " + command);
    return m;
}

struct Timing {
    double best = 0, median = 0;
};

template <class F>
Timing timeRuns(int runs, F&& run) {
    std::vector<double> times;
    for (int i = 0; i < runs; ++i) {
        auto start = Clock::now();
        run();
        times.push_back(seconds(Clock::now() - start));
    }
    std::sort(times.begin(), times.end());
    return {times.front(), times[times.size() / 2]};
}

std::string mb(double bytes) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.1f MB", bytes / 1e6);
    return buffer;
}

int usage() {
    std::cerr << "usage: usda_parse_bench [--meshes N] [--grid WxH] [--runs N] [--keep FILE]\n"
                 "       usda_parse_bench --file LAYER.usda [--runs N | --parse-once]\n";
    return 2;
}

}  // namespace

int main(int argc, char** argv) {
    Options o;
    try {
        for (int i = 1; i < argc; ++i) {
            std::string arg = argv[i];
            auto next = [&]() -> std::string {
                if (i + 1 >= argc) throw std::invalid_argument(arg + " needs a value");
                return argv[++i];
            };
            if (arg == "--memory-child" && i + 2 < argc) return memoryChild(argv[i + 1], argv[i + 2]);
            if (arg == "--meshes")
                o.meshes = std::stoi(next());
            else if (arg == "--grid") {
                std::string g = next();
                std::size_t x = g.find('x');
                if (x == std::string::npos) return usage();
                o.gridW = std::stoi(g.substr(0, x)), o.gridH = std::stoi(g.substr(x + 1));
            } else if (arg == "--runs")
                o.runs = std::max(1, std::stoi(next()));
            else if (arg == "--keep")
                o.keep = next();
            else if (arg == "--file")
                o.file = next();
            else if (arg == "--parse-once")
                o.parseOnce = true;
            else if (arg == "--help" || arg == "-h")
                return usage(), 0;
            else
                return usage();
        }
        if (o.meshes < 1 || o.gridW < 2 || o.gridH < 2) return usage();
        if (o.parseOnce) {
            if (o.file.empty()) return usage();
            std::string text = readFile(o.file);
            auto layer = parseUsdaString(text, o.file);
            std::printf("parsed %s: %zu root prims\n", o.file.c_str(), layer->rootPrims.size());
            return 0;
        }

        std::string path, text;
        bool temporary = false;
        double generateSeconds = 0;
        if (!o.file.empty()) {
            path = o.file;
            text = readFile(path);
        } else {
            auto start = Clock::now();
            text = generateLayer(o);
            generateSeconds = seconds(Clock::now() - start);
            if (!o.keep.empty()) {
                path = o.keep;
            } else {
                const char* tmp = std::getenv("TMPDIR");
                path =
                    std::string(tmp && *tmp ? tmp : "/tmp") + "/usda_parse_bench-" + std::to_string(getpid()) + ".usda";
                temporary = true;
            }
            std::ofstream out(path, std::ios::binary);
            out.write(text.data(), static_cast<std::streamsize>(text.size()));
            if (!out) throw std::runtime_error("cannot write " + path);
        }
        const double bytes = static_cast<double>(text.size());

        // A first parse (not timed) warms the allocator and the caches, and gives the counts.
        LayerStats stats;
        {
            auto layer = parseUsdaString(text, path);
            stats = statsOf(*layer);
        }
        Timing parse = timeRuns(o.runs, [&] { auto layer = parseUsdaString(text, path); });
        Timing open = timeRuns(o.runs, [&] { auto stage = Stage::open(path); });
        // The time to free a parsed layer, which a parse-and-drop loop would otherwise hide.
        Timing destroy;
        {
            std::vector<double> times;
            for (int i = 0; i < std::min(o.runs, 3); ++i) {
                auto layer = parseUsdaString(text, path);
                auto start = Clock::now();
                layer.reset();
                times.push_back(seconds(Clock::now() - start));
            }
            std::sort(times.begin(), times.end());
            destroy = {times.front(), times[times.size() / 2]};
        }
        std::string().swap(text);

        MemoryFigures openMemory = measureMemory("open", path);
        MemoryFigures parseMemory = measureMemory("parse", path);
        if (temporary) std::filesystem::remove(path);

        const double payload = static_cast<double>(stats.payloadBytes());
        const double openPeak = (openMemory.hwm1 - openMemory.rss0) * 1024.0;
        const double parsePeak = (parseMemory.hwm1 - parseMemory.rss0) * 1024.0;
        const double retained = (openMemory.rss1 - openMemory.rss0) * 1024.0;
        const double throughput = bytes / 1e6 / parse.best;

        std::printf("USDA parse benchmark (%s)\n\n", o.file.empty() ? "generated layer" : o.file.c_str());
        std::printf("layer\n");
        if (o.file.empty()) {
            std::printf(
                "  generated            %d meshes of %dx%d vertices, %d materials, %d instances"
                " (%.2f s to generate)\n",
                o.meshes, o.gridW, o.gridH, o.materials, o.meshes, generateSeconds);
            std::printf("  points               %ld\n", static_cast<long>(o.meshes) * o.gridW * o.gridH);
        }
        std::printf("  text                 %s (%.0f bytes)\n", mb(bytes).c_str(), bytes);
        std::printf("  prims / attributes   %zu / %zu (%zu relationships, %zu time samples)\n", stats.prims,
                    stats.attributes, stats.relationships, stats.timeSamples);
        std::printf("  values               %zu: %zu numbers, %zu strings (%zu chars)\n", stats.values, stats.numbers,
                    stats.strings, stats.stringBytes);
        std::printf("  value payload        %s (numbers x 8 B + string chars); doubles allocated %s\n\n",
                    mb(payload).c_str(), mb(stats.numberCapacity * 8.0).c_str());

        std::printf("%-34s %12s %12s %14s\n", "time (best / median of runs)", "best", "median", "throughput");
        std::printf("%-34s %10.3f s %10.3f s %9.1f MB/s\n", "parseUsdaString (text in memory)", parse.best,
                    parse.median, throughput);
        std::printf("%-34s %10.3f s %10.3f s %9.1f MB/s\n", "Stage::open (read, parse, compose)", open.best,
                    open.median, bytes / 1e6 / open.best);
        std::printf("%-34s %10.3f s %10.3f s\n\n", "freeing the parsed layer", destroy.best, destroy.median);

        std::printf("%-34s %12s %14s\n", "memory (fresh process, VmHWM)", "peak growth", "x payload");
        std::printf("%-34s %12s %13.2fx\n", "Stage::open peak", mb(openPeak).c_str(), openPeak / payload);
        std::printf("%-34s %12s %13.2fx\n", "parseUsdaString (text already read)", mb(parsePeak).c_str(),
                    parsePeak / payload);
        std::printf("%-34s %12s %13.2fx\n", "retained after Stage::open (VmRSS)", mb(retained).c_str(),
                    retained / payload);
        std::printf("%-34s %12s %13.2fx\n", "  composed layer's own values",
                    mb(static_cast<double>(openMemory.composed)).c_str(),
                    static_cast<double>(openMemory.composed) / payload);
        std::printf("\n");

        bool speedMet = throughput >= 150.0;
        bool memoryMet = openPeak < 3.0 * payload;
        std::printf("targets (issue)\n");
        std::printf("  parse >= 150 MB/s of USDA text          %7.1f MB/s   %s\n", throughput,
                    speedMet ? "MET" : "NOT MET");
        std::printf("  peak memory < 3x the values' payload    %7.2fx       %s\n", openPeak / payload,
                    memoryMet ? "MET" : "NOT MET");
        return 0;
    } catch (const std::exception& error) {
        std::cerr << "usda_parse_bench: " << error.what() << "\n";
        return 1;
    }
}
