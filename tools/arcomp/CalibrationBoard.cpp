#include "tools/arcomp/CalibrationBoard.hpp"

#include "tools/arcomp/ArucoDictionary.hpp"
#include "tools/cli/Command.hpp"

#include <opencv2/aruco.hpp>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace arcomp {
namespace {

// A ChArUco view with fewer corners, or all on one line, leaves the board's
// pose in that view loose, and calibrateCameraCharuco refuses it.
constexpr int kMinCharucoCorners = 6;

// k3 stays 0, as ROS's camera_calibration keeps it by default: for the
// ordinary lenses of a station the r^6 term fits noise in the views' corners,
// and a k3 fitted that way bends the image wildly outside the area the board
// covered.
constexpr int kCalibrationFlags = cv::CALIB_FIX_K3;

cv::Mat grey(const cv::Mat& image) {
    if (image.channels() == 1) return image;
    cv::Mat g;
    cv::cvtColor(image, g, image.channels() == 4 ? cv::COLOR_BGRA2GRAY : cv::COLOR_BGR2GRAY);
    return g;
}

std::string metres(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", x);
    return text;
}

double hullCoverage(const std::vector<cv::Point2f>& corners, cv::Size imageSize) {
    std::vector<cv::Point2f> hull;
    cv::convexHull(corners, hull);
    return cv::contourArea(hull) / (static_cast<double>(imageSize.width) * imageSize.height);
}

}  // namespace

CalibrationBoard::CalibrationBoard(const BoardSpec& spec) : spec_(spec) {
    const bool chess = spec.kind == BoardKind::Chessboard;
    // findChessboardCorners wants at least 3 inner corners each way.
    const int fewest = chess ? 4 : 3;
    if (spec.cols < fewest || spec.rows < fewest || spec.cols > 100 || spec.rows > 100)
        throw InputError("--cols " + std::to_string(spec.cols) + " --rows " + std::to_string(spec.rows) + ": a " +
                         (chess ? "chessboard" : "ChArUco board") + " needs " + std::to_string(fewest) +
                         " to 100 squares each way (count the squares, not the inner corners)");
    if (chess && spec.cols == spec.rows)
        // A square grid of corners reads the same turned a quarter: views
        // would number its corners differently and disagree on the lens.
        throw InputError("--cols and --rows are both " + std::to_string(spec.cols) +
                         ": a square chessboard's corners can be numbered from any of its corners; use one with "
                         "different counts across and down (for example 9 x 6)");
    if (!(spec.square > 0.0) || !std::isfinite(spec.square))
        throw InputError("--square " + metres(spec.square) + ": a square's edge must be a positive length in metres");
    if (chess) return;
    if (!(spec.markerLength > 0.0) || !(spec.markerLength < spec.square))
        throw InputError("--marker-length " + metres(spec.markerLength) +
                         ": a ChArUco board needs its markers' edge in metres, more than 0 and less than --square " +
                         metres(spec.square));
    const cv::Ptr<cv::aruco::Dictionary> dictionary = arucoDictionary(spec.dictionary);
    const int markers = spec.cols * spec.rows / 2;
    if (markers > dictionary->bytesList.rows)
        throw InputError("--dictionary " + spec.dictionary + ": has " + std::to_string(dictionary->bytesList.rows) +
                         " markers, and a " + std::to_string(spec.cols) + " x " + std::to_string(spec.rows) +
                         " ChArUco board needs " + std::to_string(markers));
    charuco_ = cv::aruco::CharucoBoard::create(spec.cols, spec.rows, static_cast<float>(spec.square),
                                               static_cast<float>(spec.markerLength), dictionary);
}

std::string CalibrationBoard::describe() const {
    const std::string squares = std::to_string(spec_.cols) + " x " + std::to_string(spec_.rows) + " squares";
    const std::string inner =
        std::to_string(spec_.cols - 1) + " x " + std::to_string(spec_.rows - 1) + " inner corners";
    if (spec_.kind == BoardKind::Chessboard) return "chessboard of " + squares + " (" + inner + ")";
    return "ChArUco board of " + squares + " with " + spec_.dictionary + " markers";
}

std::optional<BoardView> CalibrationBoard::find(const cv::Mat& image) const {
    const cv::Mat g = grey(image);
    BoardView view;
    if (spec_.kind == BoardKind::Chessboard) {
        const cv::Size pattern(spec_.cols - 1, spec_.rows - 1);
        if (!cv::findChessboardCorners(g, pattern, view.corners,
                                       cv::CALIB_CB_ADAPTIVE_THRESH | cv::CALIB_CB_NORMALIZE_IMAGE |
                                           cv::CALIB_CB_FAST_CHECK))
            return std::nullopt;
        // The search window stays inside a square: a window reaching over
        // the next corner pulls the estimate towards it.
        double nearest = 1e9;
        for (int r = 0; r < pattern.height; ++r)
            for (int c = 0; c + 1 < pattern.width; ++c)
                nearest = std::min<double>(
                    nearest, cv::norm(view.corners[r * pattern.width + c] - view.corners[r * pattern.width + c + 1]));
        const int half = std::clamp(static_cast<int>(0.4 * nearest), 2, 11);
        cv::cornerSubPix(g, view.corners, cv::Size(half, half), cv::Size(-1, -1),
                         cv::TermCriteria(cv::TermCriteria::EPS + cv::TermCriteria::COUNT, 40, 0.01));
        for (int i = 0; i < static_cast<int>(view.corners.size()); ++i) view.ids.push_back(i);
    } else {
        std::vector<std::vector<cv::Point2f>> markerCorners;
        std::vector<int> markerIds;
        cv::aruco::detectMarkers(g, charuco_->dictionary, markerCorners, markerIds);
        if (markerIds.empty()) return std::nullopt;
        // Interpolation refines each corner with cornerSubPix itself.
        cv::aruco::interpolateCornersCharuco(markerCorners, markerIds, g, charuco_, view.corners, view.ids);
        if (static_cast<int>(view.ids.size()) < kMinCharucoCorners ||
            cv::aruco::testCharucoCornersCollinear(charuco_, view.ids))
            return std::nullopt;
    }
    view.coverage = hullCoverage(view.corners, g.size());
    return view;
}

LensFit CalibrationBoard::calibrate(const std::vector<BoardView>& views, cv::Size imageSize) const {
    cv::Mat cameraMatrix, distortion;
    double rms = 0.0;
    try {
        if (spec_.kind == BoardKind::Chessboard) {
            std::vector<std::vector<cv::Point3f>> board;
            std::vector<std::vector<cv::Point2f>> image;
            const int across = spec_.cols - 1;
            for (const BoardView& v : views) {
                std::vector<cv::Point3f>& points = board.emplace_back();
                for (int id : v.ids)
                    points.emplace_back(static_cast<float>((id % across) * spec_.square),
                                        static_cast<float>((id / across) * spec_.square), 0.0f);
                image.push_back(v.corners);
            }
            rms = cv::calibrateCamera(board, image, imageSize, cameraMatrix, distortion, cv::noArray(), cv::noArray(),
                                      kCalibrationFlags);
        } else {
            std::vector<std::vector<cv::Point2f>> corners;
            std::vector<std::vector<int>> ids;
            for (const BoardView& v : views) {
                corners.push_back(v.corners);
                ids.push_back(v.ids);
            }
            rms = cv::aruco::calibrateCameraCharuco(corners, ids, charuco_, imageSize, cameraMatrix, distortion,
                                                    cv::noArray(), cv::noArray(), kCalibrationFlags);
        }
    } catch (const cv::Exception& e) {
        throw InputError("the " + std::to_string(views.size()) + " views do not determine the lens (OpenCV: " + e.err +
                         "); show the board at more angles and distances");
    }
    if (!std::isfinite(rms) || cameraMatrix.empty() || !(cameraMatrix.at<double>(0, 0) > 0.0) ||
        !(cameraMatrix.at<double>(1, 1) > 0.0))
        throw InputError(
            "the " + std::to_string(views.size()) +
            " views do not determine the lens (no finite focal length fits them); show the board at more angles");
    LensFit fit;
    CameraIntrinsics& k = fit.intrinsics;
    k.imageSize = {imageSize.width, imageSize.height};
    k.fx = cameraMatrix.at<double>(0, 0);
    k.fy = cameraMatrix.at<double>(1, 1);
    k.cx = cameraMatrix.at<double>(0, 2);
    k.cy = cameraMatrix.at<double>(1, 2);
    distortion = distortion.reshape(1, 1);
    for (int i = 0; i < 5 && i < distortion.cols; ++i)
        k.distortion[static_cast<std::size_t>(i)] = distortion.at<double>(0, i);
    fit.rmsPixels = rms;
    return fit;
}

}  // namespace arcomp
