#pragma once
// How well a found person mask matches the true one.

#include <opencv2/core.hpp>

namespace arcomp::test {

// Intersection over union of two 8-bit masks; two empty masks agree fully.
inline double maskIou(const cv::Mat& a, const cv::Mat& b) {
    const double either = cv::countNonZero(a | b);
    return either > 0 ? cv::countNonZero(a & b) / either : 1.0;
}

}  // namespace arcomp::test
