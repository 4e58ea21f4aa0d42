// Issue #11: the crate reader's deferred arrays. Large numeric arrays are decoded on first use
// (scene/number_array.h, scene/crate_values.h): not before, once whichever threads ask, with the
// numbers eager decoding gives; the memory-mapped file stays readable while an array still needs
// it; and damaged or truncated files fail with FileError naming the file, at load or, for a
// damaged compressed array, when its numbers are first read.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "scene/crate_reader.h"
#include "scene/layer_file.h"
#include "scene/stage.h"
#include "scene/usda_parser.h"
#include "tests/support/crate_writer.h"
#include "tests/support/temp_dir.h"

namespace fluence::usd {
namespace {

using test::CrateWriter;
namespace T = detail::crate_type;
using ST = detail::CrateSpecType;

// ---- NumberArray::deferred ------------------------------------------------------------------------

TEST(DeferredNumberArray, DecodesOnceOnFirstUseWhicheverThreadsAsk) {
    std::atomic<int> decodes = 0;
    NumberArray array = NumberArray::deferred(1000, [&decodes] {
        ++decodes;
        std::vector<double> numbers(1000);
        for (std::size_t i = 0; i < numbers.size(); ++i) numbers[i] = static_cast<double>(i) * 0.5;
        return numbers;
    });
    const NumberArray copy = array;  // copies share the one decoding
    EXPECT_EQ(array.size(), 1000u);
    EXPECT_FALSE(array.empty());
    EXPECT_FALSE(copy.isDecoded());
    EXPECT_EQ(decodes, 0);

    std::vector<std::thread> threads;
    std::vector<const double*> seen(8);
    for (std::size_t t = 0; t < seen.size(); ++t)
        threads.emplace_back([&, t] { seen[t] = (t % 2 ? array : copy).data(); });
    for (std::thread& thread : threads) thread.join();
    EXPECT_EQ(decodes, 1);
    for (const double* data : seen) EXPECT_EQ(data, seen.front());
    EXPECT_TRUE(array.isDecoded());
    EXPECT_TRUE(copy.isDecoded());
    EXPECT_EQ(copy[999], 499.5);
}

TEST(DeferredNumberArray, AFailedDecodingThrowsAgainOnTheNextAccess) {
    int attempts = 0;
    NumberArray array = NumberArray::deferred(3, [&attempts]() -> std::vector<double> {
        ++attempts;
        throw FileError("damaged");
    });
    EXPECT_THROW(array.vector(), FileError);
    EXPECT_THROW(array[0], FileError);
    EXPECT_EQ(attempts, 2);
    EXPECT_FALSE(array.isDecoded());
    EXPECT_EQ(array.size(), 3u);
}

TEST(DeferredNumberArray, ADecoderReturningTheWrongCountIsAnError) {
    NumberArray array = NumberArray::deferred(3, [] { return std::vector<double>{1, 2}; });
    EXPECT_THROW(array.vector(), std::logic_error);
}

// ---- crate arrays ----------------------------------------------------------------------------------

// A mesh-like prim whose large arrays are deferred (points float3[], faceVertexIndices as a
// compressed int[], widths double[], a half[] primvar) beside a small float3[] decoded at once.
struct MeshFile {
    std::vector<float> points;
    std::vector<std::int32_t> indices;
    std::vector<double> widths;
    std::vector<std::uint16_t> halves;
    std::vector<char> bytes;
    std::size_t indicesOffset = 0;  // where the compressed indices' count is

    MeshFile() {
        for (int i = 0; i < 300 * 3; ++i) points.push_back(static_cast<float>(i) * 0.25f - 7.0f);
        for (int i = 0; i < 1200; ++i) indices.push_back((i * 7919) % 300);
        for (int i = 0; i < 300; ++i) widths.push_back(1.0 / (i + 1));
        for (int i = 0; i < 300; ++i) halves.push_back(static_cast<std::uint16_t>(0x3C00 + i));  // 1 + i/1024
        CrateWriter w;
        std::vector<std::string> properties;
        auto attribute = [&](const std::string& name, const std::string& type, CrateWriter::Rep value) {
            properties.push_back(name);
            w.spec("/Mesh." + name, ST::Attribute, {{"typeName", w.tokenValue(type)}, {"default", value}});
        };
        attribute("points", "point3f[]", w.array(T::Vec3f, points, 300));
        CrateWriter::Rep indicesRep = w.compressedInts(T::Int, indices);
        indicesOffset = static_cast<std::size_t>(indicesRep & ((1ull << 48) - 1));
        attribute("faceVertexIndices", "int[]", indicesRep);
        attribute("widths", "double[]", w.array(T::Double, widths, 300));
        attribute("primvars:h", "half[]", w.array(T::Half, halves, 300));
        attribute("extent", "float3[]", w.array<float>(T::Vec3f, {-1, -1, -1, 1, 1, 1}, 2));
        w.spec("/", ST::PseudoRoot, {{"primChildren", w.tokenVector({"Mesh"})}});
        w.spec("/Mesh", ST::Prim,
               {{"specifier", CrateWriter::inlined(T::Specifier, 0)},
                {"typeName", w.tokenValue("Mesh")},
                {"properties", w.tokenVector(properties)}});
        bytes = w.finish();
    }

    void write(const std::string& path, std::size_t size) const {
        std::ofstream file(path, std::ios::binary | std::ios::trunc);
        file.write(bytes.data(), static_cast<std::streamsize>(size));
    }
};

const Value& defaultOf(const Layer& layer, const std::string& name) {
    const PrimSpec* mesh = layer.primAtPath("/Mesh");
    if (!mesh || !mesh->attribute(name)) throw std::runtime_error("no /Mesh." + name);
    return mesh->attribute(name)->defaultValue;
}

TEST(CrateDeferredArrays, LargeArraysAreDecodedOnFirstUseWithTheNumbersEagerDecodingGives) {
    const MeshFile file;
    test::TempDir dir;
    const std::string path = dir.file("mesh.usdc");
    file.write(path, file.bytes.size());
    std::unique_ptr<Layer> layer = readLayerFile(path);

    const Value& points = defaultOf(*layer, "points");
    const Value& indices = defaultOf(*layer, "faceVertexIndices");
    const Value& widths = defaultOf(*layer, "widths");
    const Value& halves = defaultOf(*layer, "primvars:h");
    for (const Value* value : {&points, &indices, &widths, &halves}) EXPECT_FALSE(value->numbers.isDecoded());
    EXPECT_TRUE(defaultOf(*layer, "extent").numbers.isDecoded());  // 6 numbers: decoded at once
    // The sizes are known without decoding.
    EXPECT_EQ(points.size(), 300u);
    EXPECT_EQ(points.components, 3);
    EXPECT_EQ(points.typeName, "point3f[]");
    EXPECT_EQ(indices.size(), 1200u);
    EXPECT_FALSE(points.numbers.isDecoded());

    std::vector<double> expectedPoints(file.points.begin(), file.points.end());
    std::vector<double> expectedIndices(file.indices.begin(), file.indices.end());
    std::vector<double> expectedHalves;
    for (int i = 0; i < 300; ++i) expectedHalves.push_back(1.0 + i / 1024.0);
    EXPECT_EQ(points.numbers.vector(), expectedPoints);
    EXPECT_TRUE(points.numbers.isDecoded());
    EXPECT_FALSE(indices.numbers.isDecoded());  // each array on its own
    EXPECT_EQ(indices.numbers.vector(), expectedIndices);
    EXPECT_EQ(widths.numbers.vector(), file.widths);
    EXPECT_EQ(halves.numbers.vector(), expectedHalves);

    // The same bytes read from memory (no mapping) give the same values.
    std::unique_ptr<Layer> fromMemory = readCrateBytes(file.bytes, "mesh.usdc");
    for (const char* name : {"points", "faceVertexIndices", "widths", "primvars:h", "extent"})
        EXPECT_EQ(defaultOf(*fromMemory, name).numbers, defaultOf(*layer, name).numbers) << name;
}

TEST(CrateDeferredArrays, ComposedCopiesShareOneDecodingAcrossThreads) {
    const MeshFile file;
    auto stage = std::make_unique<Stage>(readCrateBytes(file.bytes, "mesh.usdc"));
    const PrimSpec* mesh = stage->prim("/Mesh");
    ASSERT_NE(mesh, nullptr);
    const AttributeSpec* points = mesh->attribute("points");
    ASSERT_NE(points, nullptr);
    EXPECT_FALSE(points->defaultValue.numbers.isDecoded());
    std::vector<std::thread> threads;
    std::vector<std::vector<double>> seen(4);
    for (std::size_t t = 0; t < seen.size(); ++t)
        threads.emplace_back([&, t] { seen[t] = Stage::resolve(*points, kDefaultTime)->numbers.vector(); });
    for (std::thread& thread : threads) thread.join();
    for (const auto& numbers : seen) EXPECT_EQ(numbers, std::vector<double>(file.points.begin(), file.points.end()));
    EXPECT_TRUE(points->defaultValue.numbers.isDecoded());
}

TEST(CrateDeferredArrays, TheMappedFileOutlivesItsDirectoryEntry) {
    const MeshFile file;
    test::TempDir dir;
    const std::string path = dir.file("mesh.usdc");
    file.write(path, file.bytes.size());
    std::unique_ptr<Layer> layer = readCrateFile(path);
    std::filesystem::remove(path);  // as an editor saving by rename-over leaves the old file
    EXPECT_EQ(defaultOf(*layer, "widths").numbers.vector(), file.widths);
}

TEST(CrateDeferredArrays, ADamagedCompressedArrayFailsNamingTheFileWhenRead) {
    MeshFile file;
    // Past the count (8 bytes) and the compressed size (8 bytes): the LZ4 framing of the codes.
    file.bytes[file.indicesOffset + 16] = 7;  // 7 chunks, whose sizes are not there
    std::unique_ptr<Layer> layer = readCrateBytes(file.bytes, "damaged-mesh.usdc");
    const Value& indices = defaultOf(*layer, "faceVertexIndices");
    EXPECT_EQ(indices.size(), 1200u);
    for (int attempt = 0; attempt < 2; ++attempt) {
        try {
            indices.numbers.vector();
            ADD_FAILURE() << "the damaged array decoded";
        } catch (const FileError& error) {
            EXPECT_NE(std::string(error.what()).find("'damaged-mesh.usdc': damaged or unsupported USD crate file"),
                      std::string::npos)
                << error.what();
        }
    }
    EXPECT_EQ(defaultOf(*layer, "widths").numbers.vector(), file.widths);  // the others still read
}

// Every length of a file cut short (as when it is still being written), read from disk through
// the mapping and every number then read: a FileError naming the file or a layer whose values
// read, never a crash or another exception.
TEST(CrateDeferredArrays, TruncatedFilesOnDiskFailCleanly) {
    const MeshFile file;
    test::TempDir dir;
    const std::string path = dir.file("partial.usdc");
    int failed = 0;
    for (std::size_t size = 0; size <= file.bytes.size(); size += size < 200 ? 1 : 37) {
        SCOPED_TRACE(size);
        file.write(path, size);
        try {
            std::unique_ptr<Layer> layer = readLayerFile(path);
            for (const char* name : {"points", "faceVertexIndices", "widths", "primvars:h", "extent"})
                EXPECT_EQ(defaultOf(*layer, name).numbers.size(), defaultOf(*layer, name).numbers.vector().size());
        } catch (const FileError& error) {
            EXPECT_NE(std::string(error.what()).find(path), std::string::npos) << error.what();
            ++failed;
        } catch (const ParseError&) {
            ++failed;  // under 8 bytes there is no crate header: the file is read as (bad) text
        }
    }
    EXPECT_GT(failed, 0);
    file.write(path, file.bytes.size());
    EXPECT_NO_THROW(readLayerFile(path));
}

}  // namespace
}  // namespace fluence::usd
