// Reading frames back: synchronously each frame comes back at once; through
// the pixel-buffer pair each comes back one call later, the last through
// drain(), with its own size and its rows top to bottom.

#include "runtime/gl/FrameReadback.hpp"
#include "runtime/gl/GlContext.hpp"

#include <gtest/gtest.h>

using namespace arcomp;

namespace {

class FrameReadbackOnEachApi : public ::testing::TestWithParam<GlRequest> {};

// Frame `n`: its own red level, and a blue band over its top `n + 1` rows
// (GL counts rows from the bottom), so that both order and flip show.
void paintFrame(const RenderTarget& target, int n) {
    target.bind();
    gl::glClearColor(static_cast<float>(10 * n) / 255.0f, 0.0f, 0.0f, 1.0f);
    gl::glClear(GL_COLOR_BUFFER_BIT);
    gl::glEnable(GL_SCISSOR_TEST);
    gl::glScissor(0, target.size().y - (n + 1), target.size().x, n + 1);
    gl::glClearColor(0.0f, 0.0f, 1.0f, 1.0f);
    gl::glClear(GL_COLOR_BUFFER_BIT);
    gl::glDisable(GL_SCISSOR_TEST);
}

TEST_P(FrameReadbackOnEachApi, asynchronousReturnsEachFrameOneCallLaterAndTheLastThroughDrain) {
    auto context = HeadlessContext::create(GetParam());
    RenderTarget target({37, 21}), larger({64, 48});
    FrameReadback readback(FrameReadback::Mode::Asynchronous);
    EXPECT_EQ(readback.latencyFrames(), 1);
    Image image;
    Image expected[4];

    paintFrame(target, 0);
    expected[0] = target.read();
    EXPECT_FALSE(readback.read(target, image)) << "nothing was in flight before the first frame";
    for (int n = 1; n < 4; ++n) {
        // Frame 2 is larger: each frame keeps its own size.
        const RenderTarget& t = n == 2 ? larger : target;
        paintFrame(t, n);
        expected[n] = t.read();
        ASSERT_TRUE(readback.read(t, image)) << n;
        EXPECT_EQ(image.width, expected[n - 1].width) << n;
        EXPECT_EQ(image.height, expected[n - 1].height) << n;
        EXPECT_EQ(image.rgba, expected[n - 1].rgba) << "call " << n << " returns frame " << n - 1;
    }
    ASSERT_TRUE(readback.drain(image));
    EXPECT_EQ(image.rgba, expected[3].rgba);
    EXPECT_FALSE(readback.drain(image)) << "drained already";
    // Frame 3's top four rows are its blue band, the fifth its red.
    EXPECT_EQ(image.rgba[(3u * 37u) * 4u + 2u], 255);
    EXPECT_EQ(image.rgba[(4u * 37u) * 4u + 0u], 30);
}

TEST_P(FrameReadbackOnEachApi, synchronousReturnsEachFrameAtOnce) {
    auto context = HeadlessContext::create(GetParam());
    RenderTarget target({37, 21});
    FrameReadback readback(FrameReadback::Mode::Synchronous);
    EXPECT_EQ(readback.latencyFrames(), 0);
    Image image;
    for (int n = 0; n < 3; ++n) {
        paintFrame(target, n);
        ASSERT_TRUE(readback.read(target, image));
        EXPECT_EQ(image.rgba, target.read().rgba) << n;
    }
    EXPECT_FALSE(readback.drain(image));
}

TEST_P(FrameReadbackOnEachApi, autoReadsSynchronouslyOnASoftwareRasterizerOnly) {
    auto context = HeadlessContext::create(GetParam());
    RenderTarget target({8, 8});
    FrameReadback readback;
    Image image;
    paintFrame(target, 1);
    const bool gotFrame = readback.read(target, image);
    EXPECT_EQ(readback.latencyFrames(), isSoftwareRasterizer() ? 0 : 1);
    EXPECT_EQ(gotFrame, isSoftwareRasterizer());
}

INSTANTIATE_TEST_SUITE_P(Apis, FrameReadbackOnEachApi, ::testing::Values(GlRequest::Gl33, GlRequest::Es3),
                         [](const auto& info) { return info.param == GlRequest::Gl33 ? "gl33" : "es3"; });

}  // namespace
