#pragma once
// Deterministic generated video: colour bars, a circle and a square moving
// at known speeds, and the frame number printed large. Frame k is the same
// image on every run and machine, so tests and replays can compare pixels.
//
//   TestPatternSource pattern({.width = 1280, .height = 720, .fps = 60});
//   cv::Mat img = pattern.render(42);   // what grab() returns as frame 42

#include "video/sources/FrameGrabber.hpp"
#include "video/sources/FramePacer.hpp"

#include <cstdint>

namespace arcomp {

struct TestPatternOptions {
    int width = 640;
    int height = 480;
    double fps = 30.0;
    bool paced = true;  // false: grab() returns the next frame at once (replay, tests)
};

class TestPatternSource : public FrameGrabber {
public:
    explicit TestPatternSource(TestPatternOptions options);

    GrabResult grab() override;
    std::string name() const override;

    cv::Mat render(std::uint64_t index) const;
    // Where the moving circle's centre is in frame `index`; tests use it.
    cv::Point circleCentre(std::uint64_t index) const;

private:
    TestPatternOptions options_;
    std::uint64_t next_ = 0;
    FramePacer pacer_;
};

}  // namespace arcomp
