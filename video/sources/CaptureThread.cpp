#include "video/sources/CaptureThread.hpp"
#include "graph/core/JoinText.hpp"

#include <spdlog/spdlog.h>

namespace arcomp {

CaptureThread::CaptureThread(std::string name, GrabberFactory factory)
    : name_(std::move(name)), factory_(std::move(factory)) {}

CaptureThread::~CaptureThread() { close(); }

void CaptureThread::open() {
    if (thread_.joinable()) return;
    stop_ = false;
    thread_ = std::thread([this] { run(); });
}

std::optional<Frame> CaptureThread::newest() { return slot_.take(); }

SourceState CaptureThread::state() const {
    std::lock_guard lock(stateMutex_);
    return state_;
}

void CaptureThread::close() {
    stop_ = true;
    if (thread_.joinable()) thread_.join();
}

void CaptureThread::setState(SourceState state) {
    std::lock_guard lock(stateMutex_);
    if (state.status != state_.status || state.reason != state_.reason) {
        if (state.status != SourceStatus::Streaming)
            spdlog::info(joinText("video source ", name_, ": ", sourceStatusName(state.status),
                                  state.reason.empty() ? "" : ": ", state.reason));
    }
    state_ = std::move(state);
}

void CaptureThread::run() {
    std::unique_ptr<FrameGrabber> grabber;
    try {
        grabber = factory_();
    } catch (const std::exception& e) {
        setState({SourceStatus::Error, e.what()});
        return;
    }
    while (!stop_) {
        GrabResult r;
        try {
            r = grabber->grab();
        } catch (const std::exception& e) {
            r.state = {SourceStatus::Error, e.what()};
        }
        if (r.frame) slot_.put(std::move(*r.frame));
        setState(std::move(r.state));
        const SourceStatus s = state().status;
        if (s == SourceStatus::Ended || s == SourceStatus::Error) break;
    }
    // The grabber is destroyed on the thread that used it: libcamera and
    // V4L2 teardown then happen outside any callback and off the render loop.
    grabber.reset();
}

}  // namespace arcomp
