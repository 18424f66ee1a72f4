#pragma once
// Person matte for real places: foreground is whatever differs from a model
// of the empty scene. The model is OpenCV's MOG2 or KNN, bgsegm's CNT (the
// fastest), or a fixed clean plate. (The default method, Consensus, is
// ConsensusMatte's: video/matte/ConsensusMatte.hpp; makeMatte picks the class.) The raw foreground mask is then made
// fit for compositing: shadows dropped, specks opened away, holes closed,
// the edge feathered, and alpha blended with the previous frame's against
// flicker.
//
//   BackgroundMatte matte({.method = BackgroundMethod::Cnt, .scale = 0.5});
//   for (each frame in order) matte.apply(frame, person);   // premultiplied BGRA
//
// The model runs on a scaled-down copy of the frame (spec.scale): people are
// large, and the cost of the model falls with the square of the scale.
// Deterministic: the same frames in the same order give the same alphas.

#include "video/matte/MatteSpec.hpp"

#include <opencv2/core/mat.hpp>

namespace cv {
class BackgroundSubtractor;
}

namespace arcomp {

class BackgroundMatte final : public PersonMatte {
public:
    // Throws VideoError for settings out of range or an unreadable clean plate.
    explicit BackgroundMatte(const BackgroundSpec& spec);
    ~BackgroundMatte() override;
    void apply(const cv::Mat& frame, cv::Mat& person) override;
    std::string name() const override;

    // The last raw (cleaned, unfeathered) mask at model scale, 0 or 255.
    const cv::Mat& mask() const { return mask_; }

private:
    void foreground(const cv::Mat& small);

    BackgroundSpec spec_;
    cv::Ptr<cv::BackgroundSubtractor> model_;
    cv::Mat plate_;  // CleanPlate, at model scale
    cv::Mat small_, mask_, soft_, alpha_, previous_;
    cv::Mat openKernel_, closeKernel_;
};

}  // namespace arcomp
