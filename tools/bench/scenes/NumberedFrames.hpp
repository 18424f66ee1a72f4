#pragma once
// Frames that carry their own number, for the tests and benchmarks that
// must know which frame came out of an encoder, a network and a decoder,
// and in what order: 12 bits as 16-pixel squares in the top-left corner,
// each bit twice (white over black, then black over white) so that a
// square the encoder smeared reads as no number rather than a wrong one.
// Behind them a picture that changes each frame, as a composite does.
//
//   const cv::Mat f = numberedFrame(41, {320, 240});
//   assert(frameNumberOf(f) == 41);

#include <opencv2/core.hpp>

#include <filesystem>

namespace arcomp {

inline constexpr int kNumberBits = 12;

cv::Mat numberedFrame(int index, cv::Size size);

// The number in a BGR frame; -1 when a square is neither clearly white nor
// clearly black against its twin.
int frameNumberOf(const cv::Mat& bgr);

// Frames 0 .. count-1 as an MJPEG file, a replay's input.
std::filesystem::path writeNumberedVideo(const std::filesystem::path& file, int count, cv::Size size,
                                         double fps = 25.0);

}  // namespace arcomp
