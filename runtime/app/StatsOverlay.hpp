#pragma once
// The operator's on-screen panel: frame time over the last seconds against
// the target, the controller's predicted vs measured time, what was drawn
// per LOD level and shading, grouped proxies, and the camera's state and
// dropped frames. Drawn on the CPU into a small premultiplied RGBA image
// that the window presenter lays over the composited frame, so it costs the
// GPU one textured quad and works the same on GL 3.3 and GLES 3.0.
//
//   StatsOverlay overlay;
//   overlay.add(station.stats(), station.drawList(), camera);   // each frame
//   const cv::Mat& rgba = overlay.image();

#include "graph/core/DrawList.hpp"
#include "runtime/station/Station.hpp"
#include "video/sources/SourceStatus.hpp"

#include <opencv2/core.hpp>

#include <deque>
#include <string>

namespace arcomp {

struct CameraLine {
    std::string name;
    SourceState state;
    std::uint64_t drops = 0;
};

class StatsOverlay {
public:
    static constexpr int kWidth = 440, kHeight = 200;
    static constexpr std::size_t kHistory = 120;  // frames in the graph

    // `targetMs` is drawn as the graph's reference line: the budget's
    // target when the controller is on, else the display's frame period.
    void add(const FrameStats& stats, const DrawList& drawn, const CameraLine& camera, double frameMs, double targetMs);
    // Premultiplied RGBA, rows top to bottom.
    const cv::Mat& image() const { return image_; }

private:
    void draw(const FrameStats& stats, const DrawList& drawn, const CameraLine& camera, double targetMs);
    std::deque<double> frameMs_;
    cv::Mat image_;
};

}  // namespace arcomp
