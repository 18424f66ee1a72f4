#include "FakeV4l2Device.hpp"
#include "video/sources/V4l2Source.hpp"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>

using namespace arcomp;
using arcomp::test::FakeEvent;
using arcomp::test::FakeV4l2Device;

namespace {

V4l2Options options(std::vector<PixelFormat> preference = {PixelFormat::Yuyv, PixelFormat::Mjpeg}) {
    V4l2Options o;
    o.device = "/dev/v4l/by-id/usb-fake-cam-video-index0";
    o.width = 640;
    o.height = 480;
    o.preference = std::move(preference);
    o.backoffInitial = std::chrono::milliseconds(0);
    o.backoffMax = std::chrono::milliseconds(0);
    return o;
}

double meanAbsDiff(const cv::Mat& a, const cv::Mat& b) { return cv::norm(a, b, cv::NORM_L1) / double(a.total() * 3); }

}  // namespace

TEST(V4l2Source, negotiatesTheFirstPreferredFormatTheDeviceOffers) {
    auto dev = std::make_shared<FakeV4l2Device>();
    V4l2Source src(options({PixelFormat::Nv12, PixelFormat::Mjpeg, PixelFormat::Yuyv}), dev);
    GrabResult r = src.grab();
    ASSERT_TRUE(r.frame) << r.state.reason;
    EXPECT_EQ(src.format(), PixelFormat::Mjpeg);  // NV12 is not offered; MJPEG comes before YUYV in the list
    EXPECT_EQ(dev->negotiated, static_cast<std::uint32_t>(V4L2_PIX_FMT_MJPEG));
    EXPECT_EQ(r.frame->format, PixelFormat::Mjpeg);
    EXPECT_EQ(r.frame->image.size(), cv::Size(640, 480));
    EXPECT_EQ(dev->maps, 4);  // four mmap buffers
}

TEST(V4l2Source, decodesYuyvFramesToTheScene) {
    auto dev = std::make_shared<FakeV4l2Device>();
    V4l2Source src(options(), dev);
    GrabResult r = src.grab();
    ASSERT_TRUE(r.frame) << r.state.reason;
    EXPECT_EQ(src.format(), PixelFormat::Yuyv);
    EXPECT_LT(meanAbsDiff(r.frame->image, dev->scene(0)), 3.0);
    // Driver timestamp: 1000 s + 0 us for the fake's first frame.
    EXPECT_EQ(r.frame->timestamp, std::chrono::seconds(1000));
}

TEST(V4l2Source, usesMjpegFromAnMjpegOnlyDevice) {
    auto dev = std::make_shared<FakeV4l2Device>();
    dev->offered = {V4L2_PIX_FMT_MJPEG};
    V4l2Source src(options({PixelFormat::Yuyv, PixelFormat::Mjpeg}), dev);
    GrabResult r = src.grab();
    ASSERT_TRUE(r.frame) << r.state.reason;
    EXPECT_EQ(src.format(), PixelFormat::Mjpeg);
    EXPECT_LT(meanAbsDiff(r.frame->image, dev->scene(0)), 4.0);
}

TEST(V4l2Source, refusesADeviceThatOffersNoneOfTheWantedFormats) {
    auto dev = std::make_shared<FakeV4l2Device>();
    dev->offered = {V4L2_PIX_FMT_MJPEG};
    V4l2Source src(options({PixelFormat::Yuyv, PixelFormat::Nv12}), dev);
    GrabResult r = src.grab();
    EXPECT_FALSE(r.frame);
    EXPECT_EQ(r.state.status, SourceStatus::Error);
    EXPECT_NE(r.state.reason.find("offers MJPG"), std::string::npos) << r.state.reason;
    EXPECT_NE(r.state.reason.find("YUYV, NV12"), std::string::npos) << r.state.reason;
    EXPECT_EQ(dev->opens, dev->closes);
}

TEST(V4l2Source, reportsStalledWhenNoFrameComesThenStreamsOn) {
    auto dev = std::make_shared<FakeV4l2Device>();
    dev->script = {FakeEvent::Frame, FakeEvent::Stall};
    V4l2Source src(options(), dev);
    ASSERT_TRUE(src.grab().frame);
    GrabResult stalled = src.grab();
    EXPECT_EQ(stalled.state.status, SourceStatus::Stalled);
    EXPECT_FALSE(stalled.frame);
    GrabResult again = src.grab();
    ASSERT_TRUE(again.frame);
    EXPECT_EQ(again.frame->sequence, 1u);
}

TEST(V4l2Source, skipsErrorFlaggedBuffers) {
    auto dev = std::make_shared<FakeV4l2Device>();
    dev->script = {FakeEvent::Frame, FakeEvent::ErrorBuffer, FakeEvent::Frame};
    V4l2Source src(options(), dev);
    ASSERT_TRUE(src.grab().frame);
    GrabResult flagged = src.grab();
    EXPECT_FALSE(flagged.frame);
    EXPECT_EQ(flagged.state.status, SourceStatus::Streaming);
    EXPECT_EQ(src.errorFrames(), 1u);
    GrabResult next = src.grab();
    ASSERT_TRUE(next.frame);
    // The delivered frame is the device's third, not the damaged second.
    EXPECT_LT(meanAbsDiff(next.frame->image, dev->scene(2)), 3.0);
}

TEST(V4l2Source, reconnectsUnderANewNodeByItsStableLinkAfterUnplug) {
    auto dev = std::make_shared<FakeV4l2Device>();
    dev->script = {FakeEvent::Frame, FakeEvent::Unplug};
    V4l2Source src(options(), dev);
    ASSERT_TRUE(src.grab().frame);
    EXPECT_EQ(src.node(), "/dev/video0");

    GrabResult gone = src.grab();
    EXPECT_EQ(gone.state.status, SourceStatus::Disconnected);
    EXPECT_EQ(dev->maps, dev->unmaps);  // buffers released on unplug
    EXPECT_EQ(dev->opens, dev->closes);
    GrabResult stillGone = src.grab();
    EXPECT_EQ(stillGone.state.status, SourceStatus::Disconnected);
    EXPECT_NE(stillGone.state.reason.find("not present"), std::string::npos) << stillGone.state.reason;

    dev->replug("/dev/video2");
    GrabResult back = src.grab();
    ASSERT_TRUE(back.frame) << back.state.reason;
    EXPECT_EQ(src.node(), "/dev/video2");
    EXPECT_EQ(src.reconnects(), 1u);
    EXPECT_EQ(back.frame->sequence, 1u);  // our sequence continues across the replug
}

TEST(V4l2Source, reportsEnodevFromDqbufAsDisconnected) {
    auto dev = std::make_shared<FakeV4l2Device>();
    V4l2Source src(options(), dev);
    dev->script = {FakeEvent::Frame, FakeEvent::DequeueEnodev};
    ASSERT_TRUE(src.grab().frame);
    GrabResult r = src.grab();
    EXPECT_EQ(r.state.status, SourceStatus::Disconnected);
    EXPECT_NE(r.state.reason.find("VIDIOC_DQBUF"), std::string::npos) << r.state.reason;
    EXPECT_FALSE(r.frame);
    EXPECT_EQ(dev->opens, dev->closes);
}

TEST(V4l2Source, listsFormatsSizesAndRates) {
    FakeV4l2Device dev;
    const std::vector<V4l2FormatInfo> formats = listV4l2Formats(dev, dev.link);
    ASSERT_EQ(formats.size(), 2u);
    EXPECT_EQ(fourccString(formats[0].fourcc), "YUYV");
    EXPECT_EQ(fourccString(formats[1].fourcc), "MJPG");
    ASSERT_EQ(formats[0].sizes.size(), 1u);
    EXPECT_EQ(formats[0].sizes[0].width, 640);
    EXPECT_EQ(formats[0].sizes[0].fps, (std::vector<double>{30.0, 15.0}));
    EXPECT_EQ(dev.opens, dev.closes);
}
