#pragma once
// A labelled video sequence in the CDnet 2014 layout (changedetection.net):
//
//   DIR/input/in000001.jpg ...       the frames, numbered from 1
//   DIR/groundtruth/gt000001.png ... one label image per frame (see MatteScore.hpp)
//   DIR/temporalROI.txt              "first last": the frames that are scored
//   DIR/ROI.bmp                      optional: 255 inside the scored region
//
//   const CdnetSequence seq = openCdnetSequence("data/video/busStation");
//   for (int i = 1; i <= seq.frameCount; ++i) {
//       cv::Mat frame = seq.frame(i);
//       if (seq.scored(i)) score.add(mask, seq.labels(i), seq.roi);
//   }
//
// Opening checks the layout and throws VideoError naming the folder and what
// is missing; frames are read one at a time, on demand.

#include <opencv2/core/mat.hpp>

#include <filesystem>

namespace arcomp {

struct CdnetSequence {
    std::filesystem::path dir;
    int frameCount = 0;   // input/in000001.jpg .. in<frameCount>.jpg all exist
    int firstScored = 1;  // temporalROI.txt, inclusive
    int lastScored = 0;
    cv::Mat roi;  // CV_8UC1, 255 = scored; all 255 when ROI.bmp is absent

    bool scored(int index) const { return index >= firstScored && index <= lastScored; }
    // CV_8UC3 BGR; throws VideoError when the file is missing or unreadable.
    cv::Mat frame(int index) const;
    // CV_8UC1 CDnet labels; throws VideoError when the file is missing or unreadable.
    cv::Mat labels(int index) const;
};

// Throws VideoError("<dir>", "<file>", "<what was expected>") for a missing
// folder, no input frames, a missing or malformed temporalROI.txt, or a
// ROI.bmp of the wrong size.
CdnetSequence openCdnetSequence(const std::filesystem::path& dir);

}  // namespace arcomp
