#include "video/matte/BackgroundMatte.hpp"

#include "video/pixels/AreaShrink.hpp"
#include "video/pixels/VideoError.hpp"

#include <opencv2/bgsegm.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/video/background_segm.hpp>

namespace arcomp {

namespace {

void checkBackground(bool ok, const std::string& what) {
    if (!ok) throw VideoError("background matte", "settings", what);
}

cv::Mat ellipse(int px) { return px > 0 ? cv::getStructuringElement(cv::MORPH_ELLIPSE, {px, px}) : cv::Mat(); }

}  // namespace

BackgroundMatte::BackgroundMatte(const BackgroundSpec& spec) : spec_(spec) {
    checkBackground(spec.scale >= 0.1 && spec.scale <= 1.0, "scale must lie in 0.1..1");
    checkBackground(spec.temporal >= 0.0 && spec.temporal <= 0.95, "temporal must lie in 0..0.95");
    checkBackground(spec.openPx >= 0 && spec.closePx >= 0 && spec.featherPx >= 0,
                    "open, close and feather must be >= 0");
    checkBackground(spec.history >= 1, "history must be >= 1");
    checkBackground(spec.threshold > 0.0, "threshold must be > 0");
    switch (spec.method) {
    case BackgroundMethod::Consensus:
        throw VideoError("background matte", "settings",
                         "the consensus method is ConsensusMatte's (makeMatte builds it)");
    case BackgroundMethod::Mog2: model_ = cv::createBackgroundSubtractorMOG2(spec.history, spec.threshold, true); break;
    case BackgroundMethod::Knn: model_ = cv::createBackgroundSubtractorKNN(spec.history, 400.0, true); break;
    case BackgroundMethod::Cnt:
        // minPixelStability ~ a second at 15 fps; maxPixelStability = history.
        model_ = cv::bgsegm::createBackgroundSubtractorCNT(15, true, std::max(15, spec.history), true);
        break;
    case BackgroundMethod::CleanPlate:
        if (!spec.cleanPlate.empty()) {
            plate_ = cv::imread(spec.cleanPlate, cv::IMREAD_COLOR);
            if (plate_.empty()) throw VideoError(spec.cleanPlate, "clean plate", "cannot read the image");
        }
        break;
    }
    openKernel_ = ellipse(spec.openPx);
    closeKernel_ = ellipse(spec.closePx);
}

BackgroundMatte::~BackgroundMatte() = default;

std::string BackgroundMatte::name() const {
    switch (spec_.method) {
    case BackgroundMethod::Consensus: return "background consensus";
    case BackgroundMethod::Mog2: return "background MOG2";
    case BackgroundMethod::Knn: return "background KNN";
    case BackgroundMethod::Cnt: return "background CNT";
    case BackgroundMethod::CleanPlate: return "clean plate";
    }
    return "background";
}

void BackgroundMatte::foreground(const cv::Mat& small) {
    if (spec_.method == BackgroundMethod::CleanPlate) {
        if (plate_.empty())
            plate_ = small.clone();  // the first frame is the empty place
        else if (plate_.size() != small.size())
            cv::resize(plate_, plate_, small.size(), 0, 0, cv::INTER_AREA);
        cv::Mat diff;
        cv::absdiff(small, plate_, diff);
        cv::Mat largest = diff.reshape(1, static_cast<int>(diff.total()));
        cv::reduce(largest, largest, 1, cv::REDUCE_MAX);
        cv::threshold(largest.reshape(1, small.rows), mask_, spec_.threshold, 255, cv::THRESH_BINARY);
        return;
    }
    model_->apply(small, mask_, spec_.learningRate);
    // MOG2 and KNN mark shadows 127: a shadow is not the person.
    cv::threshold(mask_, mask_, 200, 255, cv::THRESH_BINARY);
}

void BackgroundMatte::apply(const cv::Mat& frame, cv::Mat& person) {
    CV_Assert(frame.type() == CV_8UC3);
    if (spec_.scale < 1.0)
        shrinkByArea(frame, spec_.scale, small_);
    else
        small_ = frame;
    foreground(small_);
    if (!openKernel_.empty()) cv::morphologyEx(mask_, mask_, cv::MORPH_OPEN, openKernel_);
    if (!closeKernel_.empty()) cv::morphologyEx(mask_, mask_, cv::MORPH_CLOSE, closeKernel_);

    // Feathering and smoothing at model scale: a fraction of the pixels, and
    // the linear upscale below softens the edge further.
    if (spec_.featherPx > 0) {
        const int k = std::max(1, static_cast<int>(spec_.featherPx * spec_.scale + 0.5)) | 1;
        cv::GaussianBlur(mask_, soft_, {k, k}, 0.0);
    } else {
        mask_.copyTo(soft_);
    }
    if (spec_.temporal > 0.0) {
        if (previous_.size() == soft_.size())
            cv::addWeighted(previous_, spec_.temporal, soft_, 1.0 - spec_.temporal, 0.0, soft_);
        soft_.copyTo(previous_);
    }
    if (soft_.size() != frame.size())
        cv::resize(soft_, alpha_, frame.size(), 0, 0, cv::INTER_LINEAR);
    else
        soft_.copyTo(alpha_);
    premultiply(frame, alpha_, person);
}

}  // namespace arcomp
