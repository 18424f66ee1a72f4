#pragma once
// Photographs of flat targets (a chessboard, a ChArUco board, a marker on
// the floor) through a known camera, for the calibrate commands' tests and
// `arcomp-bench ar`: the calibration has to give back the camera that took them.
//
//   SyntheticCamera camera({.size = {640, 480}, .fx = 600, .fy = 590, .cx = 322, .cy = 236, .distortion = {-0.08}});
//   const cv::Mat board = chessboardTexture(9, 6, 40);            // 40 texels a square, one square of white margin
//   cv::Mat photo = camera.photograph(board, 0.025 / 40, {-0.025, -0.025}, boardToCamera(rvec, tvec));
//   cv::Mat floor = camera.photograph(floorWithMarkers(...), 1.0 / 400, {-1.0, -1.0}, floorToCamera(0, 3, 3.6, 40));
//
// The target lies in its plane's (X, Y) (for the floor, x and z); texel
// (column, row) covers origin + (column, row) * metresPerTexel onwards.
// planeToCamera's columns are the camera-frame directions of the plane's X
// and Y axes and the camera-frame position of its origin, so the undistorted
// image of plane point (X, Y) is K * planeToCamera * (X, Y, 1). Each
// photograph is rendered at twice the size and averaged down, so edges are
// antialiased as a real sensor's are; distortion moves each pixel where the
// lens model puts it.

#include <opencv2/aruco.hpp>
#include <opencv2/aruco/charuco.hpp>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include <cmath>
#include <vector>

namespace arcomp {

struct SyntheticLens {
    cv::Size size{640, 480};
    double fx = 0.0, fy = 0.0, cx = 0.0, cy = 0.0;
    cv::Vec<double, 5> distortion{};  // k1, k2, p1, p2, k3
};

class SyntheticCamera {
public:
    explicit SyntheticCamera(const SyntheticLens& lens) : lens_(lens) {
        // The normalised ray of every supersampled pixel. Undistorting is the
        // slow part, and it depends only on the lens: done once, exactly at
        // every 8th supersample and bilinearly between (the rays bend
        // smoothly; the difference is under a thousandth of a pixel).
        const cv::Size big(lens.size.width * kSuper, lens.size.height * kSuper);
        const int nodesX = big.width / kStep + 2, nodesY = big.height / kStep + 2;
        std::vector<cv::Point2d> nodes;
        for (int j = 0; j < nodesY; ++j)
            for (int i = 0; i < nodesX; ++i) nodes.push_back(centre(i * kStep, j * kStep));
        const cv::Matx33d k(lens.fx, 0, lens.cx, 0, lens.fy, lens.cy, 0, 0, 1);
        std::vector<cv::Point2d> nodeRays;
        cv::undistortPoints(nodes, nodeRays, k, lens.distortion, cv::noArray(), cv::noArray(),
                            cv::TermCriteria(cv::TermCriteria::COUNT + cv::TermCriteria::EPS, 20, 1e-12));
        rays_.create(big, CV_64FC2);
        for (int y = 0; y < big.height; ++y)
            for (int x = 0; x < big.width; ++x) {
                const int i = x / kStep, j = y / kStep;
                const double a = static_cast<double>(x % kStep) / kStep, b = static_cast<double>(y % kStep) / kStep;
                const auto node = [&](int di, int dj) {
                    return nodeRays[static_cast<std::size_t>((j + dj) * nodesX + i + di)];
                };
                rays_.at<cv::Point2d>(y, x) =
                    (node(0, 0) * (1 - a) + node(1, 0) * a) * (1 - b) + (node(0, 1) * (1 - a) + node(1, 1) * a) * b;
            }
    }

    cv::Mat photograph(const cv::Mat& texture, double metresPerTexel, cv::Point2d origin,
                       const cv::Matx33d& planeToCamera, cv::Scalar background = cv::Scalar::all(70)) const {
        const cv::Matx33d cameraToPlane = planeToCamera.inv();
        cv::Mat mapX(rays_.size(), CV_32F), mapY(rays_.size(), CV_32F);
        for (int y = 0; y < rays_.rows; ++y)
            for (int x = 0; x < rays_.cols; ++x) {
                const cv::Point2d r = rays_.at<cv::Point2d>(y, x);
                const cv::Vec3d p = cameraToPlane * cv::Vec3d(r.x, r.y, 1.0);
                // The ray meets the plane behind the lens, or not at all: no target there.
                const bool seen = p[2] > 1e-12;
                mapX.at<float>(y, x) =
                    seen ? static_cast<float>((p[0] / p[2] - origin.x) / metresPerTexel - 0.5) : -1e6f;
                mapY.at<float>(y, x) =
                    seen ? static_cast<float>((p[1] / p[2] - origin.y) / metresPerTexel - 0.5) : -1e6f;
            }
        cv::Mat big, photo;
        cv::remap(texture, big, mapX, mapY, cv::INTER_LINEAR, cv::BORDER_CONSTANT, background);
        cv::resize(big, photo, lens_.size, 0, 0, cv::INTER_AREA);
        return photo;
    }

    // What this lens makes of a picture taken by the ideal pinhole camera
    // with the same fx, fy, cx, cy (a rendering): each pixel moved where the
    // distortion puts it, antialiased like photograph().
    cv::Mat throughLens(const cv::Mat& pinhole) const {
        CV_Assert(pinhole.size() == lens_.size);
        if (pinholeX_.empty()) {
            pinholeX_.create(rays_.size(), CV_32F);
            pinholeY_.create(rays_.size(), CV_32F);
            for (int y = 0; y < rays_.rows; ++y)
                for (int x = 0; x < rays_.cols; ++x) {
                    const cv::Point2d r = rays_.at<cv::Point2d>(y, x);
                    pinholeX_.at<float>(y, x) = static_cast<float>(lens_.fx * r.x + lens_.cx);
                    pinholeY_.at<float>(y, x) = static_cast<float>(lens_.fy * r.y + lens_.cy);
                }
        }
        cv::Mat big, photo;
        cv::remap(pinhole, big, pinholeX_, pinholeY_, cv::INTER_LINEAR, cv::BORDER_REPLICATE);
        cv::resize(big, photo, lens_.size, 0, 0, cv::INTER_AREA);
        return photo;
    }

    const SyntheticLens& lens() const { return lens_; }

private:
    static constexpr int kSuper = 2, kStep = 8;
    // Supersample (x, y)'s centre in the photograph's pixel coordinates.
    static cv::Point2d centre(int x, int y) { return {(x + 0.5) / kSuper - 0.5, (y + 0.5) / kSuper - 0.5}; }
    SyntheticLens lens_;
    cv::Mat rays_;
    mutable cv::Mat pinholeX_, pinholeY_;  // throughLens()'s maps, made at its first call
};

// A target's plane placed by OpenCV's rvec, tvec (plane frame to camera).
inline cv::Matx33d boardToCamera(const cv::Vec3d& rvec, const cv::Vec3d& tvec) {
    cv::Matx33d r;
    cv::Rodrigues(rvec, r);
    return cv::Matx33d(r(0, 0), r(0, 1), tvec[0], r(1, 0), r(1, 1), tvec[1], r(2, 0), r(2, 1), tvec[2]);
}

// cols x rows squares, black first, with one square of white around them
// (the quiet border findChessboardCorners needs). BGR.
inline cv::Mat chessboardTexture(int cols, int rows, int texelsPerSquare) {
    cv::Mat board(texelsPerSquare * (rows + 2), texelsPerSquare * (cols + 2), CV_8UC3, cv::Scalar::all(235));
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < cols; ++c)
            if ((r + c) % 2 == 0)
                board(cv::Rect((c + 1) * texelsPerSquare, (r + 1) * texelsPerSquare, texelsPerSquare, texelsPerSquare))
                    .setTo(cv::Scalar::all(20));
    return board;
}

// The same margin around a ChArUco board as OpenCV draws it. BGR.
inline cv::Mat charucoTexture(const cv::Ptr<cv::aruco::CharucoBoard>& board, int texelsPerSquare) {
    const cv::Size squares = board->getChessboardSize();
    cv::Mat grey;
    board->draw(cv::Size(texelsPerSquare * (squares.width + 2), texelsPerSquare * (squares.height + 2)), grey,
                texelsPerSquare, 1);
    cv::Mat bgr;
    cv::cvtColor(grey, bgr, cv::COLOR_GRAY2BGR);
    return bgr;
}

// A camera `height` metres above the floor at (x, z), looking along -z and
// tilted `tiltDegrees` down; as planeToCamera for the floor's (x, z).
inline cv::Matx33d floorToCamera(double x, double height, double z, double tiltDegrees) {
    const double tilt = tiltDegrees * CV_PI / 180.0;
    // Rows: the camera's right, down and forward in the floor frame (+y up).
    const cv::Matx33d r(1, 0, 0, 0, -std::cos(tilt), std::sin(tilt), 0, -std::sin(tilt), -std::cos(tilt));
    const cv::Vec3d t = -(r * cv::Vec3d(x, height, z));
    return cv::Matx33d(r(0, 0), r(0, 2), t[0], r(1, 0), r(1, 2), t[1], r(2, 0), r(2, 2), t[2]);
}

struct FloorMarkerSpec {
    int id = 0;
    double x = 0.0, z = 0.0;  // its centre on the floor, metres
};

// A light floor `extent` metres square centred on the origin, with ArUco
// markers of `size` metres lying on it as printed: top edge towards -z.
// Texel (column, row) covers (x, z) = -extent / 2 + (column, row) /
// texelsPerMetre onwards. BGR.
inline cv::Mat floorWithMarkers(const cv::Ptr<cv::aruco::Dictionary>& dictionary,
                                const std::vector<FloorMarkerSpec>& markers, double size, double extent,
                                double texelsPerMetre) {
    const int side = static_cast<int>(std::lround(extent * texelsPerMetre));
    cv::Mat floor(side, side, CV_8UC3, cv::Scalar::all(200));
    const int markerSide = static_cast<int>(std::lround(size * texelsPerMetre));
    for (const FloorMarkerSpec& m : markers) {
        cv::Mat marker, bgr;
        cv::aruco::drawMarker(dictionary, m.id, markerSide, marker, 1);
        cv::cvtColor(marker, bgr, cv::COLOR_GRAY2BGR);
        const int left = static_cast<int>(std::lround((m.x - size / 2 + extent / 2) * texelsPerMetre));
        const int top = static_cast<int>(std::lround((m.z - size / 2 + extent / 2) * texelsPerMetre));
        bgr.copyTo(floor(cv::Rect(left, top, markerSide, markerSide)));
    }
    return floor;
}

}  // namespace arcomp
