#include "video/pixels/VideoError.hpp"
#include "video/sources/FileSource.hpp"

#include "tests/support/OpencvVideos.hpp"
#include "tests/support/TempDir.hpp"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>

#include <filesystem>
#include <fstream>

using namespace arcomp;
namespace fs = std::filesystem;

namespace {

#define REQUIRE_OPENCV_DOC()                                                                                           \
    if (!fs::exists(test::kVtest)) GTEST_SKIP() << test::kVtest << " absent (Debian opencv-doc)"

fs::path truncatedCopy(const fs::path& folder, std::uintmax_t bytes) {
    const fs::path out = folder / ("vtest-" + std::to_string(bytes) + ".avi");
    std::ifstream in(test::kVtest, std::ios::binary);
    std::string buf(bytes, '\0');
    in.read(buf.data(), static_cast<std::streamsize>(bytes));
    std::ofstream(out, std::ios::binary).write(buf.data(), static_cast<std::streamsize>(bytes));
    return out;
}

std::string errorOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const VideoError& e) {
        return e.what();
    }
    return {};
}

}  // namespace

TEST(FileSource, readsVtestInfoAndFirstFrame) {
    REQUIRE_OPENCV_DOC();
    FileSource file({.path = test::kVtest});
    EXPECT_EQ(file.info().width, 768);
    EXPECT_EQ(file.info().height, 576);
    EXPECT_DOUBLE_EQ(file.info().fps, 10.0);
    EXPECT_EQ(file.info().frameCount, 795);
    std::optional<Frame> f = file.next();
    ASSERT_TRUE(f);
    EXPECT_EQ(f->image.type(), CV_8UC3);
    EXPECT_EQ(f->sequence, 0u);
    EXPECT_EQ(f->timestamp, std::chrono::nanoseconds(0));
    std::optional<Frame> g = file.next();
    ASSERT_TRUE(g);
    EXPECT_EQ(g->timestamp, std::chrono::milliseconds(100));
}

TEST(FileSource, pullModeIsBitIdenticalAcrossRunsAndSeeksAreFrameExact) {
    REQUIRE_OPENCV_DOC();
    FileSource a({.path = test::kVtest});
    std::vector<cv::Mat> firstRun;
    for (int i = 0; i < 12; ++i) firstRun.push_back(a.next()->image);
    FileSource b({.path = test::kVtest});
    for (int i = 0; i < 12; ++i) EXPECT_EQ(cv::norm(b.next()->image, firstRun[i], cv::NORM_INF), 0.0) << "frame " << i;
    EXPECT_GT(cv::norm(firstRun[0], firstRun[11], cv::NORM_L1), 0.0);  // people move: frames differ
    a.seek(7);
    std::optional<Frame> seven = a.next();
    ASSERT_TRUE(seven);
    EXPECT_EQ(cv::norm(seven->image, firstRun[7], cv::NORM_INF), 0.0);
    EXPECT_EQ(seven->timestamp, std::chrono::milliseconds(700));
}

TEST(FileSource, readsEveryFrameThenEnds) {
    REQUIRE_OPENCV_DOC();
    FileSource file({.path = test::kVtest});
    int n = 0;
    while (file.next()) ++n;
    EXPECT_EQ(n, 795);
    GrabResult r = file.grab();
    EXPECT_EQ(r.state.status, SourceStatus::Ended);
}

TEST(FileSource, loopsWithTimestampsThatKeepRising) {
    REQUIRE_OPENCV_DOC();
    FileSource file({.path = test::kVtest, .loop = true});
    file.seek(794);
    std::optional<Frame> last = file.next();
    std::optional<Frame> wrapped = file.next();
    ASSERT_TRUE(last && wrapped);
    EXPECT_EQ(wrapped->timestamp - last->timestamp, std::chrono::milliseconds(100));
    FileSource fresh({.path = test::kVtest});
    EXPECT_EQ(cv::norm(wrapped->image, fresh.next()->image, cv::NORM_INF), 0.0);
}

TEST(FileSource, missingFileNamesTheFile) {
    const std::string msg = errorOf([] { FileSource({.path = "/nonexistent/clip.avi"}); });
    EXPECT_NE(msg.find("/nonexistent/clip.avi"), std::string::npos) << msg;
    EXPECT_NE(msg.find("does not exist"), std::string::npos) << msg;
}

TEST(FileSource, fileThatIsNotAVideoIsRefused) {
    const test::TempDir tmp;
    const fs::path junk = tmp.path() / "not-a-video.avi";
    std::ofstream(junk) << "this is text, not a video container\n";
    const std::string msg = errorOf([&] { FileSource({.path = junk.string()}); });
    EXPECT_NE(msg.find(junk.string()), std::string::npos) << msg;
    EXPECT_NE(msg.find("FFmpeg cannot open"), std::string::npos) << msg;
}

TEST(FileSource, unsupportedCodecIsRefused) {
    REQUIRE_OPENCV_DOC();
    // vtest.avi with its codec tag rewritten to one no decoder knows.
    std::ifstream in(test::kVtest, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), {});
    int patched = 0;
    for (const char* tag : {"DIV3", "div3"})
        for (std::size_t p = bytes.find(tag); p != std::string::npos && p < 8192; p = bytes.find(tag, p + 4)) {
            bytes.replace(p, 4, "QQZZ");
            ++patched;
        }
    ASSERT_GT(patched, 0);
    const test::TempDir tmp;
    const fs::path out = tmp.path() / "unknown-codec.avi";
    std::ofstream(out, std::ios::binary) << bytes;
    const std::string msg = errorOf([&] { FileSource({.path = out.string()}); });
    EXPECT_NE(msg.find(out.string()), std::string::npos) << msg;
    EXPECT_FALSE(msg.empty());
}

TEST(FileSource, truncatedFileStopsWithFileAndFrameNamed) {
    REQUIRE_OPENCV_DOC();
    const test::TempDir tmp;
    const fs::path cut = truncatedCopy(tmp.path(), 3'000'000);
    FileSource file({.path = cut.string()});
    int good = 0;
    std::string msg;
    try {
        while (file.next()) ++good;
    } catch (const VideoError& e) {
        msg = e.what();
    }
    EXPECT_GT(good, 100);  // everything before the cut was delivered
    EXPECT_LT(good, 795);
    EXPECT_NE(msg.find(cut.string()), std::string::npos) << msg;
    EXPECT_NE(msg.find("frame " + std::to_string(good) + " of 795"), std::string::npos) << msg;
}

TEST(FileSource, truncatedFileWithSkipEndsWithoutError) {
    REQUIRE_OPENCV_DOC();
    const test::TempDir tmp;
    const fs::path cut = truncatedCopy(tmp.path(), 3'000'000);
    FileSource file({.path = cut.string(), .onDamage = OnDamage::Skip});
    int good = 0;
    GrabResult r;
    while ((r = file.grab()).frame) ++good;
    EXPECT_GT(good, 100);
    EXPECT_EQ(r.state.status, SourceStatus::Ended) << r.state.reason;
    EXPECT_GT(file.damagedFramesSkipped(), 0u);
    EXPECT_NE(r.state.reason.find("damaged frames skipped"), std::string::npos) << r.state.reason;
}

TEST(FileSource, damagedMiddleIsSkippedAndLaterFramesStillCome) {
    REQUIRE_OPENCV_DOC();
    const test::TempDir tmp;
    const fs::path bad = tmp.path() / "vtest-damaged-middle.avi";
    fs::copy_file(test::kVtest, bad, fs::copy_options::overwrite_existing);
    {
        std::fstream f(bad, std::ios::in | std::ios::out | std::ios::binary);
        f.seekp(3'000'000);
        cv::RNG rng(7);  // fixed seed: the same damage every run
        for (int i = 0; i < 300'000; ++i) f.put(static_cast<char>(rng.uniform(0, 256)));
    }
    FileSource stop({.path = bad.string()});
    EXPECT_FALSE(errorOf([&] {
                     while (stop.next()) {}
                 }).empty());
    FileSource skip({.path = bad.string(), .onDamage = OnDamage::Skip});
    std::uint64_t lastSequence = 0;
    int frames = 0;
    while (std::optional<Frame> f = skip.next()) {
        lastSequence = f->sequence;
        ++frames;
    }
    EXPECT_GT(skip.damagedFramesSkipped(), 0u);
    EXPECT_GT(frames, 700);
    EXPECT_EQ(lastSequence + 1, static_cast<std::uint64_t>(frames));
}

TEST(FileSource, megamindBugyPlaysWithoutCrashing) {
    const std::string path = test::kOpencvData + "Megamind_bugy.avi";
    if (!fs::exists(path)) GTEST_SKIP() << path << " absent";
    FileSource file({.path = path, .onDamage = OnDamage::Skip});
    int frames = 0;
    while (std::optional<Frame> f = file.next()) {
        ASSERT_EQ(f->image.size(), cv::Size(720, 528));
        ++frames;
    }
    // FFmpeg conceals its damaged macroblocks; the container's 270 frames all come out.
    EXPECT_EQ(frames, 270);
}
