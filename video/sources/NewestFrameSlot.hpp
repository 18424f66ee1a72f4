#pragma once
// A single-slot mailbox between a capture thread and the renderer. put()
// overwrites a frame nobody took (and counts it as dropped); take() returns
// the frame if it is new and never waits for the producer. There is no queue,
// so a slow consumer always sees the newest frame, never a late one.
//
//   slot.put(std::move(frame));            // capture thread
//   if (auto f = slot.take()) draw(*f);    // render loop

#include "video/pixels/Frame.hpp"

#include <atomic>
#include <cstdint>
#include <mutex>
#include <optional>

namespace arcomp {

class NewestFrameSlot {
public:
    void put(Frame frame);
    std::optional<Frame> take();
    std::uint64_t drops() const { return drops_.load(std::memory_order_relaxed); }

private:
    // The lock only guards a swap of cv::Mat headers (refcounted, no pixel
    // copy), so the consumer waits at most for a few pointer moves.
    std::mutex mutex_;
    std::optional<Frame> frame_;
    std::atomic<std::uint64_t> drops_{0};
};

}  // namespace arcomp
