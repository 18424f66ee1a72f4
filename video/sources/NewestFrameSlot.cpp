#include "video/sources/NewestFrameSlot.hpp"

#include <utility>

namespace arcomp {

void NewestFrameSlot::put(Frame frame) {
    std::optional<Frame> replaced;
    {
        std::lock_guard lock(mutex_);
        replaced.swap(frame_);
        frame_.emplace(std::move(frame));
    }
    if (replaced) drops_.fetch_add(1, std::memory_order_relaxed);
    // `replaced` releases its pixels here, outside the lock.
}

std::optional<Frame> NewestFrameSlot::take() {
    std::optional<Frame> out;
    std::lock_guard lock(mutex_);
    out.swap(frame_);
    return out;
}

}  // namespace arcomp
