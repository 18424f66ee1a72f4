#pragma once
// Makes any FrameGrabber a non-blocking FrameSource: a thread calls grab()
// in a loop and puts each frame into a NewestFrameSlot.
//
//   CaptureThread cam("usb cam", [spec] { return std::make_unique<V4l2Source>(spec); });
//   cam.open();                        // the grabber is built on the capture thread
//   auto f = cam.newest();
//
// The grabber is built on the capture thread, so a constructor that throws
// (a missing file: VideoError) becomes state() Error with its message rather
// than an exception in the render loop. The loop ends when the grabber
// reports Ended or Error; Disconnected and Stalled keep it running, since
// the grabber reconnects on its own.

#include "video/sources/FrameGrabber.hpp"
#include "video/sources/FrameSource.hpp"
#include "video/sources/NewestFrameSlot.hpp"

#include <atomic>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>

namespace arcomp {

class CaptureThread : public FrameSource {
public:
    using GrabberFactory = std::function<std::unique_ptr<FrameGrabber>()>;

    CaptureThread(std::string name, GrabberFactory factory);
    ~CaptureThread() override;

    void open() override;
    std::optional<Frame> newest() override;
    SourceState state() const override;
    std::uint64_t drops() const override { return slot_.drops(); }
    void close() override;
    std::string name() const override { return name_; }

private:
    void run();
    void setState(SourceState state);

    std::string name_;
    GrabberFactory factory_;
    NewestFrameSlot slot_;
    mutable std::mutex stateMutex_;
    SourceState state_;
    std::atomic<bool> stop_{false};
    std::thread thread_;
};

}  // namespace arcomp
