#include "video/pixels/YuvConversion.hpp"

#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>

using namespace arcomp;

namespace {

cv::Mat patches() {
    cv::Mat img(64, 128, CV_8UC3);
    const cv::Vec3b colours[] = {{40, 160, 230}, {200, 60, 60},   {30, 200, 40},  {128, 128, 128},
                                 {16, 16, 16},   {240, 240, 240}, {90, 140, 200}, {255, 0, 255}};
    for (int i = 0; i < 8; ++i) img(cv::Rect((i % 4) * 32, (i / 4) * 32, 32, 32)).setTo(colours[i]);
    return img;
}

// Compares patch centres only: chroma subsampling blurs the patch borders.
double worstCentreError(const cv::Mat& a, const cv::Mat& b) {
    double worst = 0;
    for (int i = 0; i < 8; ++i) {
        const cv::Rect centre((i % 4) * 32 + 8, (i / 4) * 32 + 8, 16, 16);
        worst = std::max(worst, cv::norm(a(centre), b(centre), cv::NORM_INF));
    }
    return worst;
}

}  // namespace

TEST(YuvConversion, limitedRangeBlackAndWhiteMapToZeroAnd255) {
    const std::uint8_t yuyv[] = {16, 128, 235, 128};
    const cv::Mat bgr = yuyvToBgr(yuyv, 2, 1, 4, {YuvMatrix::Bt601, YuvRange::Limited});
    EXPECT_EQ(bgr.at<cv::Vec3b>(0, 0), cv::Vec3b(0, 0, 0));
    EXPECT_EQ(bgr.at<cv::Vec3b>(0, 1), cv::Vec3b(255, 255, 255));
}

TEST(YuvConversion, bt709RedDecodesToRedAndTheWrongMatrixShiftsGreens) {
    // Pure red encoded with BT.709 limited: Y=63, U=102, V=240.
    const std::uint8_t red[] = {63, 102, 63, 240};
    const cv::Vec3b r = yuyvToBgr(red, 2, 1, 4, {YuvMatrix::Bt709, YuvRange::Limited}).at<cv::Vec3b>(0, 0);
    EXPECT_NEAR(r[2], 255, 2);
    EXPECT_NEAR(r[1], 0, 2);
    EXPECT_NEAR(r[0], 0, 2);
    const cv::Mat green(2, 2, CV_8UC3, cv::Scalar(40, 200, 40));
    const auto yuyv = bgrToYuyv(green, {YuvMatrix::Bt709, YuvRange::Limited});
    const cv::Mat wrong = yuyvToBgr(yuyv.data(), 2, 2, 4, {YuvMatrix::Bt601, YuvRange::Limited});
    EXPECT_GT(cv::norm(wrong, green, cv::NORM_INF), 15.0);
}

TEST(YuvConversion, roundTripsEveryMatrixAndRange) {
    const cv::Mat src = patches();
    for (YuvMatrix m : {YuvMatrix::Bt601, YuvMatrix::Bt709})
        for (YuvRange r : {YuvRange::Limited, YuvRange::Full}) {
            const YuvEncoding e{m, r};
            const auto yuyv = bgrToYuyv(src, e);
            EXPECT_LE(worstCentreError(yuyvToBgr(yuyv.data(), src.cols, src.rows, src.cols * 2, e), src), 2.0);
            const auto nv12 = bgrToNv12(src, e);
            const cv::Mat back =
                nv12ToBgr(nv12.data(), src.cols, nv12.data() + src.total(), src.cols, src.cols, src.rows, e);
            EXPECT_LE(worstCentreError(back, src), 2.0);
        }
}

TEST(YuvConversion, sameSceneFromYuyvNv12AndMjpegAgrees) {
    const cv::Mat scene = patches();
    const YuvEncoding hd = defaultYuvEncoding(PixelFormat::Yuyv, 720);
    EXPECT_EQ(hd.matrix, YuvMatrix::Bt709);
    const auto yuyv = bgrToYuyv(scene, hd);
    const cv::Mat fromYuyv = yuyvToBgr(yuyv.data(), scene.cols, scene.rows, scene.cols * 2, hd);
    const auto nv12 = bgrToNv12(scene, hd);
    const cv::Mat fromNv12 =
        nv12ToBgr(nv12.data(), scene.cols, nv12.data() + scene.total(), scene.cols, scene.cols, scene.rows, hd);
    std::vector<std::uint8_t> jpeg;
    cv::imencode(".jpg", scene, jpeg, {cv::IMWRITE_JPEG_QUALITY, 95});
    const cv::Mat fromMjpeg = cv::imdecode(jpeg, cv::IMREAD_COLOR);
    EXPECT_LE(worstCentreError(fromYuyv, fromMjpeg), 4.0);
    EXPECT_LE(worstCentreError(fromNv12, fromMjpeg), 4.0);
    // Decoding the YUYV with the wrong range is caught by the same tolerance.
    const cv::Mat wrongRange =
        yuyvToBgr(yuyv.data(), scene.cols, scene.rows, scene.cols * 2, {hd.matrix, YuvRange::Full});
    EXPECT_GT(worstCentreError(wrongRange, fromMjpeg), 10.0);
}
