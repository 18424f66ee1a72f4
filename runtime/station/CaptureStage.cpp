#include "runtime/station/CaptureStage.hpp"

#include "video/pixels/VideoError.hpp"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <thread>

namespace arcomp {

StationInput StationInput::fromReplay(std::unique_ptr<FrameGrabber> g, double fps) {
    StationInput in;
    in.replay = std::move(g);
    in.fps = fps;
    return in;
}

StationInput StationInput::fromLive(std::unique_ptr<FrameSource> s, double fps) {
    StationInput in;
    in.live = std::move(s);
    in.fps = fps;
    return in;
}

CaptureStage::CaptureStage(StationInput input) : input_(std::move(input)) {
    if (input_.pending) {
        std::optional<Frame> first = std::move(input_.pending);
        input_.pending.reset();
        if (input_.replay) {
            replayState_ = {SourceStatus::Streaming, ""};
            videoSeconds_ = std::chrono::duration<double>(first->timestamp).count();
        }
        firstPending_ = accept(std::move(first));
    } else {
        firstPending_ = grab();
    }
    if (!firstPending_) throw VideoError(name(), "first frame", "no frame to start from");
}

bool CaptureStage::next() {
    if (firstPending_) {
        firstPending_ = false;
        newFrame_ = true;
        return true;
    }
    return grab();
}

double CaptureStage::seconds() const {
    if (input_.replay) return videoSeconds_;
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - clockStart_).count();
}

double CaptureStage::frameSeconds() const {
    if (input_.replay) return videoSeconds_;
    return std::max(0.0, std::chrono::duration<double>(liveCaptured_ - clockStart_).count());
}

bool CaptureStage::grab() {
    std::optional<Frame> f;
    if (input_.replay) {
        GrabResult r = input_.replay->grab();
        replayState_ = r.state;
        if (!r.frame) {
            end_ = r.state.reason;
            return false;
        }
        replayState_.status = SourceStatus::Streaming;
        f = std::move(r.frame);
        videoSeconds_ = std::chrono::duration<double>(f->timestamp).count();
    } else {
        f = input_.live->newest();
        // A camera takes a moment to deliver its first frame; the station
        // needs one to know its size.
        for (int wait = 0; !f && frame_.empty() && wait < 600; ++wait) {
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
            f = input_.live->newest();
        }
    }
    return accept(std::move(f));
}

bool CaptureStage::accept(std::optional<Frame> f) {
    newFrame_ = f.has_value();
    if (f && !input_.replay) {
        // A source that does not stamp its frames is taken as capturing now;
        // a fallback source's frames may not come in order with the last
        // camera frame, and animation time must not run backwards.
        const auto captured =
            f->captured == std::chrono::steady_clock::time_point{} ? std::chrono::steady_clock::now() : f->captured;
        liveCaptured_ = std::max(liveCaptured_, captured);
    }
    if (f) {
        // A new image each frame, never one written in place: a pipelined
        // station still composites the previous one.
        if (!frame_.empty() && f->image.size() != frame_.size()) {
            cv::Mat scaled;
            cv::resize(f->image, scaled, frame_.size(), 0, 0, cv::INTER_AREA);  // a fallback of another size
            frame_ = scaled;
        } else {
            frame_ = f->image;
        }
        if (!frame_.isContinuous()) frame_ = frame_.clone();
        if (lens_) lens_->apply(frame_);
        raw_ = std::move(f);
    }
    return !frame_.empty();
}

StationInput CaptureStage::release(bool currentUnshown) {
    if ((currentUnshown || firstPending_) && raw_) input_.pending = std::move(raw_);
    raw_.reset();
    return std::move(input_);
}

void CaptureStage::undistortWith(LensUndistortion lens) {
    lens_ = std::move(lens);
    if (!frame_.empty()) lens_->apply(frame_);
}

std::string CaptureStage::name() const {
    if (input_.replay) return input_.replay->name();
    return input_.live ? input_.live->name() : std::string();
}

SourceState CaptureStage::state() const {
    if (input_.live) return input_.live->state();
    return replayState_;
}

std::uint64_t CaptureStage::drops() const { return input_.live ? input_.live->drops() : 0; }

}  // namespace arcomp
