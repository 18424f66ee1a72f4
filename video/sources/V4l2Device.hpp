#pragma once
// The thin seam between V4l2Source and the kernel: the six calls it makes
// on a device node, plus resolving a stable /dev/v4l/by-id link. The real
// one forwards to the system; tests script a fake device (negotiation,
// stalls, unplug and replug under a new /dev/videoN) without a camera.
//
//   std::shared_ptr<V4l2Device> dev = systemV4l2Device();
//   int fd = dev->open(dev->resolve("/dev/v4l/by-id/usb-cam-video-index0"));
//
// Calls follow the system's conventions: -1 (or MAP_FAILED) and errno.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

namespace arcomp {

class V4l2Device {
public:
    virtual ~V4l2Device() = default;
    virtual int open(const std::string& node) = 0;
    virtual int ioctl(int fd, unsigned long request, void* arg) = 0;
    virtual void* mmap(std::size_t length, int fd, std::int64_t offset) = 0;
    virtual int munmap(void* address, std::size_t length) = 0;
    // Waits for POLLIN on fd; returns poll()'s count and sets *revents.
    virtual int poll(int fd, int timeoutMs, short* revents) = 0;
    virtual int close(int fd) = 0;
    // The node a (possibly symlinked) path names now, or "" when absent.
    virtual std::string resolve(const std::string& path) = 0;
};

std::shared_ptr<V4l2Device> systemV4l2Device();

}  // namespace arcomp
