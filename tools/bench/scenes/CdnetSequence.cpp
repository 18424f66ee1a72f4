#include "tools/bench/scenes/CdnetSequence.hpp"

#include "video/pixels/VideoError.hpp"

#include <opencv2/imgcodecs.hpp>

#include <cstdio>
#include <fstream>

namespace arcomp {

namespace fs = std::filesystem;

namespace {

fs::path numbered(const fs::path& folder, const char* prefix, int index, const char* extension) {
    char name[64];
    std::snprintf(name, sizeof name, "%s%06d.%s", prefix, index, extension);
    return folder / name;
}

cv::Mat readImage(const fs::path& dir, const fs::path& file, int mode, const char* what) {
    cv::Mat image = cv::imread(file.string(), mode);
    if (image.empty())
        throw VideoError(dir.string(), fs::relative(file, dir).string(), std::string("cannot read ") + what);
    return image;
}

}  // namespace

cv::Mat CdnetSequence::frame(int index) const {
    return readImage(dir, numbered(dir / "input", "in", index, "jpg"), cv::IMREAD_COLOR, "the frame");
}

cv::Mat CdnetSequence::labels(int index) const {
    return readImage(dir, numbered(dir / "groundtruth", "gt", index, "png"), cv::IMREAD_GRAYSCALE, "the labels");
}

CdnetSequence openCdnetSequence(const fs::path& dir) {
    CdnetSequence seq;
    seq.dir = dir;
    if (!fs::is_directory(dir))
        throw VideoError(dir.string(), "",
                         "not a folder; expected a CDnet sequence with input/, groundtruth/ and temporalROI.txt");
    if (!fs::is_directory(dir / "input"))
        throw VideoError(dir.string(), "input/", "folder missing; expected input/in000001.jpg ...");
    if (!fs::is_directory(dir / "groundtruth"))
        throw VideoError(dir.string(), "groundtruth/", "folder missing; expected groundtruth/gt000001.png ...");
    while (fs::exists(numbered(dir / "input", "in", seq.frameCount + 1, "jpg"))) ++seq.frameCount;
    if (seq.frameCount == 0) throw VideoError(dir.string(), "input/", "no frames; expected input/in000001.jpg ...");

    std::ifstream roiText(dir / "temporalROI.txt");
    if (!roiText)
        throw VideoError(dir.string(), "temporalROI.txt", "file missing; expected two frame numbers \"first last\"");
    if (!(roiText >> seq.firstScored >> seq.lastScored) || seq.firstScored < 1 || seq.lastScored < seq.firstScored)
        throw VideoError(dir.string(), "temporalROI.txt",
                         "expected two frame numbers \"first last\" with 1 <= first <= last");
    seq.lastScored = std::min(seq.lastScored, seq.frameCount);
    if (seq.lastScored < seq.firstScored)
        throw VideoError(dir.string(), "temporalROI.txt",
                         "the scored frames lie beyond the " + std::to_string(seq.frameCount) + " input frames");

    const cv::Mat first = seq.frame(1);
    if (fs::exists(dir / "ROI.bmp")) {
        seq.roi = readImage(dir, dir / "ROI.bmp", cv::IMREAD_GRAYSCALE, "the region of interest");
        if (seq.roi.size() != first.size())
            throw VideoError(dir.string(), "ROI.bmp",
                             "expected the size of the frames, " + std::to_string(first.cols) + "x" +
                                 std::to_string(first.rows));
    } else {
        seq.roi = cv::Mat(first.size(), CV_8UC1, cv::Scalar(255));
    }
    return seq;
}

}  // namespace arcomp
