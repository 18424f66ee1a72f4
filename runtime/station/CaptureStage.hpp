#pragma once
// The frame's first stage: the video input. Replay pulls every frame in
// order, with no thread and no drops, so the same file gives the same
// frames; live takes the camera's newest frame and keeps the last one when
// the camera has nothing new. The first frame fixes the station's size: a
// frame of another size (a fallback source) is scaled to it.
//
//   CaptureStage capture(StationInput::fromReplay(std::move(grabber), 25.0));  // reads the first frame
//   while (capture.next()) use(capture.image(), capture.seconds());

#include "video/sources/FrameGrabber.hpp"
#include "video/sources/FrameSource.hpp"
#include "video/sources/LensUndistortion.hpp"

#include <glm/glm.hpp>
#include <opencv2/core/mat.hpp>

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

namespace arcomp {

// Where frames come from: a grabber pulled frame by frame (replay: every
// frame, in order) or a live source whose newest frame is taken.
struct StationInput {
    std::unique_ptr<FrameGrabber> replay;
    std::unique_ptr<FrameSource> live;
    double fps = 25.0;  // for the video file output
    // A frame taken from the input but never shown (a pipelined station
    // reads one frame ahead): the next CaptureStage starts with it, so a
    // reload loses no frame of a replay.
    std::optional<Frame> pending;

    static StationInput fromReplay(std::unique_ptr<FrameGrabber> g, double fps);
    static StationInput fromLive(std::unique_ptr<FrameSource> s, double fps);
};

class CaptureStage {
public:
    // Reads the first frame (a live source gets up to 3 s to deliver it);
    // throws VideoError when there is none.
    explicit CaptureStage(StationInput input);

    // The next frame (the first one, read by the constructor, comes first);
    // false when a replay input has ended: end() says why.
    bool next();
    const cv::Mat& image() const { return frame_; }  // BGR, continuous
    bool newFrame() const { return newFrame_; }      // live: false when the camera had nothing new
    glm::ivec2 size() const { return {frame_.cols, frame_.rows}; }
    double fps() const { return input_.fps; }
    // Frames pulled one by one from a file (true) or taken as a live camera
    // delivers them.
    bool isReplay() const { return input_.replay != nullptr; }

    // The current frame's time, which movers and the gaze track run on: the
    // video's own timestamp in replay (deterministic), the wall time since
    // clockStart() live. A reloaded live station keeps the previous start.
    double seconds() const;
    // The time of the frame on screen, which model animations run on: as
    // seconds() in replay; live, when the camera captured that frame, on the
    // same clock. So the CG moves with the video it is composited into and
    // holds still while the camera has nothing new.
    double frameSeconds() const;
    void setClockStart(std::chrono::steady_clock::time_point start) { clockStart_ = start; }
    std::chrono::steady_clock::time_point clockStart() const { return clockStart_; }

    // The input as an operator sees it.
    std::string name() const;
    SourceState state() const;
    std::uint64_t drops() const;
    // Why a replay ended ("end after 795 frames", a decoder error); empty while it runs.
    const std::string& end() const { return end_; }
    // From now on every frame (the current one included) is undistorted
    // before anyone sees it: a calibrated lens.
    void undistortWith(LensUndistortion lens);
    // The input, still open, for the next station after a config reload.
    // `currentUnshown`: the current frame was read ahead and never shown;
    // the next station shows it first.
    StationInput release(bool currentUnshown);

private:
    bool grab();
    bool accept(std::optional<Frame> f);

    StationInput input_;
    cv::Mat frame_;
    std::optional<Frame> raw_;  // the current frame as the input gave it, for release()
    std::optional<LensUndistortion> lens_;
    bool firstPending_ = false;
    bool newFrame_ = false;
    std::string end_;
    SourceState replayState_{SourceStatus::Opening, ""};
    std::chrono::steady_clock::time_point clockStart_ = std::chrono::steady_clock::now();
    double videoSeconds_ = 0.0;
    std::chrono::steady_clock::time_point liveCaptured_{};  // the newest live frame's capture time
};

}  // namespace arcomp
