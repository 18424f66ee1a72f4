#include "graph/io/AtomicFile.hpp"
#include "graph/io/BinaryReader.hpp"
#include "graph/io/BinaryWriter.hpp"

#include "../support/TempDir.hpp"

#include <gtest/gtest.h>

#include <sys/resource.h>

#include <algorithm>
#include <bit>
#include <csignal>
#include <fstream>
#include <iterator>
#include <limits>

using namespace arcomp;
using arcomp::test::TempDir;
namespace fs = std::filesystem;

namespace {

std::string contentOf(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

std::vector<std::byte> bytesOf(const std::string& text) {
    const auto b = std::as_bytes(std::span(text));
    return {b.begin(), b.end()};
}

std::vector<std::string> namesIn(const fs::path& folder) {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(folder)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

// What a full disk does to a write, for this process only: writes past
// `bytes` into any file fail with EFBIG (SIGXFSZ ignored so that they
// return instead of killing the process). Undone when it goes out of scope.
class FileSizeLimit {
public:
    explicit FileSizeLimit(rlim_t bytes) {
        getrlimit(RLIMIT_FSIZE, &old_);
        oldHandler_ = std::signal(SIGXFSZ, SIG_IGN);
        rlimit limit = old_;
        limit.rlim_cur = bytes;
        setrlimit(RLIMIT_FSIZE, &limit);
    }
    ~FileSizeLimit() {
        setrlimit(RLIMIT_FSIZE, &old_);
        std::signal(SIGXFSZ, oldHandler_);
    }

private:
    rlimit old_{};
    void (*oldHandler_)(int) = nullptr;
};

}  // namespace

TEST(BinaryWriter, writesLittleEndianThatTheReaderReadsBack) {
    const char magic[4] = {'A', '\0', 'B', 'C'};
    BinaryWriter w;
    w.raw(magic);
    w.u8(0xab);
    w.u16(0x1234);
    w.u32(0x12345678u);
    w.u64(0x0102030405060708ull);
    w.f32(-1.5f);
    const std::vector<std::uint32_t> indices = {0, 7, 0xffffffffu};
    w.u32s(indices);
    w.vec3s(std::vector<glm::vec3>{{1, 2, 3}, {-4, 5.5f, 6}});
    w.vec2s(std::vector<glm::vec2>{{0.25f, 0.75f}});
    ASSERT_EQ(w.bytes().size(), 4u + 1 + 2 + 4 + 8 + 4 + 12 + 24 + 8);
    EXPECT_EQ(w.bytes()[5], std::byte{0x34});  // the u16's low byte first
    EXPECT_EQ(w.bytes()[6], std::byte{0x12});

    BinaryReader r(w.bytes(), "x.bin");
    r.magic(magic, "the magic", "bad magic");
    EXPECT_EQ(r.u8("u8"), 0xab);
    EXPECT_EQ(r.u16("u16"), 0x1234);
    EXPECT_EQ(r.u32("u32"), 0x12345678u);
    EXPECT_EQ(r.u64("u64"), 0x0102030405060708ull);
    EXPECT_EQ(r.finite("f32"), -1.5f);
    for (std::uint32_t i : indices) EXPECT_EQ(r.u32("index"), i);
    EXPECT_EQ(r.vec3s(2, "positions"), (std::vector<glm::vec3>{{1, 2, 3}, {-4, 5.5f, 6}}));
    EXPECT_EQ(r.vec2s(1, "texcoords"), (std::vector<glm::vec2>{{0.25f, 0.75f}}));
    EXPECT_EQ(r.remaining(), 0u);
}

TEST(BinaryWriter, keepsTheBitsOfANaN) {
    const float nan = std::bit_cast<float>(0x7fc01234u);
    BinaryWriter w;
    w.f32(nan);
    BinaryReader r(w.bytes(), "x.bin");
    EXPECT_EQ(std::bit_cast<std::uint32_t>(r.f32("nan")), 0x7fc01234u);
}

TEST(AtomicFile, replacesTheFileAndLeavesNoTemporary) {
    const TempDir dir;
    const fs::path file = dir.path() / "model.lod";
    writeFileAtomically(file, bytesOf("first version"));
    EXPECT_EQ(contentOf(file), "first version");
    writeFileAtomically(file, bytesOf("second"));
    EXPECT_EQ(contentOf(file), "second");
    writeFileAtomically(file, {});
    EXPECT_EQ(contentOf(file), "");
    EXPECT_EQ(namesIn(dir.path()), std::vector<std::string>{"model.lod"});
}

TEST(AtomicFile, aFolderThatDoesNotExistIsAnErrorNamingTheFile) {
    const TempDir dir;
    const fs::path file = dir.path() / "missing" / "model.lod";
    try {
        writeFileAtomically(file, bytesOf("content"));
        ADD_FAILURE() << "wrote into a missing folder";
    } catch (const std::runtime_error& e) {
        const std::string what = e.what();
        EXPECT_EQ(what.find(file.string() + ": cannot create model.lod.tmp-"), 0u) << what;
        EXPECT_NE(what.find("No such file or directory"), std::string::npos) << what;
    }
    EXPECT_TRUE(namesIn(dir.path()).empty());
}

TEST(AtomicFile, aWriteThatFailsHalfwayLeavesTheOldFileAndNoTemporary) {
    const TempDir dir;
    const fs::path file = dir.path() / "model.sil";
    writeFileAtomically(file, bytesOf("the good old file"));
    const std::vector<std::byte> large(64 * 1024, std::byte{0x5a});
    std::string error;
    {
        const FileSizeLimit diskFullAfter(4096);
        try {
            writeFileAtomically(file, large);
        } catch (const std::runtime_error& e) {
            error = e.what();
        }
    }
    EXPECT_EQ(error.find(file.string() + ": cannot write model.sil.tmp-"), 0u) << error;
    EXPECT_EQ(contentOf(file), "the good old file");
    EXPECT_EQ(namesIn(dir.path()), std::vector<std::string>{"model.sil"});
}

TEST(AtomicFile, aRenameThatFailsLeavesNoTemporary) {
    const TempDir dir;
    const fs::path file = dir.path() / "model.arvox";
    fs::create_directories(file / "occupied");  // a folder with something in it cannot be renamed over
    try {
        writeFileAtomically(file, bytesOf("content"));
        ADD_FAILURE() << "renamed over a folder";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(": cannot rename model.arvox.tmp-"), std::string::npos) << e.what();
    }
    EXPECT_TRUE(fs::is_directory(file / "occupied"));
    EXPECT_EQ(namesIn(dir.path()), std::vector<std::string>{"model.arvox"});
}
