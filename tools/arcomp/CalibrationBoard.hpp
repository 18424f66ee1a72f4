#pragma once
// A printed calibration target, and the lens it measures. A chessboard or a
// ChArUco board (a chessboard with ArUco markers in its white squares, so
// that a view of part of the board still tells which corners it shows).
// Sizes count squares, as on the print: a 9 x 6 chessboard has 8 x 5 inner
// corners.
//
//   CalibrationBoard board({.kind = BoardKind::Chessboard, .cols = 9, .rows = 6, .square = 0.025});  // InputError if
//   bad std::vector<BoardView> views; for (const cv::Mat& frame : frames)
//       if (std::optional<BoardView> v = board.find(frame)) views.push_back(*v);
//   LensFit lens = board.calibrate(views, frames[0].size());   // cv::calibrateCamera: k1, k2, p1, p2, k3
//
// `arcomp calibrate intrinsics` (CalibrateIntrinsics.cpp) is the command around it.

#include "graph/camera/CalibratedCamera.hpp"

#include <opencv2/aruco/charuco.hpp>
#include <opencv2/core.hpp>

#include <optional>
#include <string>
#include <vector>

namespace arcomp {

enum class BoardKind { Chessboard, Charuco };

struct BoardSpec {
    BoardKind kind = BoardKind::Chessboard;
    int cols = 0, rows = 0;                  // squares across and down
    double square = 0.0;                     // a square's edge, metres
    double markerLength = 0.0;               // ChArUco: a marker's edge, metres
    std::string dictionary = "DICT_4X4_50";  // ChArUco: its markers' dictionary
};

// What one image shows of the board.
struct BoardView {
    std::vector<cv::Point2f> corners;  // subpixel image points of inner corners
    std::vector<int> ids;              // which corner each is: row by row over the inner corners
    double coverage = 0.0;             // the share of the image inside the corners' convex hull
};

struct LensFit {
    CameraIntrinsics intrinsics;
    double rmsPixels = 0.0;  // reprojection error over all corners of all views
};

class CalibrationBoard {
public:
    explicit CalibrationBoard(const BoardSpec& spec);

    // Nothing when the board is not in the image, or too little of it to
    // place: a ChArUco view needs 6 corners, not all on one line.
    std::optional<BoardView> find(const cv::Mat& image) const;
    // Throws InputError when the views do not determine a lens.
    LensFit calibrate(const std::vector<BoardView>& views, cv::Size imageSize) const;
    // "chessboard of 9 x 6 squares (8 x 5 inner corners)", for messages.
    std::string describe() const;

private:
    BoardSpec spec_;
    cv::Ptr<cv::aruco::CharucoBoard> charuco_;
};

}  // namespace arcomp
