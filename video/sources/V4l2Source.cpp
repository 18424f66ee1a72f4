#include "video/sources/V4l2Source.hpp"
#include "graph/core/JoinText.hpp"

#include "video/pixels/VideoError.hpp"

#include <opencv2/imgcodecs.hpp>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <thread>

#include <linux/videodev2.h>
#include <poll.h>
#include <sys/mman.h>

namespace arcomp {

namespace {

std::vector<std::uint32_t> offeredFourccs(V4l2Device& dev, int fd) {
    std::vector<std::uint32_t> out;
    for (std::uint32_t i = 0; i < 64; ++i) {
        v4l2_fmtdesc d{};
        d.index = i;
        d.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
        if (dev.ioctl(fd, VIDIOC_ENUM_FMT, &d) != 0) break;
        out.push_back(d.pixelformat);
    }
    return out;
}

std::string joinFourccs(const std::vector<std::uint32_t>& v) {
    std::string s;
    for (std::uint32_t f : v) s += (s.empty() ? "" : ", ") + fourccString(f);
    return s.empty() ? "nothing" : s;
}

}  // namespace

V4l2Source::V4l2Source(V4l2Options options, std::shared_ptr<V4l2Device> device)
    : options_(std::move(options)), device_(std::move(device)) {
    if (options_.device.empty()) throw VideoError("v4l2", "device", "no device path given");
    if (options_.preference.empty()) throw VideoError(options_.device, "formats", "empty format preference");
    if (options_.bufferCount < 2) options_.bufferCount = 2;
}

V4l2Source::~V4l2Source() { teardown(); }

std::string V4l2Source::errnoText(const char* call) const {
    return joinText(call, " (", node_, "): ", std::strerror(errno));
}

std::string V4l2Source::connect(bool& permanent) {
    permanent = false;
    node_ = device_->resolve(options_.device);
    if (node_.empty()) return joinText(options_.device, " is not present");
    fd_ = device_->open(node_);
    if (fd_ < 0) return errnoText("open");

    v4l2_capability cap{};
    if (device_->ioctl(fd_, VIDIOC_QUERYCAP, &cap) != 0) return errnoText("VIDIOC_QUERYCAP");
    const std::uint32_t caps = (cap.capabilities & V4L2_CAP_DEVICE_CAPS) ? cap.device_caps : cap.capabilities;
    if (!(caps & V4L2_CAP_VIDEO_CAPTURE) || !(caps & V4L2_CAP_STREAMING)) {
        permanent = true;
        return joinText(node_, " is not a streaming video capture device (capabilities 0x", std::hex, caps, ")");
    }

    const std::vector<std::uint32_t> offered = offeredFourccs(*device_, fd_);
    std::optional<std::uint32_t> chosen;
    for (PixelFormat want : options_.preference) {
        for (std::uint32_t f : offered)
            if (pixelFormatFromFourcc(f) == want) chosen = f;
        if (chosen) break;
    }
    if (!chosen) {
        permanent = true;
        std::string asked;
        for (PixelFormat p : options_.preference)
            asked += (asked.empty() ? "" : ", ") + std::string(pixelFormatName(p));
        return joinText(node_, " offers ", joinFourccs(offered), "; the config asks for ", asked);
    }

    v4l2_format fmt{};
    fmt.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    fmt.fmt.pix.width = static_cast<std::uint32_t>(options_.width);
    fmt.fmt.pix.height = static_cast<std::uint32_t>(options_.height);
    fmt.fmt.pix.pixelformat = *chosen;
    fmt.fmt.pix.field = V4L2_FIELD_NONE;
    if (device_->ioctl(fd_, VIDIOC_S_FMT, &fmt) != 0) return errnoText("VIDIOC_S_FMT");
    // The driver may adjust the request: what it wrote back is what we get.
    format_ = pixelFormatFromFourcc(fmt.fmt.pix.pixelformat);
    if (!format_) {
        permanent = true;
        return joinText(node_, " switched to unsupported format ", fourccString(fmt.fmt.pix.pixelformat));
    }
    width_ = static_cast<int>(fmt.fmt.pix.width);
    height_ = static_cast<int>(fmt.fmt.pix.height);
    stride_ = fmt.fmt.pix.bytesperline ? static_cast<int>(fmt.fmt.pix.bytesperline)
                                       : (*format_ == PixelFormat::Yuyv ? width_ * 2 : width_);
    if (width_ != options_.width || height_ != options_.height)
        spdlog::warn(joinText(node_, ": asked for ", options_.width, "x", options_.height, ", device gives ", width_,
                              "x", height_));
    encoding_ = options_.encoding.value_or(defaultYuvEncoding(*format_, height_));

    v4l2_streamparm parm{};
    parm.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    parm.parm.capture.timeperframe = {1000, static_cast<std::uint32_t>(std::lround(options_.fps * 1000.0))};
    if (device_->ioctl(fd_, VIDIOC_S_PARM, &parm) != 0)
        spdlog::debug(joinText(node_, ": VIDIOC_S_PARM refused; keeping the device's rate"));

    v4l2_requestbuffers req{};
    req.count = static_cast<std::uint32_t>(options_.bufferCount);
    req.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    req.memory = V4L2_MEMORY_MMAP;
    if (device_->ioctl(fd_, VIDIOC_REQBUFS, &req) != 0) return errnoText("VIDIOC_REQBUFS");
    if (req.count < 2) return joinText(node_, " granted ", req.count, " buffers, need 2");
    for (std::uint32_t i = 0; i < req.count; ++i) {
        v4l2_buffer b{};
        b.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
        b.memory = V4L2_MEMORY_MMAP;
        b.index = i;
        if (device_->ioctl(fd_, VIDIOC_QUERYBUF, &b) != 0) return errnoText("VIDIOC_QUERYBUF");
        void* p = device_->mmap(b.length, fd_, b.m.offset);
        if (p == MAP_FAILED) return errnoText("mmap");
        buffers_.push_back({p, b.length});
        if (device_->ioctl(fd_, VIDIOC_QBUF, &b) != 0) return errnoText("VIDIOC_QBUF");
    }
    int type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    if (device_->ioctl(fd_, VIDIOC_STREAMON, &type) != 0) return errnoText("VIDIOC_STREAMON");
    spdlog::info(joinText(options_.device, ": streaming ", pixelFormatName(*format_), " ", width_, "x", height_,
                          " from ", node_));
    return {};
}

void V4l2Source::teardown() {
    if (fd_ >= 0) {
        int type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
        device_->ioctl(fd_, VIDIOC_STREAMOFF, &type);  // fails harmlessly on a vanished device
    }
    for (const Buffer& b : buffers_) device_->munmap(b.data, b.length);
    buffers_.clear();
    if (fd_ >= 0) {
        v4l2_requestbuffers req{};
        req.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
        req.memory = V4L2_MEMORY_MMAP;
        device_->ioctl(fd_, VIDIOC_REQBUFS, &req);
        device_->close(fd_);
    }
    fd_ = -1;
}

GrabResult V4l2Source::disconnect(std::string reason) {
    teardown();
    waitBeforeConnect_ = true;
    return {std::nullopt, {SourceStatus::Disconnected, std::move(reason)}};
}

std::optional<cv::Mat> V4l2Source::convert(const Buffer& b, std::uint32_t bytesUsed) {
    const auto* data = static_cast<const std::uint8_t*>(b.data);
    switch (*format_) {
    case PixelFormat::Yuyv:
        if (bytesUsed < static_cast<std::uint32_t>(stride_ * height_)) return std::nullopt;
        return yuyvToBgr(data, width_, height_, stride_, encoding_);
    case PixelFormat::Nv12:
        if (bytesUsed < static_cast<std::uint32_t>(stride_ * height_ * 3 / 2)) return std::nullopt;
        return nv12ToBgr(data, stride_, data + static_cast<std::ptrdiff_t>(stride_) * height_, stride_, width_, height_,
                         encoding_);
    case PixelFormat::Mjpeg: {
        const cv::Mat jpeg(1, static_cast<int>(std::min<std::size_t>(bytesUsed, b.length)), CV_8UC1,
                           const_cast<std::uint8_t*>(data));
        cv::Mat img = cv::imdecode(jpeg, cv::IMREAD_COLOR);
        if (img.empty()) return std::nullopt;
        return img;
    }
    default: return std::nullopt;
    }
}

GrabResult V4l2Source::grab() {
    if (fd_ < 0) {
        if (waitBeforeConnect_) {
            std::this_thread::sleep_for(backoff_);
            backoff_ = std::clamp(backoff_ * 2, options_.backoffInitial, options_.backoffMax);
        }
        bool permanent = false;
        std::string why = connect(permanent);
        if (!why.empty()) {
            teardown();
            waitBeforeConnect_ = true;
            return {std::nullopt, {permanent ? SourceStatus::Error : SourceStatus::Disconnected, why}};
        }
        if (everConnected_) ++reconnects_;
        everConnected_ = true;
        waitBeforeConnect_ = false;
        backoff_ = std::chrono::milliseconds(0);
    }

    const int periodMs = static_cast<int>(std::ceil(1000.0 / options_.fps));
    const int timeoutMs = std::max(3 * periodMs, 50);
    short revents = 0;
    const int n = device_->poll(fd_, timeoutMs, &revents);
    if (n < 0 && errno == EINTR) return {std::nullopt, {SourceStatus::Streaming, {}}};
    if (n < 0) return disconnect(errnoText("poll"));
    if (n == 0) return {std::nullopt, {SourceStatus::Stalled, joinText(node_, ": no frame for ", timeoutMs, " ms")}};
    if (revents & (POLLERR | POLLHUP | POLLNVAL))
        return disconnect(joinText(node_, ": poll reports the device gone (revents 0x", std::hex, revents, ")"));

    v4l2_buffer b{};
    b.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    b.memory = V4L2_MEMORY_MMAP;
    if (device_->ioctl(fd_, VIDIOC_DQBUF, &b) != 0) {
        if (errno == EAGAIN) return {std::nullopt, {SourceStatus::Streaming, {}}};
        return disconnect(errnoText("VIDIOC_DQBUF"));
    }
    std::optional<cv::Mat> img;
    const bool flaggedError = (b.flags & V4L2_BUF_FLAG_ERROR) != 0;
    if (!flaggedError && b.index < buffers_.size()) img = convert(buffers_[b.index], b.bytesused);
    const std::uint32_t bufferSequence = b.sequence;
    Frame f;
    f.timestamp = std::chrono::seconds(b.timestamp.tv_sec) + std::chrono::microseconds(b.timestamp.tv_usec);
    // A monotonic driver timestamp is on CLOCK_MONOTONIC, which is steady_clock on Linux.
    const bool monotonic = (b.flags & V4L2_BUF_FLAG_TIMESTAMP_MASK) == V4L2_BUF_FLAG_TIMESTAMP_MONOTONIC;
    f.captured = monotonic ? std::chrono::steady_clock::time_point(
                                 std::chrono::duration_cast<std::chrono::steady_clock::duration>(f.timestamp))
                           : std::chrono::steady_clock::now();
    if (device_->ioctl(fd_, VIDIOC_QBUF, &b) != 0) return disconnect(errnoText("VIDIOC_QBUF"));
    if (!img) {
        ++errorFrames_;
        spdlog::debug(joinText(node_, ": skipped buffer ", bufferSequence, " (",
                               flaggedError ? "V4L2_BUF_FLAG_ERROR" : "undecodable", ")"));
        return {std::nullopt, {SourceStatus::Streaming, {}}};
    }
    f.image = std::move(*img);
    f.sequence = sequence_++;
    f.format = *format_;
    return {std::move(f), {SourceStatus::Streaming, {}}};
}

std::vector<V4l2FormatInfo> listV4l2Formats(V4l2Device& dev, const std::string& path) {
    const std::string node = dev.resolve(path);
    if (node.empty()) throw VideoError(path, "", "device is not present");
    const int fd = dev.open(node);
    if (fd < 0) throw VideoError(path, "open", std::strerror(errno));
    std::vector<V4l2FormatInfo> out;
    for (std::uint32_t i = 0; i < 64; ++i) {
        v4l2_fmtdesc d{};
        d.index = i;
        d.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
        if (dev.ioctl(fd, VIDIOC_ENUM_FMT, &d) != 0) break;
        V4l2FormatInfo info;
        info.fourcc = d.pixelformat;
        info.description = reinterpret_cast<const char*>(d.description);
        for (std::uint32_t s = 0; s < 256; ++s) {
            v4l2_frmsizeenum fs{};
            fs.index = s;
            fs.pixel_format = d.pixelformat;
            if (dev.ioctl(fd, VIDIOC_ENUM_FRAMESIZES, &fs) != 0) break;
            V4l2FormatInfo::Size size;
            if (fs.type == V4L2_FRMSIZE_TYPE_DISCRETE) {
                size.width = static_cast<int>(fs.discrete.width);
                size.height = static_cast<int>(fs.discrete.height);
            } else {
                size.width = static_cast<int>(fs.stepwise.max_width);
                size.height = static_cast<int>(fs.stepwise.max_height);
                size.stepwise = true;
            }
            for (std::uint32_t r = 0; r < 64; ++r) {
                v4l2_frmivalenum fi{};
                fi.index = r;
                fi.pixel_format = d.pixelformat;
                fi.width = static_cast<std::uint32_t>(size.width);
                fi.height = static_cast<std::uint32_t>(size.height);
                if (dev.ioctl(fd, VIDIOC_ENUM_FRAMEINTERVALS, &fi) != 0 || fi.type != V4L2_FRMIVAL_TYPE_DISCRETE) break;
                if (fi.discrete.numerator) size.fps.push_back(double(fi.discrete.denominator) / fi.discrete.numerator);
            }
            info.sizes.push_back(std::move(size));
            if (fs.type != V4L2_FRMSIZE_TYPE_DISCRETE) break;
        }
        out.push_back(std::move(info));
    }
    dev.close(fd);
    return out;
}

}  // namespace arcomp
