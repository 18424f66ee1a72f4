#pragma once
// The calibration, drawn over the video so that it can be checked by eye:
// the floor's 1 m grid where the calibrated camera says the floor is, and
// each tracked person's foot point with their id and distance. Grid lines
// that lie along the tiles and marks on the feet mean the camera file fits;
// a grid that slides off the floor, or a distance a tape measure disagrees
// with, means it does not.
// Drawn on the CPU into a premultiplied RGBA image at the video's size, which
// the window presenter stretches over the frame (runtime/app/WindowPresenter.hpp).
//
//   CalibrationOverlay overlay;
//   overlay.draw(*cfg.camera.calibrated, station.size(), station.standingPeople());   // each frame
//   presenter.present(station.compositedFrame(), windowSize, &stats.image(), &overlay.image());
//
// The grid covers 10 m each way around where the optical axis meets the
// floor (kept within 10 m of the point below the lens, so that a camera
// looking near the horizon still gets its near floor), and only the floor
// in front of the lens.

#include "graph/camera/CalibratedCamera.hpp"
#include "runtime/station/PersonDepthStage.hpp"

#include <opencv2/core.hpp>

#include <span>
#include <string>

namespace arcomp {

class CalibrationOverlay {
public:
    static constexpr int kGridHalfMetres = 10;

    // `camera` at any resolution (it is scaled to `size`); `people` in frame pixels.
    void draw(const CalibratedCamera& camera, glm::ivec2 size, std::span<const StandingPerson> people);
    // Premultiplied RGBA at `size`, rows top to bottom; transparent where nothing is drawn.
    const cv::Mat& image() const { return image_; }

private:
    // The grid only changes with the camera (a reload), so it is kept.
    cv::Mat grid_;
    CalibratedCamera gridCamera_;
    cv::Mat image_;
};

// The floor grid alone, drawn into premultiplied RGBA `image` (at the camera's
// intrinsics.imageSize): lines every metre, the x axis (z = 0) and z axis (x = 0) in their own colours.
void drawFloorGrid(cv::Mat& image, const CalibratedCamera& camera);
// "#3 7.4 m", with "(kept)" when the distance is an earlier frame's and
// "(plane)" when it is the person plane's.
std::string standingLabel(const StandingPerson& person);

}  // namespace arcomp
