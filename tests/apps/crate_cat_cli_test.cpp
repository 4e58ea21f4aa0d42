// `fluence cat` of crate layers (issue #11): a path expression written back as a USDA
// `pathExpression` value, a large array decoded when first read (as the text is written), and a
// damaged compressed array found then: exit code 4 and an error naming the file, not a crash or
// an internal error; a crate 0.0.1 layer written as its text twin is.
#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include "tests/support/cli.h"
#include "tests/support/crate_writer.h"
#include "tests/support/temp_dir.h"

namespace fluence {
namespace {

using test::CrateWriter;
namespace T = usd::detail::crate_type;
using ST = usd::detail::CrateSpecType;

class CrateCatCli : public ::testing::Test {
protected:
    test::TempDir tmp_{"fluence_crate_cat"};

    // A layer /World with a path-expression attribute and a compressed int[] of 1000 indices;
    // `damage` overwrites the LZ4 framing byte of the indices.
    std::string writeCrate(bool damage) {
        CrateWriter w;
        std::vector<std::int32_t> indices;
        for (int i = 0; i < 1000; ++i) indices.push_back(i % 97);
        w.spec("/", ST::PseudoRoot, {{"primChildren", w.tokenVector({"World"})}});
        w.spec("/World", ST::Prim,
               {{"specifier", CrateWriter::inlined(T::Specifier, 0)},
                {"properties", w.tokenVector({"collection:membershipExpression", "indices"})}});
        w.spec("/World.collection:membershipExpression", ST::Attribute,
               {{"typeName", w.tokenValue("pathExpression")}, {"default", w.pathExpression("/World/**")}});
        CrateWriter::Rep indicesRep = w.compressedInts(T::Int, indices);
        w.spec("/World.indices", ST::Attribute, {{"typeName", w.tokenValue("int[]")}, {"default", indicesRep}});
        std::vector<char> bytes = w.finish();
        // Past the count and the compressed size: the chunk count, 7 chunks whose sizes are not there.
        if (damage) bytes[(indicesRep & ((1ull << 48) - 1)) + 16] = 7;
        const std::string path = tmp_.file(damage ? "damaged.usdc" : "world.usdc");
        std::ofstream(path, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        return path;
    }
};

TEST_F(CrateCatCli, WritesPathExpressionsAndDecodedArrays) {
    test::RunResult cat = test::runFluence("cat " + writeCrate(false), tmp_.path());
    ASSERT_EQ(cat.exitCode, 0) << cat.err;
    EXPECT_NE(cat.out.find("pathExpression collection:membershipExpression = \"/World/**\"\n"), std::string::npos)
        << cat.out;
    EXPECT_NE(cat.out.find("int[] indices = [0, 1, 2, 3, "), std::string::npos) << cat.out;
}

TEST_F(CrateCatCli, ADamagedArrayFoundWhenReadExits4NamingTheFile) {
    const std::string path = writeCrate(true);
    test::RunResult cat = test::runFluence("cat " + path, tmp_.path());
    EXPECT_EQ(cat.exitCode, 4) << cat.err;
    EXPECT_NE(cat.err.find("fluence: error: '" + path + "': damaged or unsupported USD crate file"), std::string::npos)
        << cat.err;
}

// Crate 0.0.1 (OpenUSD's own test layer, tests/scene/data/crate/v0.0.1) cats as its text twin.
TEST_F(CrateCatCli, Version001LayerCatsAsItsTextTwin) {
    const std::string data = FLUENCE_SOURCE_DIR "/tests/scene/data/crate/v0.0.1/";
    test::RunResult crate = test::runFluence("cat " + data + "testHasDefiningSpecifier.usdc", tmp_.path());
    test::RunResult text = test::runFluence("cat " + data + "testHasDefiningSpecifier.usda", tmp_.path());
    ASSERT_EQ(crate.exitCode, 0) << crate.err;
    ASSERT_EQ(text.exitCode, 0) << text.err;
    EXPECT_EQ(crate.out, text.out);
    EXPECT_NE(crate.out.find("def \"b6\""), std::string::npos) << crate.out;
}

}  // namespace
}  // namespace fluence
