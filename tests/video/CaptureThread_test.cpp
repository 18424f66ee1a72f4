#include "video/sources/CaptureThread.hpp"
#include "video/sources/TestPatternSource.hpp"

#include <gtest/gtest.h>

#include <thread>

using namespace arcomp;

TEST(CaptureThread, slowConsumerSeesNewestFramesAndCountsDrops) {
    CaptureThread src("pattern", [] {
        return std::make_unique<TestPatternSource>(
            TestPatternOptions{.width = 32, .height = 32, .fps = 1000, .paced = false});
    });
    src.open();
    std::uint64_t lastSeq = 0;
    int got = 0;
    for (int i = 0; i < 200 && got < 3; ++i) {
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
        if (auto f = src.newest()) {
            if (got > 0) {
                EXPECT_GT(f->sequence, lastSeq);
            }
            lastSeq = f->sequence;
            ++got;
        }
    }
    src.close();
    EXPECT_EQ(got, 3);
    EXPECT_GT(src.drops(), 0u);  // the producer outran the consumer: stale frames dropped, not queued
}
