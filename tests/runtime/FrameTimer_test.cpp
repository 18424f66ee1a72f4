// The cost model's timer on both context kinds: timer queries where the
// driver has them (desktop GL 3.3; ES only with GL_EXT_disjoint_timer_query),
// otherwise the wall clock around glFinish, never a failure.

#include "runtime/gl/FrameTimer.hpp"
#include "runtime/gl/GlContext.hpp"
#include "runtime/gl/RenderTarget.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstring>
#include <thread>

using namespace arcomp;

namespace {

bool esHasTimerExtension() {
    GLint count = 0;
    gl::glGetIntegerv(GL_NUM_EXTENSIONS, &count);
    for (GLint i = 0; i < count; ++i)
        if (std::strcmp(reinterpret_cast<const char*>(gl::glGetStringi(GL_EXTENSIONS, static_cast<GLuint>(i))),
                        "GL_EXT_disjoint_timer_query") == 0)
            return true;
    return false;
}

class FrameTimerOnEachApi : public ::testing::TestWithParam<GlRequest> {};

}  // namespace

TEST_P(FrameTimerOnEachApi, usesQueriesOnlyWhereTheDriverHasThemAndTimesTheWork) {
    auto context = HeadlessContext::create(GetParam());
    const bool expectQueries = context->api() == GlApiKind::Gl33 ? true : esHasTimerExtension();
    EXPECT_EQ(hasTimerQueries(), expectQueries);

    FrameTimer timer(TimerMode::Query);
    EXPECT_EQ(timer.usesQueries(), expectQueries);
    EXPECT_EQ(timer.method(), expectQueries ? "gl_time_elapsed" : "wall_glfinish");
    FrameTimer finish(TimerMode::Finish);
    EXPECT_FALSE(finish.usesQueries());

    RenderTarget target({512, 512});
    target.bind();
    for (FrameTimer* t : {&timer, &finish}) {
        t->begin();
        for (int i = 0; i < 20; ++i) {
            gl::glClearColor(0.1f * static_cast<float>(i % 10), 0.2f, 0.3f, 1.0f);
            gl::glClear(GL_COLOR_BUFFER_BIT);
        }
        const double ms = t->end();
        EXPECT_TRUE(std::isfinite(ms));
        EXPECT_GE(ms, 0.0);
    }
}

// A wait inside the frame is a viewer's time but not the device's: the
// wall clock counts it, the process's CPU time does not.
TEST_P(FrameTimerOnEachApi, processCpuModeLeavesOutTimeTheProcessDidNotRun) {
    auto context = HeadlessContext::create(GetParam());
    FrameTimer cpu(TimerMode::ProcessCpu), wall(TimerMode::Finish);
    EXPECT_FALSE(cpu.usesQueries());
    EXPECT_EQ(cpu.method(), "process_cpu_glfinish");
    EXPECT_EQ(wall.method(), "wall_glfinish");
    const auto frameWithAWait = [](FrameTimer& t) {
        t.begin();
        std::this_thread::sleep_for(std::chrono::milliseconds(200));
        return t.end();
    };
    EXPECT_GE(frameWithAWait(wall), 200.0);
    const double cpuMs = frameWithAWait(cpu);
    EXPECT_GE(cpuMs, 0.0);
    EXPECT_LT(cpuMs, 100.0);
}

INSTANTIATE_TEST_SUITE_P(Apis, FrameTimerOnEachApi, ::testing::Values(GlRequest::Gl33, GlRequest::Es3),
                         [](const auto& info) { return info.param == GlRequest::Gl33 ? "gl33" : "es3"; });
