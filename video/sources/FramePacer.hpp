#pragma once
// Holds a generated or decoded stream to its own clock: the frame stamped
// t is released at (first frame's wall time + t), as a camera would deliver
// it. Replay does not pace; it runs as fast as it can.
//
//   FramePacer pacer;
//   frame.captured = pacer.release(frame.timestamp);   // sleeps until due

#include <chrono>
#include <optional>
#include <thread>

namespace arcomp {

class FramePacer {
public:
    // Sleeps until the frame is due and returns when it was due (its
    // capture time). A frame already late is released at once.
    std::chrono::steady_clock::time_point release(std::chrono::nanoseconds timestamp) {
        const auto now = std::chrono::steady_clock::now();
        if (!origin_) origin_ = now - timestamp;
        const auto due = *origin_ + std::chrono::duration_cast<std::chrono::steady_clock::duration>(timestamp);
        if (due > now) std::this_thread::sleep_until(due);
        return due;
    }
    // After a seek or a loop the timeline restarts.
    void reset() { origin_.reset(); }

private:
    std::optional<std::chrono::steady_clock::time_point> origin_;
};

}  // namespace arcomp
