#pragma once
// The default person matte for real places: a ConsensusModel (people who
// stand still stay in, shadows and light changes stay out) run at reduced
// scale, its person pixels cleaned of specks and holes, and the edge laid
// onto the frame's own edges by a guided filter (He, Sun & Tang, 2013), so
// the composite shows neither a halo of background nor a shrunken person.
//
//   ConsensusMatte matte(BackgroundSpec{});      // method Consensus, defaults
//   for (each frame in order) matte.apply(frame, person);   // premultiplied BGRA
//
// The guided filter's coefficients are computed at model scale and only
// applied at full size (the "fast guided filter", He & Sun, 2015): the full
// frame costs one grey conversion and one multiply-add per pixel.
// Deterministic: the same frames in the same order give the same alphas.

#include "video/matte/ConsensusModel.hpp"
#include "video/matte/MatteSpec.hpp"

#include <opencv2/core/mat.hpp>

namespace arcomp {

class ConsensusMatte final : public PersonMatte {
public:
    // Throws VideoError for settings out of range or an unreadable clean plate.
    explicit ConsensusMatte(const BackgroundSpec& spec);
    void apply(const cv::Mat& frame, cv::Mat& person) override;
    std::string name() const override { return "background consensus"; }

    // The last cleaned person mask at model scale, 0 or 255.
    const cv::Mat& mask() const { return mask_; }
    // The last labels of the model at model scale (0, kShadow, kPerson).
    const cv::Mat& labels() const { return labels_; }
    const ConsensusModel& model() const { return model_; }

private:
    void cleanUp();
    // A ghost is foreground that the model holds and the image does not:
    // where someone stood while the start-up median was taken, after they
    // left. Its outline is sharp in the model's background, not in the
    // image; a person's, still or moving, is sharp in the image. Ghosts are
    // dropped from the mask and relearnt at once.
    void forgetGhosts();
    void guidedEdges(const cv::Mat& frame);
    int guidedRadius() const;  // window radius at model scale

    BackgroundSpec spec_;
    ConsensusModel model_;
    cv::Mat closeKernel_;
    cv::Rect work_;  // model-scale box around the people of this frame, where clean-up and edges work
    cv::Mat small_, labels_, mask_, alpha_;
    cv::Mat ids_, stats_, centroids_, holes_, modelGrey_, ghosts_;                // clean-up scratch
    cv::Mat grey_, guide_, target_, guideSquared_, guideTarget_, meanI_, meanP_;  // guided filter scratch
    cv::Mat meanA_, meanB_;
};

}  // namespace arcomp
