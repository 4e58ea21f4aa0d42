// Cryptomatte encoding (output/cryptomatte.h): MurmurHash3_x86_32 against published test vectors,
// ids against the float values of Psyop's reference implementation, the float conversion's
// exponent rule, and the channels and metadata appendCryptomatte writes.
#include "output/cryptomatte.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <map>
#include <string>

namespace fluence::output {
namespace {

// The test vectors published with MurmurHash3 ports (SMHasher's verification values
// reproduced input by input).
TEST(Cryptomatte, MurmurHashMatchesPublishedVectors) {
    using namespace std::string_literals;
    struct Vector {
        std::string data;
        std::uint32_t seed, hash;
    };
    const Vector vectors[] = {
        {"", 0u, 0u},
        {"", 1u, 0x514E28B7u},
        {"", 0xffffffffu, 0x81F16F39u},
        {"\xff\xff\xff\xff"s, 0u, 0x76293B50u},
        {"\x21\x43\x65\x87"s, 0u, 0xF55B516Bu},
        {"\x21\x43\x65\x87"s, 0x5082EDEEu, 0x2362F9DEu},
        {"\x21\x43\x65"s, 0u, 0x7E4A8634u},
        {"\x21\x43"s, 0u, 0xA0F7B07Au},
        {"\x21"s, 0u, 0x72661CF4u},
        {"\0\0\0\0"s, 0u, 0x2362F9DEu},
        {"\0\0\0"s, 0u, 0x85F0B427u},
        {"\0\0"s, 0u, 0x30F4C306u},
        {"\0"s, 0u, 0x514E28B7u},
        {"Hello, world!", 0x9747b28cu, 0x24884CBAu},
        {"aaaa", 0x9747b28cu, 0x5A97808Au},
        {"aaa", 0x9747b28cu, 0x283E0130u},
        {"aa", 0x9747b28cu, 0x5D211726u},
        {"a", 0x9747b28cu, 0x7FA09EA6u},
        {"abcd", 0x9747b28cu, 0xF0478627u},
        {"abc", 0x9747b28cu, 0xC84A62DDu},
        {"ab", 0x9747b28cu, 0x74875592u},
        {"The quick brown fox jumps over the lazy dog", 0x9747b28cu, 0x2FA826CDu},
    };
    for (const Vector& v : vectors)
        EXPECT_EQ(murmurHash3_x86_32(v.data, v.seed), v.hash)
            << "'" << v.data << "' (" << v.data.size() << " bytes), seed " << v.seed;
}

// The ids of Psyop's own tests (nuke/cryptomatte_utilities_tests.py, mm3hash_float), UTF-8 names
// included: the float each name is stored as.
TEST(Cryptomatte, IdsMatchTheReferenceImplementation) {
    const std::map<std::string, double> expected{
        {"hello", 6.0705627102400005616e-17},
        {"cube", -4.08461912519e+15},
        {"sphere", 2.79018604383e+15},
        {"plane", 3.66557617593e-11},
        {"\xd1\x80\xd0\xb0\xd0\xb2\xd0\xbd\xd0\xb8\xd0\xbd\xd0\xb0", -1.3192631212399999468e-25},
        {"m\xc3\xa4"
         "dchen",
         6.2361298211599995797e+25},
    };
    for (const auto& [name, value] : expected)
        EXPECT_EQ(cryptomatteIdFloat(cryptomatteId(name)), static_cast<float>(value)) << name;
}

// Every id is a normal float (never zero, denormal, infinite or NaN), and only hashes whose exponent
// is all zeros or all ones are changed, by their lowest exponent bit. Among 2^18 names, about 2/256 of
// them need the fix: the rule is exercised, not only the common case.
TEST(Cryptomatte, IdsAreAlwaysNormalFloats) {
    int fixed = 0;
    for (int i = 0; i < (1 << 18); ++i) {
        const std::string name = "/World/prim_" + std::to_string(i);
        const std::uint32_t hash = murmurHash3_x86_32(name), id = cryptomatteId(name);
        const std::uint32_t exponent = (hash >> 23) & 0xffu;
        if (exponent == 0 || exponent == 0xffu) {
            ++fixed;
            EXPECT_EQ(id, hash ^ (1u << 23)) << name;
        } else {
            EXPECT_EQ(id, hash) << name;
        }
        ASSERT_TRUE(std::isnormal(cryptomatteIdFloat(id))) << name << " -> " << cryptomatteHex(id);
    }
    EXPECT_GT(fixed, 1000);  // expected 2^18 * 2 / 256 = 2048
}

TEST(Cryptomatte, KeyAndHexFollowTheSpecification) {
    EXPECT_EQ(cryptomatteHex(0x0000abcdu), "0000abcd");
    EXPECT_EQ(cryptomatteKey("CryptoObject"), cryptomatteHex(cryptomatteId("CryptoObject")).substr(0, 7));
    EXPECT_EQ(cryptomatteKey("CryptoObject").size(), 7u);
}

// A 2x1 film: pixel 0 seen by names 1 (3 samples), 0 (1 sample); pixel 1 by nothing. Depth 3: two
// RGBA layers, ranks 0 and 1 in the first, rank 2 (empty) in the second.
TEST(Cryptomatte, AppendWritesRankedChannelsAndMetadata) {
    NameTable names;
    names.add("/World/a\"quoted\"");
    names.add("/World/b");
    CryptomatteFilm film(2, 1, {CryptomatteSource::Object});
    FilmSample sample;
    for (std::uint32_t name : {1u, 0u, 1u, 1u}) {
        sample.objectName = name;
        film.add(0, 0, sample);
    }
    film.add(1, 0, FilmSample{});
    Image image(2, 1, {"R", "G", "B"});
    image.pixel(0, 0)[1] = 0.5f;
    ExrHeader header;
    appendCryptomatte(image, header, film, {{"CryptoObject", &names}}, 3);

    ASSERT_EQ(image.channels.size(), 3u + 8u);
    EXPECT_EQ(image.pixel(0, 0)[1], 0.5f);  // the image's own channels are kept
    const auto at = [&](int x, const std::string& channel) { return image.pixel(x, 0)[image.channelIndex(channel)]; };
    EXPECT_EQ(std::bit_cast<std::uint32_t>(at(0, "CryptoObject00.R")), cryptomatteId("/World/b"));
    EXPECT_EQ(at(0, "CryptoObject00.G"), 0.75f);
    EXPECT_EQ(std::bit_cast<std::uint32_t>(at(0, "CryptoObject00.B")), cryptomatteId("/World/a\"quoted\""));
    EXPECT_EQ(at(0, "CryptoObject00.A"), 0.25f);
    for (const char* c :
         {"CryptoObject01.R", "CryptoObject01.G", "CryptoObject01.B", "CryptoObject01.A", "CryptoObject00.R"})
        EXPECT_EQ(at(1, c), 0.0f) << c;

    const std::string prefix = "cryptomatte/" + cryptomatteKey("CryptoObject") + "/";
    std::map<std::string, std::string> strings(header.strings.begin(), header.strings.end());
    EXPECT_EQ(strings[prefix + "name"], "CryptoObject");
    EXPECT_EQ(strings[prefix + "hash"], "MurmurHash3_32");
    EXPECT_EQ(strings[prefix + "conversion"], "uint32_to_float32");
    EXPECT_EQ(strings[prefix + "manifest"],
              "{\"/World/a\\\"quoted\\\"\":\"" + cryptomatteHex(cryptomatteId("/World/a\"quoted\"")) +
                  "\",\"/World/b\":\"" + cryptomatteHex(cryptomatteId("/World/b")) + "\"}");
    EXPECT_EQ(header.dataChannels.size(), 8u);
}

TEST(Cryptomatte, AppendRejectsMismatchedDescriptions) {
    NameTable names;
    CryptomatteFilm film(1, 1, {CryptomatteSource::Object, CryptomatteSource::Material});
    Image image(1, 1, {"R"});
    ExrHeader header;
    EXPECT_THROW(appendCryptomatte(image, header, film, {{"CryptoObject", &names}}, 6), std::invalid_argument);
    EXPECT_THROW(appendCryptomatte(image, header, film, {{"CryptoObject", &names}, {"CryptoMaterial", &names}}, 0),
                 std::invalid_argument);
}

// Tiles of one image each list the names they saw; assembled, the manifest holds them all, once.
TEST(Cryptomatte, ManifestsMergeWithoutRepeats) {
    EXPECT_EQ(mergeCryptomatteManifests(R"({"/a":"00000001","/q\"x":"00000002"})",
                                        R"({ "/b" : "00000003", "/a":"00000001" })"),
              R"({"/a":"00000001","/q\"x":"00000002","/b":"00000003"})");
    EXPECT_EQ(mergeCryptomatteManifests("{}", R"({"/b":"00000003"})"), R"({"/b":"00000003"})");
    EXPECT_THROW(mergeCryptomatteManifests("{}", R"({"/b":3})"), std::invalid_argument);
    EXPECT_THROW(mergeCryptomatteManifests(R"({"/b":"3")", "{}"), std::invalid_argument);
}

}  // namespace
}  // namespace fluence::output
