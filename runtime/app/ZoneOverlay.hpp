#pragma once
// The zones, drawn over the video so that an operator sees where they lie
// and who stands in them: each zone's outline (a floor zone through the
// calibrated camera, a picture zone as it is), its name and its count; an
// occupied zone in its own colour. Premultiplied RGBA at the video's size,
// over whatever overlay lies below it (the calibration's grid), for the
// window presenter (runtime/app/WindowPresenter.hpp).
//
//   ZoneOverlay zones;
//   zones.draw(&calibration.image(), cfg.zones, station.people().zones, cfg.camera.calibrated, station.size());
//   presenter.present(station.compositedFrame(), windowSize, &stats.image(), &zones.image());

#include "graph/camera/CalibratedCamera.hpp"
#include "runtime/people/PeopleFrame.hpp"
#include "runtime/zones/Zone.hpp"

#include <opencv2/core.hpp>

#include <optional>
#include <span>

namespace arcomp {

class ZoneOverlay {
public:
    // `below`: an overlay at `size` to draw over, or null for a clear one.
    // `counts`: per zone, in the same order (the station's people frame).
    void draw(const cv::Mat* below, std::span<const Zone> zones, std::span<const ZoneCount> counts,
              const std::optional<CalibratedCamera>& camera, glm::ivec2 size);
    const cv::Mat& image() const { return image_; }

private:
    cv::Mat image_;
};

}  // namespace arcomp
