#include "video/sources/LensUndistortion.hpp"

#include <gtest/gtest.h>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

namespace arcomp {

// A dot where a barrel-distorting lens images a point comes out, after
// undistortion, where the ideal pinhole would have imaged it.
TEST(LensUndistortion, aDotMovesFromWhereTheLensPutItToWhereThePinholeWould) {
    const cv::Size size(640, 480);
    const cv::Matx33d k(520.0, 0, 322.0, 0, 518.0, 236.0, 0, 0, 1);
    const cv::Vec<double, 5> barrel(-0.28, 0.09, 0.0005, -0.0003, 0.0);
    const std::vector<cv::Point3d> point{{-0.42, 0.31, 1.0}};  // towards a corner, where distortion is strong
    std::vector<cv::Point2d> distorted, ideal;
    cv::projectPoints(point, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), k, barrel, distorted);
    cv::projectPoints(point, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), k, cv::noArray(), ideal);
    ASSERT_GT(cv::norm(distorted[0] - ideal[0]), 10.0);  // the lens really moves it

    cv::Mat frame(size, CV_8UC3, cv::Scalar::all(0));
    cv::circle(frame, distorted[0], 3, cv::Scalar::all(255), cv::FILLED);
    LensUndistortion lens(k, barrel, size);
    lens.apply(frame);
    cv::Mat gray;
    cv::cvtColor(frame, gray, cv::COLOR_BGR2GRAY);
    const cv::Moments m = cv::moments(gray);
    ASSERT_GT(m.m00, 0.0);
    EXPECT_NEAR(m.m10 / m.m00, ideal[0].x, 1.0);
    EXPECT_NEAR(m.m01 / m.m00, ideal[0].y, 1.0);
}

TEST(LensUndistortion, aFrameOfAnotherSizeIsAnError) {
    LensUndistortion lens(cv::Matx33d(500, 0, 320, 0, 500, 240, 0, 0, 1), cv::Vec<double, 5>(-0.1, 0, 0, 0, 0),
                          {640, 480});
    cv::Mat small(240, 320, CV_8UC3, cv::Scalar::all(0));
    EXPECT_THROW(lens.apply(small), std::invalid_argument);
}

}  // namespace arcomp
