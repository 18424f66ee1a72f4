#include "graph/io/AtomicFile.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>

namespace arcomp {

namespace {

// Unique per process (pid) and per call (counter), so that two processes or
// two threads writing the same file never write into one temporary.
std::filesystem::path temporaryBeside(const std::filesystem::path& file) {
    static std::atomic<unsigned> calls{0};
    std::filesystem::path temp = file;
    temp += ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(calls++);
    return temp;
}

[[noreturn]] void failed(const std::filesystem::path& file, const std::string& step, int error) {
    throw std::runtime_error(file.string() + ": " + step + ": " + std::strerror(error));
}

bool writeAll(int fd, std::span<const std::byte> bytes) {
    while (!bytes.empty()) {
        const ssize_t n = ::write(fd, bytes.data(), bytes.size());
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            if (n == 0) errno = EIO;  // no progress and no reason: do not loop forever
            return false;
        }
        bytes = bytes.subspan(static_cast<std::size_t>(n));
    }
    return true;
}

}  // namespace

void writeFileAtomically(const std::filesystem::path& file, std::span<const std::byte> bytes) {
    const std::filesystem::path temp = temporaryBeside(file);
    const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (fd < 0) failed(file, "cannot create " + temp.filename().string(), errno);

    // Without fsync a crash after the rename could leave the new name on
    // disk with the data not yet there: an empty file where a good one was.
    // EINVAL: a file system that cannot sync at all; nothing to wait for.
    std::string step;
    int error = 0;
    if (!writeAll(fd, bytes)) {
        step = "cannot write ";
        error = errno;
    } else if (::fsync(fd) != 0 && errno != EINVAL) {
        step = "cannot flush ";
        error = errno;
    }
    // NFS and some FUSE file systems report a failed write only at close.
    if (::close(fd) != 0 && step.empty()) {
        step = "cannot write ";
        error = errno;
    }
    if (!step.empty()) {
        ::unlink(temp.c_str());
        failed(file, step + temp.filename().string(), error);
    }
    if (::rename(temp.c_str(), file.c_str()) != 0) {
        const int why = errno;
        ::unlink(temp.c_str());
        failed(file, "cannot rename " + temp.filename().string() + " over it", why);
    }
}

}  // namespace arcomp
