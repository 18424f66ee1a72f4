// The tests' child runner: a child that does not finish (as one that
// inherited a lock held at the fork) is killed and run once more, and one
// stuck both times is reported, not waited for.

#include "tests/support/ChildProcess.hpp"
#include "tests/support/TempDir.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>

using arcomp::test::ChildLimits;
using arcomp::test::runForked;

namespace {

TEST(ChildProcess, aChildStuckOnceIsRunAgain) {
    arcomp::test::TempDir dir;
    const std::filesystem::path tried = dir.path() / "tried";
    const auto r = runForked(
        [&] {
            if (!std::filesystem::exists(tried)) {
                std::ofstream(tried) << "once";
                std::this_thread::sleep_for(std::chrono::seconds(30));
            }
            std::puts("second try");
            return 3;
        },
        ChildLimits{.fileSizeLimit = std::nullopt, .seconds = std::chrono::seconds(1)});
    EXPECT_TRUE(r.exited);
    EXPECT_EQ(r.code, 3);
    EXPECT_NE(r.output.find("second try"), std::string::npos) << r.output;
}

TEST(ChildProcess, aChildStuckTwiceIsReportedKilled) {
    const auto r = runForked(
        [] {
            std::this_thread::sleep_for(std::chrono::seconds(30));
            return 0;
        },
        ChildLimits{.fileSizeLimit = std::nullopt, .seconds = std::chrono::seconds(1)});
    EXPECT_FALSE(r.exited);
    EXPECT_TRUE(r.crashed());
    EXPECT_NE(r.output.find("did not finish in 1 s, twice"), std::string::npos) << r.output;
}

}  // namespace
