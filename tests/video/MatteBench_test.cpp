// Runs the built `arcomp-bench matte`; skips when the executable has not been built.
#include "tests/support/Shell.hpp"
#include "tests/support/TempDir.hpp"

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <filesystem>
#include <fstream>

namespace {

namespace fs = std::filesystem;

arcomp::test::ShellResult bench(const std::string& args) {
    return arcomp::test::benchCommand("matte --speed-clip /nonexistent/clip.avi " + args);
}

// A tiny CDnet sequence: a grey floor, a dark square crossing it from frame 6,
// labelled 255, with its border labelled 170 (not counted). In the test's
// own folder: ctest runs the tests of this file side by side.
fs::path writeSequence(const arcomp::test::TempDir& folder) {
    const fs::path dir = folder.path() / "seq";
    fs::create_directories(dir / "input");
    fs::create_directories(dir / "groundtruth");
    for (int i = 1; i <= 20; ++i) {
        cv::Mat frame(60, 80, CV_8UC3, cv::Scalar(120, 130, 140)), labels = cv::Mat::zeros(60, 80, CV_8UC1);
        if (i > 5) {
            const cv::Rect box(4 * (i - 5), 20, 16, 24);
            cv::rectangle(frame, box, cv::Scalar(20, 30, 200), cv::FILLED);
            cv::rectangle(labels, box, 170, 2);
            cv::rectangle(labels, {box.x + 1, box.y + 1, box.width - 2, box.height - 2}, 255, cv::FILLED);
        }
        char in[32], gt[32];
        std::snprintf(in, sizeof in, "in%06d.jpg", i);
        std::snprintf(gt, sizeof gt, "gt%06d.png", i);
        cv::imwrite((dir / "input" / in).string(), frame);
        cv::imwrite((dir / "groundtruth" / gt).string(), labels);
    }
    std::ofstream(dir / "temporalROI.txt") << "6 20";
    return dir;
}

}  // namespace

TEST(MatteBench, scoresEveryMethodAndItsPeersAsOneJsonLine) {
    if (!fs::exists(ARCOMP_BINARY)) GTEST_SKIP() << "arcomp not built";
    const arcomp::test::TempDir folder;
    const fs::path out = folder.path() / "out";
    const auto r = bench("--fps 10 --sequence " + writeSequence(folder).string() + " --out " + out.string());
    ASSERT_EQ(r.code, 0) << r.out;
    const std::string json = arcomp::test::lastLine(r.out);
    EXPECT_EQ(json.rfind("{\"bench\":\"matte\"", 0), 0u) << json;
    EXPECT_NE(json.find("\"default\":\"consensus\""), std::string::npos) << json;
    for (const char* name :
         {"consensus", "mog2", "knn", "cnt", "clean_plate", "opencv_mog2", "opencv_knn", "bgsegm_gsoc"})
        EXPECT_NE(json.find(std::string("\"name\":\"") + name + "\""), std::string::npos) << name;
    EXPECT_NE(json.find("\"peer\":true"), std::string::npos);
    EXPECT_NE(json.find("\"ms_per_frame_768x576\":null"), std::string::npos) << "no clip, no speed figure";
    // A plain square on a plain floor: the default finds it.
    const std::size_t consensus = json.find("{\"name\":\"consensus\"");
    const double f = std::stod(json.substr(json.find("\"f_measure\":", consensus) + 12));
    EXPECT_GT(f, 0.8) << json;
    EXPECT_TRUE(fs::exists(out / "strip-consensus.png"));
    EXPECT_TRUE(fs::exists(out / "f_per_frame.png"));
}

TEST(MatteBench, aMissingSequenceOrTemporalRoiIsBadInput) {
    if (!fs::exists(ARCOMP_BINARY)) GTEST_SKIP() << "arcomp not built";
    const auto missing = bench("--sequence /nonexistent/busStation");
    EXPECT_EQ(missing.code, 2) << missing.out;
    EXPECT_NE(missing.out.find("/nonexistent/busStation: not a folder"), std::string::npos) << missing.out;

    const arcomp::test::TempDir folder;
    const fs::path seq = writeSequence(folder);
    fs::remove(seq / "temporalROI.txt");
    const auto noRoi = bench("--sequence " + seq.string());
    EXPECT_EQ(noRoi.code, 2) << noRoi.out;
    EXPECT_NE(noRoi.out.find("temporalROI.txt: file missing"), std::string::npos) << noRoi.out;
}
