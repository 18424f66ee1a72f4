#include "tools/bench/report/MatteScore.hpp"

namespace arcomp {

namespace {

double ratio(std::int64_t a, std::int64_t b) { return b > 0 ? static_cast<double>(a) / static_cast<double>(b) : 0.0; }

}  // namespace

void MatteScore::add(const cv::Mat& mask, const cv::Mat& labels, const cv::Mat& roi) {
    CV_Assert(mask.type() == CV_8UC1 && labels.type() == CV_8UC1 && mask.size() == labels.size());
    CV_Assert(roi.empty() || (roi.type() == CV_8UC1 && roi.size() == mask.size()));
    for (int y = 0; y < mask.rows; ++y) {
        const std::uint8_t* m = mask.ptr<std::uint8_t>(y);
        const std::uint8_t* l = labels.ptr<std::uint8_t>(y);
        const std::uint8_t* r = roi.empty() ? nullptr : roi.ptr<std::uint8_t>(y);
        for (int x = 0; x < mask.cols; ++x) {
            if (r && r[x] == 0) continue;
            const bool person = l[x] == 255;
            const bool background = l[x] == 0 || l[x] == 50;
            if (!person && !background) continue;  // 85, 170 and anything else: not counted
            const bool found = m[x] > 127;
            if (person)
                (found ? truePositives : falseNegatives) += 1;
            else
                (found ? falsePositives : trueNegatives) += 1;
        }
    }
}

MatteScore& MatteScore::operator+=(const MatteScore& other) {
    truePositives += other.truePositives;
    falsePositives += other.falsePositives;
    falseNegatives += other.falseNegatives;
    trueNegatives += other.trueNegatives;
    return *this;
}

double MatteScore::precision() const { return ratio(truePositives, truePositives + falsePositives); }
double MatteScore::recall() const { return ratio(truePositives, truePositives + falseNegatives); }

double MatteScore::fMeasure() const {
    const double p = precision(), r = recall();
    return p + r > 0.0 ? 2.0 * p * r / (p + r) : 0.0;
}

double MatteScore::iou() const { return ratio(truePositives, truePositives + falsePositives + falseNegatives); }

double MatteScore::percentWrong() const {
    return 100.0 *
           ratio(falsePositives + falseNegatives, truePositives + falsePositives + falseNegatives + trueNegatives);
}

}  // namespace arcomp
