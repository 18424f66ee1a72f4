#pragma once
// How well a foreground mask matches CDnet ground truth, counted the CDnet
// way: label 255 is the person; 0 (static) and 50 (hard shadow) are
// background; 85 (outside the region of interest) and 170 (unknown, e.g. a
// motion-blurred edge) are not counted, nor is any pixel outside `roi`.
//
//   MatteScore total;
//   total.add(mask, labels, roi);          // mask: CV_8UC1, > 127 = person
//   double f = total.fMeasure();
//
// Counts add up over frames; the figures are those of the totals, as CDnet
// reports a sequence.

#include <opencv2/core/mat.hpp>

#include <cstdint>

namespace arcomp {

struct MatteScore {
    std::int64_t truePositives = 0, falsePositives = 0, falseNegatives = 0, trueNegatives = 0;

    // `mask` and `labels` are CV_8UC1 of one size; `roi` is empty or CV_8UC1
    // of that size (0 = not scored).
    void add(const cv::Mat& mask, const cv::Mat& labels, const cv::Mat& roi = cv::Mat());
    MatteScore& operator+=(const MatteScore& other);

    double precision() const;
    double recall() const;
    double fMeasure() const;
    double iou() const;
    // Percentage of wrong classifications among the counted pixels.
    double percentWrong() const;
};

}  // namespace arcomp
