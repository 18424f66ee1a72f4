#pragma once
// A scripted V4L2 camera for tests: it answers the ioctls V4l2Source makes,
// fills its mmap buffers with test-pattern frames in the negotiated format,
// and follows a script of events (frame, error-flagged buffer, stall,
// unplug). replug() brings it back under a new /dev/videoN behind the same
// by-id link.

#include "video/pixels/PixelFormat.hpp"
#include "video/pixels/YuvConversion.hpp"
#include "video/sources/TestPatternSource.hpp"
#include "video/sources/V4l2Device.hpp"

#include <opencv2/imgcodecs.hpp>

#include <cerrno>
#include <cstring>
#include <deque>
#include <map>
#include <vector>

#include <linux/videodev2.h>
#include <poll.h>
#include <sys/mman.h>

namespace arcomp::test {

// Unplug: poll reports POLLERR. DequeueEnodev: poll says ready, DQBUF fails with ENODEV.
enum class FakeEvent { Frame, ErrorBuffer, Stall, Unplug, DequeueEnodev };

class FakeV4l2Device : public V4l2Device {
public:
    std::string link = "/dev/v4l/by-id/usb-fake-cam-video-index0";
    std::string node = "/dev/video0";
    bool present = true;
    std::vector<std::uint32_t> offered{V4L2_PIX_FMT_YUYV, V4L2_PIX_FMT_MJPEG};
    int nativeWidth = 640, nativeHeight = 480;  // S_FMT snaps every request to this size
    YuvEncoding encoding{YuvMatrix::Bt601, YuvRange::Limited};
    std::deque<FakeEvent> script;  // empty: every poll delivers a frame
    std::uint32_t negotiated = 0;
    int opens = 0, closes = 0, maps = 0, unmaps = 0;
    bool streaming = false;

    void replug(std::string newNode) {
        node = std::move(newNode);
        present = true;
    }

    int open(const std::string& path) override {
        if (!present || path != node) return fail(ENOENT);
        ++opens;
        return fd_ = 3 + opens;
    }
    int close(int) override {
        ++closes;
        return 0;
    }
    std::string resolve(const std::string& path) override {
        if (!present) return {};
        return (path == link || path == node) ? node : std::string();
    }
    void* mmap(std::size_t length, int fd, std::int64_t offset) override {
        const auto i = static_cast<std::size_t>(offset / kStride);
        if (fd != fd_ || i >= buffers_.size() || length != buffers_[i].size()) {
            errno = EINVAL;
            return MAP_FAILED;
        }
        ++maps;
        return buffers_[i].data();
    }
    int munmap(void*, std::size_t) override {
        ++unmaps;
        return 0;
    }
    int poll(int fd, int, short* revents) override {
        *revents = 0;
        if (!present || fd != fd_) {
            *revents = POLLERR;
            return 1;
        }
        const FakeEvent e = script.empty() ? FakeEvent::Frame : script.front();
        if (e == FakeEvent::Stall) {
            script.pop_front();
            return 0;
        }
        if (e == FakeEvent::Unplug) {
            script.pop_front();
            present = false;
            *revents = POLLERR;
            return 1;
        }
        *revents = POLLIN;
        return 1;
    }

    int ioctl(int fd, unsigned long request, void* arg) override {
        if (!present || fd != fd_) return fail(ENODEV);
        switch (request) {
        case VIDIOC_QUERYCAP: {
            auto* c = static_cast<v4l2_capability*>(arg);
            *c = {};
            c->capabilities = V4L2_CAP_VIDEO_CAPTURE | V4L2_CAP_STREAMING | V4L2_CAP_DEVICE_CAPS;
            c->device_caps = V4L2_CAP_VIDEO_CAPTURE | V4L2_CAP_STREAMING;
            return 0;
        }
        case VIDIOC_ENUM_FMT: {
            auto* d = static_cast<v4l2_fmtdesc*>(arg);
            if (d->index >= offered.size()) return fail(EINVAL);
            d->pixelformat = offered[d->index];
            std::snprintf(reinterpret_cast<char*>(d->description), sizeof d->description, "fake %s",
                          fourccString(d->pixelformat).c_str());
            return 0;
        }
        case VIDIOC_ENUM_FRAMESIZES: {
            auto* s = static_cast<v4l2_frmsizeenum*>(arg);
            if (s->index > 0) return fail(EINVAL);
            s->type = V4L2_FRMSIZE_TYPE_DISCRETE;
            s->discrete = {static_cast<std::uint32_t>(nativeWidth), static_cast<std::uint32_t>(nativeHeight)};
            return 0;
        }
        case VIDIOC_ENUM_FRAMEINTERVALS: {
            auto* i = static_cast<v4l2_frmivalenum*>(arg);
            if (i->index > 1) return fail(EINVAL);
            i->type = V4L2_FRMIVAL_TYPE_DISCRETE;
            i->discrete = {1, i->index == 0 ? 30u : 15u};
            return 0;
        }
        case VIDIOC_S_FMT: {
            auto* f = static_cast<v4l2_format*>(arg);
            bool known = false;
            for (std::uint32_t o : offered) known |= o == f->fmt.pix.pixelformat;
            if (!known) f->fmt.pix.pixelformat = offered.front();  // drivers substitute, as the spec allows
            negotiated = f->fmt.pix.pixelformat;
            f->fmt.pix.width = static_cast<std::uint32_t>(nativeWidth);
            f->fmt.pix.height = static_cast<std::uint32_t>(nativeHeight);
            f->fmt.pix.bytesperline = negotiated == V4L2_PIX_FMT_YUYV   ? nativeWidth * 2
                                      : negotiated == V4L2_PIX_FMT_NV12 ? nativeWidth
                                                                        : 0;
            return 0;
        }
        case VIDIOC_S_PARM: return 0;
        case VIDIOC_REQBUFS: {
            auto* r = static_cast<v4l2_requestbuffers*>(arg);
            buffers_.assign(r->count, std::vector<std::uint8_t>(kStride));
            queued_.clear();
            return 0;
        }
        case VIDIOC_QUERYBUF: {
            auto* b = static_cast<v4l2_buffer*>(arg);
            if (b->index >= buffers_.size()) return fail(EINVAL);
            b->length = kStride;
            b->m.offset = b->index * kStride;
            return 0;
        }
        case VIDIOC_QBUF: queued_.push_back(static_cast<v4l2_buffer*>(arg)->index); return 0;
        case VIDIOC_STREAMON: streaming = true; return 0;
        case VIDIOC_STREAMOFF: streaming = false; return 0;
        case VIDIOC_DQBUF: return dequeue(*static_cast<v4l2_buffer*>(arg));
        default: return fail(ENOTTY);
        }
    }

    // The image frame k of the fake's scene has.
    cv::Mat scene(std::uint64_t k) const {
        return TestPatternSource({.width = nativeWidth, .height = nativeHeight, .fps = 30, .paced = false}).render(k);
    }

    static constexpr std::size_t kStride = 4 << 20;  // room for any fake frame

private:
    static int fail(int e) {
        errno = e;
        return -1;
    }

    int dequeue(v4l2_buffer& b) {
        if (!streaming || queued_.empty()) return fail(EAGAIN);
        FakeEvent e = FakeEvent::Frame;
        if (!script.empty()) {
            e = script.front();
            script.pop_front();
        }
        if (e == FakeEvent::DequeueEnodev) {
            present = false;
            return fail(ENODEV);
        }
        const std::uint32_t index = queued_.front();
        queued_.pop_front();
        std::vector<std::uint8_t>& mem = buffers_[index];
        const cv::Mat img = scene(produced_);
        std::vector<std::uint8_t> bytes;
        if (negotiated == V4L2_PIX_FMT_YUYV)
            bytes = bgrToYuyv(img, encoding);
        else if (negotiated == V4L2_PIX_FMT_NV12)
            bytes = bgrToNv12(img, encoding);
        else
            cv::imencode(".jpg", img, bytes, {cv::IMWRITE_JPEG_QUALITY, 95});
        std::memcpy(mem.data(), bytes.data(), bytes.size());
        b.index = index;
        b.bytesused = static_cast<std::uint32_t>(bytes.size());
        b.sequence = static_cast<std::uint32_t>(produced_++);
        b.flags = V4L2_BUF_FLAG_TIMESTAMP_MONOTONIC | (e == FakeEvent::ErrorBuffer ? V4L2_BUF_FLAG_ERROR : 0);
        b.timestamp = {static_cast<long>(1000 + b.sequence / 30), static_cast<long>((b.sequence % 30) * 33333)};
        return 0;
    }

    int fd_ = -1;
    std::vector<std::vector<std::uint8_t>> buffers_;
    std::deque<std::uint32_t> queued_;
    std::uint64_t produced_ = 0;
};

}  // namespace arcomp::test
