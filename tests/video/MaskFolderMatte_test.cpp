// Masks made elsewhere, one a frame: read in order, premultiplied like any
// matte, and a mask that is missing or of the wrong size named in the error.
#include "video/matte/MaskFolderMatte.hpp"

#include "video/pixels/VideoError.hpp"

#include "../support/TempDir.hpp"

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

using namespace arcomp;

TEST(MaskFolderMatte, eachFrameTakesItsOwnMaskInOrder) {
    test::TempDir dir;
    for (int i = 0; i < 2; ++i) {
        cv::Mat mask(4, 6, CV_8UC1, cv::Scalar(0));
        mask.at<std::uint8_t>(1, 2 + i) = 255;
        mask.at<std::uint8_t>(2, 2) = 128;
        ASSERT_TRUE(cv::imwrite(MaskFolderMatte::maskFile(dir.path(), static_cast<std::uint64_t>(i)).string(), mask));
    }
    EXPECT_EQ(MaskFolderMatte::maskFile(dir.path(), 7).filename(), "matte-000007.png");
    MaskFolderMatte matte({.folder = dir.path()});
    const cv::Mat frame(4, 6, CV_8UC3, cv::Scalar(10, 20, 200));
    cv::Mat person;
    matte.apply(frame, person);
    EXPECT_EQ(person.at<cv::Vec4b>(1, 2), cv::Vec4b(10, 20, 200, 255));
    EXPECT_EQ(person.at<cv::Vec4b>(1, 3), cv::Vec4b(0, 0, 0, 0));
    EXPECT_EQ(person.at<cv::Vec4b>(2, 2), cv::Vec4b(5, 10, 100, 128));  // premultiplied
    matte.apply(frame, person);
    EXPECT_EQ(person.at<cv::Vec4b>(1, 2)[3], 0);
    EXPECT_EQ(person.at<cv::Vec4b>(1, 3)[3], 255);
    try {
        matte.apply(frame, person);
        FAIL() << "frame 2 has no mask";
    } catch (const VideoError& e) {
        EXPECT_NE(std::string(e.what()).find("matte-000002.png"), std::string::npos) << e.what();
    }
}

TEST(MaskFolderMatte, aMaskOfAnotherSizeIsRefusedWithBothSizes) {
    test::TempDir dir;
    ASSERT_TRUE(
        cv::imwrite(MaskFolderMatte::maskFile(dir.path(), 0).string(), cv::Mat(4, 6, CV_8UC1, cv::Scalar(255))));
    MaskFolderMatte matte({.folder = dir.path()});
    cv::Mat person;
    try {
        matte.apply(cv::Mat(8, 12, CV_8UC3, cv::Scalar::all(0)), person);
        FAIL() << "a 6x4 mask for a 12x8 frame";
    } catch (const VideoError& e) {
        EXPECT_NE(std::string(e.what()).find("6x4"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("12x8"), std::string::npos) << e.what();
    }
}
