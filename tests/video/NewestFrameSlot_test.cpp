#include "video/sources/NewestFrameSlot.hpp"

#include <gtest/gtest.h>

using namespace arcomp;

namespace {

Frame slotFrame(std::uint64_t seq, std::uint8_t grey) {
    return {cv::Mat(8, 8, CV_8UC3, cv::Scalar::all(grey)), {}, std::chrono::steady_clock::now(), seq, PixelFormat::Bgr};
}

}  // namespace

TEST(NewestFrameSlot, overwritesUntakenFramesAndCountsDrops) {
    NewestFrameSlot slot;
    slot.put(slotFrame(0, 1));
    slot.put(slotFrame(1, 2));
    slot.put(slotFrame(2, 3));
    std::optional<Frame> f = slot.take();
    ASSERT_TRUE(f);
    EXPECT_EQ(f->sequence, 2u);
    EXPECT_EQ(slot.drops(), 2u);
    EXPECT_FALSE(slot.take());  // each frame is handed out once
}
