#include "graph/points/WorkerPool.hpp"

#include <gtest/gtest.h>

#include <array>
#include <atomic>
#include <set>

using namespace arcomp;

// Every worker runs every job once, on its own thread, and run() returns
// only when all are done: the threads live across jobs.
TEST(WorkerPool, eachJobRunsOnceOnEveryWorkerAndTheThreadsStay) {
    WorkerPool pool(3);
    ASSERT_EQ(pool.size(), 3u);
    std::set<std::thread::id> firstThreads;
    for (int job = 0; job < 200; ++job) {
        std::array<std::atomic<int>, 3> calls{};
        std::array<std::thread::id, 3> threads{};
        auto work = [&](std::size_t worker) {
            calls[worker].fetch_add(1);
            threads[worker] = std::this_thread::get_id();
        };
        pool.run(work);
        for (std::size_t w = 0; w < 3; ++w) ASSERT_EQ(calls[w].load(), 1) << "job " << job << " worker " << w;
        EXPECT_EQ(threads[0], std::this_thread::get_id());
        const std::set<std::thread::id> now(threads.begin(), threads.end());
        EXPECT_EQ(now.size(), 3u);
        if (job == 0) firstThreads = now;
        EXPECT_EQ(now, firstThreads) << "job " << job;
    }
}

TEST(WorkerPool, oneWorkerRunsOnTheCaller) {
    WorkerPool pool(1);
    std::thread::id ran;
    auto work = [&](std::size_t worker) {
        EXPECT_EQ(worker, 0u);
        ran = std::this_thread::get_id();
    };
    pool.run(work);
    EXPECT_EQ(ran, std::this_thread::get_id());
}
