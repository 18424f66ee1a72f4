#pragma once
// A per-pixel background model that keeps people who stand still, tells cast
// shadows from people, and survives a light being switched on. Each pixel
// remembers `samples` colours of its background (sample consensus, after
// ViBe: Barnich & Van Droogenbroeck, 2011); a colour near at least `matches`
// of them is background.
//
//   ConsensusModel model(spec.consensus);        // spec: video/matte/MatteSpec.hpp
//   cv::Mat labels;                              // CV_8UC1 at the image's size
//   for (each image in order) model.apply(image, labels);   // 0, kShadow or kPerson
//
// What makes it fit for a kiosk:
//  - Selective update: only pixels seen as background refresh the model, so
//    a visitor who stops is not learnt. A pixel that stays foreground and
//    unchanging for `absorbSeconds` (a bag left behind) slowly joins the
//    background again.
//  - Shadows: a foreground pixel darker than the background by a factor in
//    [shadowDarkest, shadowLightest] with the background's chromaticity is a
//    shadow (brightness and chromaticity distortion: Horprasert, Harwood &
//    Davis, 1999).
//  - Light changes: when much of the frame changes at once by one common
//    gain per channel, the model is rescaled by that gain in the same frame.
//  - Start-up: from a clean plate (setPlate), or else from the per-pixel
//    median of the first `warmupSeconds`, which needs no empty frame.

#include "video/matte/MatteSpec.hpp"

#include <opencv2/core/mat.hpp>

#include <cstdint>
#include <vector>

namespace arcomp {

class ConsensusModel {
public:
    static constexpr std::uint8_t kShadow = 64;
    static constexpr std::uint8_t kPerson = 255;

    // Throws VideoError for settings out of range.
    explicit ConsensusModel(const ConsensusSpec& spec);

    // Starts the model from an image of the empty place (any size; scaled to
    // the images given to apply). Skips the median warm-up.
    void setPlate(const cv::Mat& plate);

    // `image` is CV_8UC3 BGR, the same size every call.
    void apply(const cv::Mat& image, cv::Mat& labels);

    // Takes the pixels where `where` (CV_8UC1, the images' size) is not 0
    // as background at once, from the last image: for a ghost, the place
    // something left that the model still holds (see ConsensusMatte).
    void relearn(const cv::Mat& where);

    // Per pixel, how many frames it has been foreground and unchanging (CV_16UC1).
    const cv::Mat& stillFrames() const { return stillFrames_; }
    // The model's estimate of the empty place (CV_8UC3), for shadows and inspection.
    const cv::Mat& background() const { return background_; }
    // How many frames so far had a light change corrected (for tests and logs).
    int lightChanges() const { return lightChanges_; }

private:
    void seed(const cv::Mat& empty);
    void classify(const cv::Mat& image, cv::Mat& labels);
    void update(const cv::Mat& image, const cv::Mat& labels);
    bool correctLightChange(const cv::Mat& image, const cv::Mat& labels);
    void finishWarmup();

    ConsensusSpec spec_;
    cv::Size size_;
    std::vector<std::uint8_t> samples_;  // per pixel: samples x BGR, contiguous
    cv::Mat background_;                 // running mean of the background seen, CV_8UC3
    cv::Mat previous_;                   // last image, for the "unchanging" test
    cv::Mat stillFrames_;                // CV_16UC1: frames a pixel has been foreground and unchanging
    std::vector<cv::Mat> warmup_;        // images kept for the start-up median
    int warmupFrames_ = 0;
    bool seeded_ = false, plateGiven_ = false;
    int lightChanges_ = 0;
    std::uint32_t random_ = 2463534242u;
};

}  // namespace arcomp
