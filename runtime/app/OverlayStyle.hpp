#pragma once
// What the run window's overlays (the calibration's floor grid, the zones)
// draw alike: the dark outline under lines and labels, and where a floor
// point is too near the lens's plane to draw (it projects too far out, and
// at or behind the plane nowhere).
//
//   cv::putText(image, label, at, cv::FONT_HERSHEY_SIMPLEX, 0.5, kOverlayOutline, 3, cv::LINE_AA);
//   if (camera.depthOf(floorPoint) < kOverlayNearMetres) skip(floorPoint);

#include <opencv2/core.hpp>

namespace arcomp {

inline const cv::Scalar kOverlayOutline{0, 0, 0, 200};  // premultiplied RGBA
inline constexpr double kOverlayNearMetres = 0.1;

}  // namespace arcomp
