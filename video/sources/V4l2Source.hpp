#pragma once
// A V4L2 camera, driven by ioctls through the V4l2Device seam: negotiate a
// format from the config's preference list, 4 mmap buffers, DQBUF/QBUF with
// poll, driver timestamps. When the camera is unplugged (ENODEV, poll error)
// it reports Disconnected, then reconnects with backoff, finding the camera
// again by its stable path: name /dev/v4l/by-id/... in the options, because
// /dev/videoN changes on replug.
//
//   V4l2Source cam({.device = "/dev/v4l/by-id/usb-046d_C920-video-index0",
//                   .preference = {PixelFormat::Mjpeg, PixelFormat::Yuyv}});
//   GrabResult r = cam.grab();   // CaptureThread calls this on its own thread

#include "video/pixels/YuvConversion.hpp"
#include "video/sources/FrameGrabber.hpp"
#include "video/sources/V4l2Device.hpp"

#include <chrono>
#include <cstdint>
#include <optional>
#include <vector>

namespace arcomp {

struct V4l2Options {
    std::string device;
    int width = 1280;
    int height = 720;
    double fps = 30.0;
    std::vector<PixelFormat> preference{PixelFormat::Yuyv, PixelFormat::Mjpeg, PixelFormat::Nv12};
    std::optional<YuvEncoding> encoding;  // default: defaultYuvEncoding(format, height)
    int bufferCount = 4;
    std::chrono::milliseconds backoffInitial{100};
    std::chrono::milliseconds backoffMax{2000};
};

class V4l2Source : public FrameGrabber {
public:
    explicit V4l2Source(V4l2Options options, std::shared_ptr<V4l2Device> device = systemV4l2Device());
    ~V4l2Source() override;

    GrabResult grab() override;
    std::string name() const override { return options_.device; }

    // What was negotiated on the current connection.
    std::optional<PixelFormat> format() const { return format_; }
    int width() const { return width_; }
    int height() const { return height_; }
    std::string node() const { return node_; }                  // the /dev/videoN in use
    std::uint64_t errorFrames() const { return errorFrames_; }  // V4L2_BUF_FLAG_ERROR or undecodable
    std::uint64_t reconnects() const { return reconnects_; }

private:
    struct Buffer {
        void* data = nullptr;
        std::size_t length = 0;
    };
    // Returns "" on success, else why not; `permanent` when retrying cannot help.
    std::string connect(bool& permanent);
    void teardown();
    GrabResult disconnect(std::string reason);
    std::optional<cv::Mat> convert(const Buffer& b, std::uint32_t bytesUsed);
    std::string errnoText(const char* call) const;

    V4l2Options options_;
    std::shared_ptr<V4l2Device> device_;
    int fd_ = -1;
    std::string node_;
    std::vector<Buffer> buffers_;
    std::optional<PixelFormat> format_;
    int width_ = 0, height_ = 0, stride_ = 0;
    YuvEncoding encoding_;
    std::uint64_t sequence_ = 0;
    std::uint64_t errorFrames_ = 0;
    std::uint64_t reconnects_ = 0;
    bool everConnected_ = false;
    std::chrono::milliseconds backoff_{0};
    bool waitBeforeConnect_ = false;
};

// One pixel format a device offers, with its frame sizes and rates.
struct V4l2FormatInfo {
    std::uint32_t fourcc = 0;
    std::string description;
    struct Size {
        int width = 0, height = 0;
        std::vector<double> fps;  // empty when the driver does not enumerate intervals
        bool stepwise = false;    // width/height are the maximum of a continuous range
    };
    std::vector<Size> sizes;
};

// For `arcomp inspect-video /dev/videoN`: ENUM_FMT, ENUM_FRAMESIZES and
// ENUM_FRAMEINTERVALS. Throws VideoError when the device cannot be opened.
std::vector<V4l2FormatInfo> listV4l2Formats(V4l2Device& device, const std::string& path);

}  // namespace arcomp
