// The station's front thread: one thread for its whole life, one job at a
// time, what a job throws rethrown by finish() on the owner's thread.

#include "runtime/station/WorkerThread.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <thread>

using namespace arcomp;

TEST(WorkerThread, runsEveryJobOnOneThreadThatIsNotTheCallers) {
    WorkerThread worker;
    std::thread::id first, each;
    bool sameThread = true;
    for (int i = 0; i < 50; ++i) {
        worker.start([&] {
            each = std::this_thread::get_id();
            if (i == 0) first = each;
            sameThread = sameThread && each == first;
        });
        worker.finish();
    }
    EXPECT_TRUE(sameThread);
    EXPECT_NE(first, std::this_thread::get_id());
}

TEST(WorkerThread, finishWaitsForTheJobAndRethrowsWhatItThrewOnce) {
    WorkerThread worker;
    int result = 0;
    worker.start([&] { result = 42; });
    EXPECT_TRUE(worker.busy());
    worker.finish();
    EXPECT_FALSE(worker.busy());
    EXPECT_EQ(result, 42);

    worker.start([] { throw std::runtime_error("vtest.avi: frame 12 is damaged"); });
    worker.wait();  // waits, keeps the outcome
    EXPECT_TRUE(worker.busy());
    EXPECT_THROW(worker.finish(), std::runtime_error);
    EXPECT_NO_THROW(worker.finish());   // nothing in hand any more
    worker.start([&] { result = 7; });  // the thread goes on after a job threw
    worker.finish();
    EXPECT_EQ(result, 7);
}

TEST(WorkerThread, aSecondJobBeforeTheFirstIsFinishedIsRefused) {
    WorkerThread worker;
    worker.start([] {});
    EXPECT_THROW(worker.start([] {}), std::logic_error);
    worker.finish();
}

TEST(WorkerThread, destructionWaitsForTheJobInHand) {
    bool ran = false;
    {
        WorkerThread worker;
        worker.start([&] { ran = true; });
    }
    EXPECT_TRUE(ran);
}
