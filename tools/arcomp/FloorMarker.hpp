#pragma once
// An ArUco marker lying flat on the floor as the floor frame's origin, for
// `arcomp calibrate floor --marker ID --marker-size M`: its four corners,
// each with its pixel and its floor point, to place the camera by the same
// solvePnP as marks given by hand.
//
// The marker's centre is the origin and its edges run along x and z: +x
// towards the marker's right edge as printed, +z towards its bottom edge.
// (The floor frame is right-handed with +y up, so from above, with x to the
// right, z points down the page: the print lies the way it reads.)
//
//   std::vector<FloorPoint> corners = findFloorMarker(image, "DICT_4X4_50", 7, 0.40);   // InputError when it is not
//   there

#include <opencv2/core.hpp>

#include <string>
#include <vector>

namespace arcomp {

// A floor mark's pixel in the image and its place on the floor (metres, y = 0).
struct FloorPoint {
    cv::Point2d pixel;
    cv::Point3d floor;
};

// The marker's top-left, top-right, bottom-right and bottom-left corners as
// printed. `sizeMetres` is the black square's edge, border included.
std::vector<FloorPoint> findFloorMarker(const cv::Mat& image, const std::string& dictionary, int id, double sizeMetres);

}  // namespace arcomp
