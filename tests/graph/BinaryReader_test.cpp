#include "graph/io/BinaryReader.hpp"
#include "graph/io/BinaryWriter.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>

using namespace arcomp;

namespace {

std::vector<unsigned char> bytes(std::initializer_list<int> values) {
    std::vector<unsigned char> out;
    for (int v : values) out.push_back(static_cast<unsigned char>(v));
    return out;
}

// The ModelError `read` throws; fails the test when it throws nothing.
ModelError errorOf(const std::function<void()>& read) {
    try {
        read();
    } catch (const ModelError& e) {
        return e;
    }
    ADD_FAILURE() << "no ModelError";
    return ModelError("", "", "");
}

constexpr char kTestMagic[4] = {'T', 'E', '\0', 'S'};

}  // namespace

TEST(BinaryReader, readsLittleEndianValuesAndKeepsItsPlace) {
    const auto b = bytes({0x11, 0x34, 0x12, 0x78, 0x56, 0x34, 0x12, 1, 0, 0, 0, 0, 0, 0, 0x80, 0, 0, 0x80, 0x3f});
    BinaryReader r(b, "x.bin");
    EXPECT_EQ(r.u8("a"), 0x11);
    EXPECT_EQ(r.u16("b"), 0x1234);
    EXPECT_EQ(r.u32("c"), 0x12345678u);
    EXPECT_EQ(r.position(), 7u);
    EXPECT_EQ(r.u64("d"), 0x8000000000000001ull);
    EXPECT_EQ(r.remaining(), 4u);
    EXPECT_EQ(r.finite("e"), 1.0f);
    EXPECT_EQ(r.remaining(), 0u);
    EXPECT_EQ(r.position(), b.size());
}

TEST(BinaryReader, magicMustMatchEveryByteIncludingZeros) {
    const auto good = bytes({'T', 'E', 0, 'S', 7});
    BinaryReader r(good, "x.bin");
    r.magic(kTestMagic, "the header", "wrong magic");
    EXPECT_EQ(r.position(), 4u);

    const auto wrong = bytes({'T', 'E', 'S', 'T', 7});
    const ModelError e = errorOf([&] { BinaryReader(wrong, "x.bin").magic(kTestMagic, "the header", "wrong magic"); });
    EXPECT_EQ(std::string(e.what()), "x.bin: byte 0: wrong magic");

    const auto shortFile = bytes({'T', 'E'});
    const ModelError s =
        errorOf([&] { BinaryReader(shortFile, "x.bin").magic(kTestMagic, "the header", "wrong magic"); });
    EXPECT_EQ(std::string(s.what()), "x.bin: byte 0: file ends inside the header");
}

TEST(BinaryReader, readingPastTheEndNamesWhatAndWhereAndMovesNothing) {
    const auto b = bytes({1, 2, 3, 4, 5, 6, 7});
    BinaryReader r(b, "x.bin");
    r.u32("the count");
    const ModelError e = errorOf([&] { r.u32("the flags"); });
    EXPECT_EQ(e.file, "x.bin");
    EXPECT_EQ(e.where, "byte 4");
    EXPECT_EQ(e.reason, "file ends inside the flags");
    EXPECT_EQ(r.position(), 4u);
    EXPECT_EQ(r.u16("two of the three bytes left"), 0x0605);
    EXPECT_EQ(errorOf([&] { r.u64("a size"); }).reason, "file ends inside a size");
    EXPECT_EQ(errorOf([&] { BinaryReader(std::span<const unsigned char>(), "e.bin").u8("anything"); }).where, "byte 0");
}

TEST(BinaryReader, nonFiniteFloatsAreRefusedAtTheirFirstByte) {
    BinaryWriter w;
    w.f32(2.0f);
    w.f32(std::numeric_limits<float>::quiet_NaN());
    w.f32(-std::numeric_limits<float>::infinity());
    const std::vector<std::byte> b = w.take();

    BinaryReader r(b, "x.bin");
    EXPECT_EQ(r.finite("scale"), 2.0f);
    const ModelError nan = errorOf([&] { r.finite("scale"); });
    EXPECT_EQ(nan.where, "byte 4");
    EXPECT_EQ(nan.reason, "scale is not a finite number");

    BinaryReader raw(b, "x.bin");
    raw.f32("scale");
    EXPECT_TRUE(std::isnan(raw.f32("scale")));  // f32 passes any bit pattern on
    EXPECT_EQ(errorOf([&] { raw.finite("offset"); }).where, "byte 8");

    // Inside an array too: the second vector's y.
    BinaryWriter v;
    v.vec2s(std::vector<glm::vec2>{{1, 2}, {3, std::numeric_limits<float>::infinity()}});
    const std::vector<std::byte> vb = v.take();
    const ModelError inArray = errorOf([&] { BinaryReader(vb, "x.bin").vec2s(2, "texcoords"); });
    EXPECT_EQ(inArray.where, "byte 12");
    EXPECT_EQ(inArray.reason, "texcoords is not a finite number");
}

TEST(BinaryReader, aCountBeyondTheBytesLeftIsRefusedBeforeAllocating) {
    // A u32 count of 0xFFFFFFFF vec3s (48 GiB) followed by one vec3.
    BinaryWriter w;
    w.u32(0xFFFFFFFFu);
    w.vec3s(std::vector<glm::vec3>{{1, 2, 3}});
    const std::vector<std::byte> b = w.take();
    BinaryReader r(b, "bomb.bin");
    const std::uint32_t count = r.u32("the vertex count");
    const ModelError e = errorOf([&] { r.vec3s(count, "positions"); });
    EXPECT_EQ(e.where, "byte 4");
    EXPECT_EQ(e.reason, "file ends inside positions: 4294967295 items of 12 bytes, 12 bytes left");
    EXPECT_EQ(r.position(), 4u);  // nothing consumed, so nothing was read into a vector
    EXPECT_EQ(r.vec3s(1, "positions"), (std::vector<glm::vec3>{{1, 2, 3}}));
}

TEST(BinaryReader, aCountWhoseByteSizeWrapsAroundIsRefusedToo) {
    // 2^62 vec3s are 3 * 2^64 bytes: a multiplied check would see 0 bytes
    // needed, pass, and reserve 2^62 vectors.
    const std::vector<unsigned char> b(24);
    BinaryReader r(b, "wrap.bin");
    EXPECT_EQ(errorOf([&] { r.vec3s(std::uint64_t{1} << 62, "positions"); }).where, "byte 0");
    EXPECT_EQ(errorOf([&] { r.vec2s(std::uint64_t{1} << 61, "texcoords"); }).where, "byte 0");
    EXPECT_EQ(errorOf([&] { r.needItems(std::uint64_t{1} << 62, 4, "indices"); }).where, "byte 0");
    EXPECT_EQ(r.vec3s(2, "positions").size(), 2u);  // exactly the bytes there: accepted
}

TEST(BinaryReader, failAtNamesAnEarlierByte) {
    const auto b = bytes({9, 0, 0, 0});
    BinaryReader r(b, "x.bin");
    const std::uint32_t index = r.u32("an index");
    const ModelError e = errorOf([&] { r.failAt(r.position() - 4, "index " + std::to_string(index) + " too big"); });
    EXPECT_EQ(std::string(e.what()), "x.bin: byte 0: index 9 too big");
    EXPECT_EQ(errorOf([&] { r.fail("bytes after the end"); }).where, "byte 4");
}
