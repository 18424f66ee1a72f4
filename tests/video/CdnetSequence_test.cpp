#include "tools/bench/scenes/CdnetSequence.hpp"

#include "video/pixels/VideoError.hpp"

#include "tests/support/TempDir.hpp"

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include <fstream>

namespace arcomp {
namespace {

namespace fs = std::filesystem;

// A three-frame sequence in the CDnet layout in `dir`.
fs::path writeSequence(const fs::path& dir, bool withTemporalRoi = true, const std::string& roiText = "2 3") {
    fs::create_directories(dir / "input");
    fs::create_directories(dir / "groundtruth");
    for (int i = 1; i <= 3; ++i) {
        char in[32], gt[32];
        std::snprintf(in, sizeof in, "in%06d.jpg", i);
        std::snprintf(gt, sizeof gt, "gt%06d.png", i);
        cv::imwrite((dir / "input" / in).string(), cv::Mat(24, 32, CV_8UC3, cv::Scalar(10 * i, 20, 30)));
        cv::imwrite((dir / "groundtruth" / gt).string(), cv::Mat(24, 32, CV_8UC1, cv::Scalar(85)));
    }
    if (withTemporalRoi) std::ofstream(dir / "temporalROI.txt") << roiText;
    return dir;
}

std::string refusal(const fs::path& dir) {
    try {
        openCdnetSequence(dir);
    } catch (const VideoError& e) {
        return e.what();
    }
    return "accepted";
}

TEST(CdnetSequence, readsFramesLabelsAndTheScoredRange) {
    const arcomp::test::TempDir tmp;
    const CdnetSequence seq = openCdnetSequence(writeSequence(tmp.path() / "cdnet-ok"));
    EXPECT_EQ(seq.frameCount, 3);
    EXPECT_FALSE(seq.scored(1));
    EXPECT_TRUE(seq.scored(2));
    EXPECT_TRUE(seq.scored(3));
    EXPECT_EQ(seq.frame(2).size(), cv::Size(32, 24));
    EXPECT_EQ(seq.labels(3).at<std::uint8_t>(0, 0), 85);
    EXPECT_EQ(cv::countNonZero(seq.roi), 32 * 24) << "no ROI.bmp: everything is scored";
}

TEST(CdnetSequence, aScoredRangeBeyondTheFramesIsCutToThem) {
    const arcomp::test::TempDir tmp;
    const CdnetSequence seq = openCdnetSequence(writeSequence(tmp.path() / "cdnet-long", true, "2 900"));
    EXPECT_EQ(seq.lastScored, 3);
}

TEST(CdnetSequence, refusalsNameTheFolderAndWhatWasExpected) {
    const arcomp::test::TempDir tmp;
    EXPECT_NE(refusal("/nonexistent/busStation").find("/nonexistent/busStation: not a folder"), std::string::npos);
    const std::string missingRoi = refusal(writeSequence(tmp.path() / "cdnet-no-roi", false));
    EXPECT_NE(missingRoi.find("temporalROI.txt: file missing"), std::string::npos) << missingRoi;
    const std::string badRoi = refusal(writeSequence(tmp.path() / "cdnet-bad-roi", true, "300"));
    EXPECT_NE(badRoi.find("temporalROI.txt: expected two frame numbers"), std::string::npos) << badRoi;
    const fs::path noInput = writeSequence(tmp.path() / "cdnet-no-input");
    fs::remove_all(noInput / "input");
    EXPECT_NE(refusal(noInput).find("input/: folder missing"), std::string::npos);
}

TEST(CdnetSequence, opensBusStation) {
    const fs::path dir = fs::path(ARCOMP_SHARED_DATA) / "video/busStation";
    if (!fs::exists(dir)) GTEST_SKIP() << dir << " absent";
    const CdnetSequence seq = openCdnetSequence(dir);
    EXPECT_EQ(seq.frameCount, 1250);
    EXPECT_EQ(seq.firstScored, 300);
    EXPECT_EQ(seq.lastScored, 1250);
    EXPECT_EQ(seq.frame(1).size(), cv::Size(360, 240));
    EXPECT_EQ(seq.roi.size(), cv::Size(360, 240));
}

}  // namespace
}  // namespace arcomp
