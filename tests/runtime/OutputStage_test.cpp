// The station's files: a frame read back asynchronously is written one
// call later under its own number, and finish() writes the last one; the
// matte's PNG is written at once either way.

#include "runtime/gl/GlContext.hpp"
#include "runtime/station/ImageFile.hpp"
#include "runtime/station/OutputStage.hpp"
#include "tests/support/TempDir.hpp"

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

using namespace arcomp;

namespace {

void paintRed(const RenderTarget& target, int level) {
    target.bind();
    gl::glClearColor(static_cast<float>(level) / 255.0f, 0.0f, 0.0f, 1.0f);
    gl::glClear(GL_COLOR_BUFFER_BIT);
}

int redOf(const std::filesystem::path& png) { return readPng(png).rgba[0]; }

class OutputStageByReadback : public ::testing::TestWithParam<FrameReadback::Mode> {};

TEST_P(OutputStageByReadback, eachFrameIsWrittenUnderItsOwnNumberAndFinishWritesTheLast) {
    const bool async = GetParam() == FrameReadback::Mode::Asynchronous;
    auto context = HeadlessContext::create(GlRequest::Auto);
    test::TempDir dir;
    OutputConfig config;
    config.pngDir = dir.path() / "frames";
    config.matteDir = dir.path() / "matte";
    RenderTarget target({16, 8});
    OutputStage out(config, 30.0, target.size(), GetParam());
    out.setFirstIndex(7);  // a reloaded station goes on from frame 7
    const cv::Mat person(8, 16, CV_8UC4, cv::Scalar(0, 0, 0, 255));
    const auto frame = [&](int n) { return config.pngDir / ("frame-00000" + std::to_string(n) + ".png"); };
    const auto matte = [&](int n) { return config.matteDir / ("matte-00000" + std::to_string(n) + ".png"); };

    paintRed(target, 70);
    out.write(target, person);
    EXPECT_TRUE(std::filesystem::exists(matte(7)));
    EXPECT_EQ(std::filesystem::exists(frame(7)), !async);
    paintRed(target, 80);
    out.write(target, person);
    ASSERT_TRUE(std::filesystem::exists(frame(7)));
    EXPECT_EQ(redOf(frame(7)), 70);
    EXPECT_EQ(std::filesystem::exists(frame(8)), !async);
    paintRed(target, 90);
    out.write(target, person);
    EXPECT_EQ(redOf(frame(8)), 80);
    out.finish();
    ASSERT_TRUE(std::filesystem::exists(frame(9)));
    EXPECT_EQ(redOf(frame(9)), 90);
    out.finish();  // twice is harmless
    EXPECT_FALSE(std::filesystem::exists(frame(10)));
    EXPECT_TRUE(std::filesystem::exists(matte(9)));
    EXPECT_EQ(out.failures(), 0u) << out.lastError();
}

INSTANTIATE_TEST_SUITE_P(Readbacks, OutputStageByReadback,
                         ::testing::Values(FrameReadback::Mode::Synchronous, FrameReadback::Mode::Asynchronous),
                         [](const auto& info) {
                             return info.param == FrameReadback::Mode::Asynchronous ? "asynchronous" : "synchronous";
                         });

}  // namespace
