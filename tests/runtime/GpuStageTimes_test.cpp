// The station's stage times are read one frame late, so that timing never
// stalls the GPU: a stage reads what it took in the previous frame, and 0
// when the previous frame skipped it.

#include "runtime/gl/GlContext.hpp"
#include "runtime/gl/GpuStageTimes.hpp"
#include "runtime/gl/RenderTarget.hpp"

#include <gtest/gtest.h>

using namespace arcomp;

namespace {

class GpuStageTimesOnEachApi : public ::testing::TestWithParam<GlRequest> {};

void clearManyTimes() {
    for (int i = 0; i < 50; ++i) {
        gl::glClearColor(0.02f * static_cast<float>(i), 0.2f, 0.3f, 1.0f);
        gl::glClear(GL_COLOR_BUFFER_BIT);
    }
}

TEST_P(GpuStageTimesOnEachApi, aStageReadsThePreviousFramesTimeAndZeroWhenThatFrameSkippedIt) {
    auto context = HeadlessContext::create(GetParam());
    RenderTarget target({512, 512});
    target.bind();
    GpuStageTimes times(2);
    // llvmpipe's queries leave out the rasterization: there it waits instead.
    EXPECT_EQ(times.waitsForStages(), isSoftwareRasterizer());
    EXPECT_EQ(times.usesQueries(), hasTimerQueries() && !isSoftwareRasterizer());
    times.collect();  // nothing was issued before the first frame
    EXPECT_EQ(times.ms(0), 0.0);
    EXPECT_EQ(times.ms(1), 0.0);

    // Frame 1 runs stage 0 only.
    times.begin(0);
    clearManyTimes();
    times.end(0);
    times.endFrame();

    // Frame 2 reads frame 1, runs stage 1 only.
    times.collect();
    EXPECT_GT(times.ms(0), 0.0);
    EXPECT_EQ(times.ms(1), 0.0);
    times.begin(1);
    clearManyTimes();
    times.end(1);
    times.endFrame();

    // Frame 3 reads frame 2.
    times.collect();
    EXPECT_EQ(times.ms(0), 0.0);
    EXPECT_GT(times.ms(1), 0.0);
}

INSTANTIATE_TEST_SUITE_P(Apis, GpuStageTimesOnEachApi, ::testing::Values(GlRequest::Gl33, GlRequest::Es3),
                         [](const auto& info) { return info.param == GlRequest::Gl33 ? "gl33" : "es3"; });

}  // namespace
