#include "video/sources/V4l2Device.hpp"

#include <filesystem>

#include <cerrno>
#include <fcntl.h>
#include <poll.h>
#include <sys/ioctl.h>
#include <sys/mman.h>
#include <unistd.h>

namespace arcomp {

namespace {

class SystemV4l2Device final : public V4l2Device {
public:
    int open(const std::string& node) override { return ::open(node.c_str(), O_RDWR | O_NONBLOCK | O_CLOEXEC); }
    int ioctl(int fd, unsigned long request, void* arg) override {
        int r;
        do r = ::ioctl(fd, request, arg);
        while (r == -1 && errno == EINTR);
        return r;
    }
    void* mmap(std::size_t length, int fd, std::int64_t offset) override {
        return ::mmap(nullptr, length, PROT_READ | PROT_WRITE, MAP_SHARED, fd, static_cast<off_t>(offset));
    }
    int munmap(void* address, std::size_t length) override { return ::munmap(address, length); }
    int poll(int fd, int timeoutMs, short* revents) override {
        pollfd p{fd, POLLIN, 0};
        const int r = ::poll(&p, 1, timeoutMs);
        *revents = p.revents;
        return r;
    }
    int close(int fd) override { return ::close(fd); }
    std::string resolve(const std::string& path) override {
        std::error_code ec;
        const auto node = std::filesystem::canonical(path, ec);
        return ec ? std::string() : node.string();
    }
};

}  // namespace

std::shared_ptr<V4l2Device> systemV4l2Device() { return std::make_shared<SystemV4l2Device>(); }

}  // namespace arcomp
