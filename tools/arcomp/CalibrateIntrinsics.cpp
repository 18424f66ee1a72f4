// arcomp calibrate intrinsics <video|image-folder|camera> --board chessboard|charuco --cols N --rows M
//     --square S [--marker-length L] [--dictionary NAME] --out F [--max-views K]:
// the lens, from views of a flat printed board (CalibrationBoard.hpp): focal
// lengths, principal point and distortion, by cv::calibrateCamera. From a
// video or a folder of images it searches up to K frames spread evenly
// through it; from a V4L2 camera (/dev/video*, /dev/v4l/by-id/...) it takes a
// view every half second while someone moves the board, until it has K.
// Prints the reprojection error and how many views it used, and writes a
// lens file (runtime/config/CameraFile.hpp) that `calibrate floor --intrinsics` reads.

#include "runtime/config/CameraFile.hpp"
#include "tools/arcomp/CalibrationBoard.hpp"
#include "tools/cli/Command.hpp"
#include "video/sources/OpenSource.hpp"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/videoio.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <memory>
#include <numbers>
#include <thread>

namespace arcomp {
namespace {

// Fewer views leave focal length, principal point and distortion trading
// off against each other.
constexpr int kMinViews = 5;
// A board this small in the picture (the share of the image inside its
// corners) measures the lens only near one spot, and its corners are too
// close together to locate well.
constexpr int kMinCoveragePercent = 2;

struct IntrinsicsOptions {
    std::string input;
    std::string board;
    int cols = 0, rows = 0;
    double square = 0.0;
    double markerLength = 0.0;
    std::string dictionary;  // charuco: DICT_4X4_50 when not given
    std::string out;
    int maxViews = 40;
};

// Called with each frame to search and where it came from ("frame 12 of 300",
// a file name); returns false when it wants no more.
using FrameVisitor = std::function<bool(const cv::Mat& frame, const std::string& where)>;

// `count` indices spread evenly over [0, total), each from the middle of its share.
std::vector<int> spread(int total, int count) {
    std::vector<int> picked;
    if (total <= count) {
        for (int i = 0; i < total; ++i) picked.push_back(i);
        return picked;
    }
    for (int i = 0; i < count; ++i)
        picked.push_back(static_cast<int>((static_cast<long long>(2 * i + 1) * total) / (2LL * count)));
    return picked;
}

bool isImageFile(const std::filesystem::path& p) {
    std::string ext = p.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext == ".png" || ext == ".jpg" || ext == ".jpeg" || ext == ".bmp" || ext == ".tif" || ext == ".tiff";
}

int visitFolder(const std::filesystem::path& folder, int maxFrames, const FrameVisitor& visit) {
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(folder))
        if (entry.is_regular_file() && isImageFile(entry.path())) files.push_back(entry.path());
    if (files.empty()) throw InputError(folder.string(), "", "no images in this folder (.png, .jpg, .bmp, .tif)");
    std::sort(files.begin(), files.end());
    int visited = 0;
    for (int i : spread(static_cast<int>(files.size()), maxFrames)) {
        const std::filesystem::path& file = files[static_cast<std::size_t>(i)];
        const cv::Mat image = cv::imread(file.string(), cv::IMREAD_COLOR);
        if (image.empty()) throw InputError(file.string(), "", "not an image OpenCV can read");
        ++visited;
        if (!visit(image, file.filename().string())) break;
    }
    return visited;
}

int visitVideo(const std::string& file, int maxFrames, const FrameVisitor& visit) {
    cv::VideoCapture video(file);
    if (!video.isOpened()) throw InputError(file, "", "neither an image nor a video OpenCV can open");
    int total = static_cast<int>(video.get(cv::CAP_PROP_FRAME_COUNT));
    if (total <= 0) {
        // Some containers do not say: count, then start again.
        total = 0;
        while (video.grab()) ++total;
        video.release();
        video.open(file);
    }
    if (total <= 0) throw InputError(file, "", "a video without frames");
    const std::vector<int> picked = spread(total, maxFrames);
    int visited = 0, index = 0;
    cv::Mat frame;
    for (int wanted : picked) {
        // Read straight through: seeking in compressed video lands on key frames only.
        for (; index < wanted; ++index)
            if (!video.grab()) {
                std::fprintf(stderr, "arcomp calibrate intrinsics: %s ended after %d frames, before the %d it claims\n",
                             file.c_str(), index, total);
                return visited;
            }
        ++index;
        if (!video.read(frame) || frame.empty())
            throw InputError(file, "frame " + std::to_string(wanted + 1) + " of " + std::to_string(total),
                             "cannot be decoded");
        ++visited;
        if (!visit(frame, "frame " + std::to_string(wanted + 1) + " of " + std::to_string(total))) break;
    }
    return visited;
}

// A live camera: a frame every half second, so that the person holding the
// board has moved it between views, for at most two minutes.
int visitCamera(const std::string& device, const FrameVisitor& visit) {
    SourceSpec spec;
    spec.kind = SourceKind::V4l2;
    spec.path = device;
    std::unique_ptr<FrameSource> source = openSource(spec);
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    auto lastFrame = start, lastLook = start - std::chrono::seconds(1);
    int visited = 0;
    std::fprintf(stderr, "%s: move the board through the picture: near and far, tilted each way, into the corners\n",
                 device.c_str());
    while (Clock::now() - start < std::chrono::minutes(2)) {
        if (std::optional<Frame> f = source->newest()) {
            lastFrame = Clock::now();
            if (lastFrame - lastLook < std::chrono::milliseconds(500)) continue;
            lastLook = lastFrame;
            ++visited;
            if (!visit(f->image, "frame " + std::to_string(f->sequence))) break;
            continue;
        }
        const SourceState state = source->state();
        if (isLost(state.status) || Clock::now() - lastFrame > std::chrono::seconds(10)) {
            source->close();
            throw InputError(device, "",
                             "no frames from the camera (" + std::string(sourceStatusName(state.status)) +
                                 (state.reason.empty() ? "" : ": " + state.reason) + ")");
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    source->close();
    return visited;
}

bool isCamera(const std::string& input) {
    return input.rfind("/dev/", 0) == 0 && std::filesystem::is_character_file(input);
}

// The same view as the last kept one, give or take: a camera on a board
// held still would otherwise fill every slot with one view.
bool nearlySame(const BoardView& a, const BoardView& b, cv::Size size) {
    double moved = 0.0;
    int common = 0;
    for (std::size_t i = 0; i < a.ids.size(); ++i)
        for (std::size_t j = 0; j < b.ids.size(); ++j)
            if (a.ids[i] == b.ids[j]) {
                moved += cv::norm(a.corners[i] - b.corners[j]);
                ++common;
            }
    return common > 0 && moved / common < 0.02 * std::hypot(size.width, size.height);
}

int calibrateIntrinsics(const IntrinsicsOptions& o) {
    BoardSpec spec;
    if (o.board == "chessboard")
        spec.kind = BoardKind::Chessboard;
    else if (o.board == "charuco")
        spec.kind = BoardKind::Charuco;
    else
        throw InputError("--board " + o.board + ": expected chessboard or charuco");
    spec.cols = o.cols;
    spec.rows = o.rows;
    spec.square = o.square;
    if (spec.kind == BoardKind::Chessboard && (o.markerLength != 0.0 || !o.dictionary.empty()))
        throw InputError("--marker-length and --dictionary describe a ChArUco board's markers; a chessboard has none");
    spec.markerLength = o.markerLength;
    if (!o.dictionary.empty()) spec.dictionary = o.dictionary;
    const CalibrationBoard board(spec);

    const bool camera = isCamera(o.input);
    if (!camera && !std::filesystem::exists(o.input)) throw InputError(o.input, "", "no such file, folder or camera");

    std::vector<BoardView> views;
    cv::Size size;
    int found = 0, small = 0;
    double largestSmall = 0.0;
    const FrameVisitor visit = [&](const cv::Mat& frame, const std::string& where) {
        if (size.empty()) size = frame.size();
        if (frame.size() != size)
            throw InputError(o.input, where,
                             std::to_string(frame.cols) + "x" + std::to_string(frame.rows) +
                                 ", but the first frame is " + std::to_string(size.width) + "x" +
                                 std::to_string(size.height) + "; calibrate one camera at one resolution");
        std::optional<BoardView> view = board.find(frame);
        if (!view) return true;
        ++found;
        if (100.0 * view->coverage < kMinCoveragePercent) {
            ++small;
            largestSmall = std::max(largestSmall, view->coverage);
            return true;
        }
        if (camera && !views.empty() && nearlySame(*view, views.back(), size)) return true;
        views.push_back(std::move(*view));
        if (camera) std::fprintf(stderr, "view %zu of %d\n", views.size(), o.maxViews);
        return static_cast<int>(views.size()) < o.maxViews;
    };
    int frames = 0;
    if (camera)
        frames = visitCamera(o.input, visit);
    else if (std::filesystem::is_directory(o.input))
        frames = visitFolder(o.input, o.maxViews, visit);
    else if (const cv::Mat image = cv::imread(o.input, cv::IMREAD_COLOR); !image.empty()) {
        frames = 1;  // one picture: too few views, but the message says so and why
        visit(image, "");
    } else
        frames = visitVideo(o.input, o.maxViews, visit);

    const std::string minCoverage = "under " + std::to_string(kMinCoveragePercent) + "% of the image";
    if (found == 0)
        throw InputError(o.input, "",
                         "no " + board.describe() + " found in any of its " + std::to_string(frames) +
                             " frames searched; check --board, --cols and --rows against the print "
                             "(squares, not inner corners) and that the whole board is in the picture");
    if (views.empty()) {
        char largest[32];
        std::snprintf(largest, sizeof largest, "%.1f%%", 100.0 * largestSmall);
        throw InputError(o.input, "",
                         "the board covers " + minCoverage + " in every view where it was found (" +
                             std::to_string(found) + " views, the largest " + largest + "); hold it nearer the camera");
    }
    if (static_cast<int>(views.size()) < kMinViews)
        throw InputError(
            o.input, "",
            "the board is usable in " + std::to_string(views.size()) + " views of the " + std::to_string(frames) +
                " frames searched" +
                (small ? " (" + std::to_string(small) + " more where it covers " + minCoverage + ")" : "") +
                "; the lens needs at least " + std::to_string(kMinViews) +
                ": show the board at more angles and distances");

    const LensFit fit = board.calibrate(views, size);
    const CameraIntrinsics& k = fit.intrinsics;
    char note[256];
    std::snprintf(note, sizeof note, "lens from %zu views of a %s in %s: %.2f px RMS", views.size(),
                  board.describe().c_str(), std::filesystem::path(o.input).filename().c_str(), fit.rmsPixels);
    writeLensFile(o.out, k, note);

    std::printf("intrinsics: %zu views of %d frames searched", views.size(), frames);
    if (frames > found) std::printf(", %d without the board", frames - found);
    if (small) std::printf(", %d where it covers %s", small, minCoverage.c_str());
    std::printf("; reprojection %.2f px RMS\n", fit.rmsPixels);
    std::printf("lens: fx %.2f, fy %.2f px; principal point %.2f, %.2f px; distortion k1 %.4f, k2 %.4f, p1 %.5f, p2 "
                "%.5f, k3 %g\n",
                k.fx, k.fy, k.cx, k.cy, k.distortion[0], k.distortion[1], k.distortion[2], k.distortion[3],
                k.distortion[4]);
    const double fovy = 2.0 * std::atan(0.5 * size.height / k.fy) * 180.0 / std::numbers::pi;
    std::printf("vertical field of view %.1f degrees at %dx%d\n", fovy, size.width, size.height);
    if (fit.rmsPixels > 1.0)
        std::fprintf(stderr,
                     "arcomp calibrate intrinsics: %.2f px RMS is high for a flat board seen sharply: check that the "
                     "board is flat, the views are not blurred, and --cols/--rows match the print\n",
                     fit.rmsPixels);
    std::printf("wrote %s\n", o.out.c_str());
    return kExitOk;
}

const bool registered = registerCalibration(
    {"intrinsics", "The lens (focal length, principal point, distortion) from views of a printed board",
     [](CommandLine& line) {
         auto o = std::make_shared<IntrinsicsOptions>();
         line.option("input", o->input, "A video, a folder of images, or a V4L2 camera (/dev/video0)").required();
         line.option("--board", o->board, "chessboard or charuco").required();
         line.option("--cols", o->cols, "Squares across the board (not inner corners)").required();
         line.option("--rows", o->rows, "Squares down the board").required();
         line.option("--square", o->square, "A square's edge in metres, as printed").required();
         line.option("--marker-length", o->markerLength, "charuco: a marker's edge in metres");
         line.option("--dictionary", o->dictionary, "charuco: the markers' ArUco dictionary (DICT_4X4_50)");
         line.option("--out", o->out, "The lens file to write").required();
         line.option("--max-views", o->maxViews, "At most this many views (frames searched in a video or folder)")
             .range(kMinViews, 1000)
             .showDefault();
         return [o] { return calibrateIntrinsics(*o); };
     }});

}  // namespace
}  // namespace arcomp
