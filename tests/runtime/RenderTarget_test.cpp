// A render target reads back as an image with its rows top to bottom, into
// a fresh image or into one kept from an earlier frame of another size.

#include "runtime/gl/GlContext.hpp"
#include "runtime/gl/RenderTarget.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <stdexcept>

using namespace arcomp;

namespace {

class RenderTargetOnEachApi : public ::testing::TestWithParam<GlRequest> {};

// Blue over the target's top rows, red below them: GL counts rows from the bottom.
void paintTopBlueBottomRed(const RenderTarget& target, int topRows) {
    target.bind();
    gl::glClearColor(1.0f, 0.0f, 0.0f, 1.0f);
    gl::glClear(GL_COLOR_BUFFER_BIT);
    gl::glEnable(GL_SCISSOR_TEST);
    gl::glScissor(0, target.size().y - topRows, target.size().x, topRows);
    gl::glClearColor(0.0f, 0.0f, 1.0f, 1.0f);
    gl::glClear(GL_COLOR_BUFFER_BIT);
    gl::glDisable(GL_SCISSOR_TEST);
}

std::uint8_t channel(const Image& img, int x, int y, int c) {
    return img
        .rgba[(static_cast<std::size_t>(y) * static_cast<std::size_t>(img.width) + static_cast<std::size_t>(x)) * 4 +
              static_cast<std::size_t>(c)];
}

TEST_P(RenderTargetOnEachApi, readsRowsTopToBottom) {
    auto context = HeadlessContext::create(GetParam());
    RenderTarget target({37, 21});  // odd sizes: rows of no particular alignment, a middle row
    paintTopBlueBottomRed(target, 5);
    const Image img = target.read();
    ASSERT_EQ(img.width, 37);
    ASSERT_EQ(img.height, 21);
    ASSERT_EQ(img.rgba.size(), 37u * 21u * 4u);
    for (int y = 0; y < 21; ++y)
        for (int x : {0, 18, 36}) {
            const bool top = y < 5;
            EXPECT_EQ(channel(img, x, y, 0), top ? 0 : 255) << x << "," << y;
            EXPECT_EQ(channel(img, x, y, 2), top ? 255 : 0) << x << "," << y;
            EXPECT_EQ(channel(img, x, y, 3), 255);
        }
}

TEST_P(RenderTargetOnEachApi, readingIntoAKeptImageGivesWhatAFreshReadGives) {
    auto context = HeadlessContext::create(GetParam());
    RenderTarget small({37, 21}), large({64, 48});
    paintTopBlueBottomRed(small, 5);
    paintTopBlueBottomRed(large, 30);
    // Kept from a larger frame and full of other bytes: none of them may show.
    Image kept;
    kept.width = 99;
    kept.height = 99;
    kept.rgba.assign(99u * 99u * 4u, 0x77);
    small.read(kept);
    const Image fresh = small.read();
    EXPECT_EQ(kept.width, fresh.width);
    EXPECT_EQ(kept.height, fresh.height);
    EXPECT_EQ(kept.rgba, fresh.rgba);
    // And back to the larger size.
    large.read(kept);
    EXPECT_EQ(kept.width, 64);
    EXPECT_EQ(kept.height, 48);
    EXPECT_EQ(kept.rgba, large.read().rgba);
    EXPECT_EQ(channel(kept, 10, 29, 2), 255);
    EXPECT_EQ(channel(kept, 10, 30, 0), 255);
}

TEST(RenderTarget, rejectsImpossibleSizes) {
    auto context = HeadlessContext::create(GlRequest::Auto);
    EXPECT_THROW(RenderTarget({0, 10}), std::invalid_argument);
    EXPECT_THROW(RenderTarget({1 << 20, 10}), std::invalid_argument);
}

INSTANTIATE_TEST_SUITE_P(Apis, RenderTargetOnEachApi, ::testing::Values(GlRequest::Gl33, GlRequest::Es3),
                         [](const auto& info) { return info.param == GlRequest::Gl33 ? "gl33" : "es3"; });

}  // namespace
