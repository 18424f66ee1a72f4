#pragma once
// Runs a program in a child process and tells how it ended, so that a test
// can count a crash instead of dying of it, and can give the child limits
// (a file-size cap standing in for a full disk) that the test itself keeps
// free of.
//
//   ChildResult r = runChild({ARCOMP_BINARY, "check", "bad.yaml"});
//   EXPECT_FALSE(r.crashed()) << r.output;
//   ChildResult full = runChild({ARCOMP_BINARY, "replay", ...}, {.fileSizeLimit = 200'000});
//   ChildResult p = runForked([&] { loadSceneFile(file); return 0; });   // no exec: cheap

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace arcomp::test {

struct ChildLimits {
    // RLIMIT_FSIZE in bytes: writes beyond it fail with EFBIG, as on a full
    // disk (SIGXFSZ is ignored in the child so it sees the error).
    std::optional<rlim_t> fileSizeLimit;
    std::chrono::seconds seconds{180};  // then it is taken for stuck (see runForked)
};

struct ChildResult {
    bool exited = false;  // false: killed by a signal
    int code = -1;        // exit status when exited
    int signal = 0;       // the signal when killed
    std::string output;   // stdout and stderr together

    // A signal, or a sanitizer's report (ASan and UBSan exit with 1 otherwise).
    bool crashed() const {
        return !exited || output.find("ERROR: AddressSanitizer") != std::string::npos ||
               output.find("ERROR: LeakSanitizer") != std::string::npos ||
               output.find("runtime error:") != std::string::npos;
    }
};

namespace detail {

// One try: the child's result, or nothing when it did not finish within
// `limit` (it is killed then).
inline std::optional<ChildResult> forkOnce(const std::function<int()>& body, const ChildLimits& limits,
                                           std::chrono::seconds limit) {
    std::fflush(nullptr);
    int fds[2];
    if (::pipe(fds) != 0) std::abort();
    const pid_t pid = ::fork();
    if (pid < 0) std::abort();
    if (pid == 0) {
        ::dup2(fds[1], STDOUT_FILENO);
        ::dup2(fds[1], STDERR_FILENO);
        ::close(fds[0]);
        ::close(fds[1]);
        if (limits.fileSizeLimit) {
            ::signal(SIGXFSZ, SIG_IGN);
            const rlimit cap{*limits.fileSizeLimit, *limits.fileSizeLimit};
            ::setrlimit(RLIMIT_FSIZE, &cap);
        }
        const int code = body();
        std::fflush(nullptr);
        ::_exit(code);
    }
    ::close(fds[1]);
    ChildResult r;
    std::array<char, 4096> buffer;
    const auto deadline = std::chrono::steady_clock::now() + limit;
    bool finished = false;
    while (!finished) {
        const auto left =
            std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0) break;
        pollfd readable{fds[0], POLLIN, 0};
        if (::poll(&readable, 1, static_cast<int>(left.count())) <= 0) continue;
        const ssize_t n = ::read(fds[0], buffer.data(), buffer.size());
        if (n > 0)
            r.output.append(buffer.data(), static_cast<std::size_t>(n));
        else
            finished = true;  // end of output: the child has exited or closed it
    }
    ::close(fds[0]);
    if (!finished) ::kill(pid, SIGKILL);
    int status = 0;
    ::waitpid(pid, &status, 0);
    if (!finished) return std::nullopt;
    r.exited = WIFEXITED(status);
    r.code = r.exited ? WEXITSTATUS(status) : -1;
    r.signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
    return r;
}

}  // namespace detail

// Runs `body` in a forked child (its return value is the exit code) with
// stdout and stderr captured. The child of a process with threads (OpenCV's
// workers, a tracing library's) can inherit a lock another thread held at
// the fork: GCC 12's AddressSanitizer does not hold its allocator's locks
// across fork(), so such a child waits forever on its first allocation.
// A child that has not finished after `limits.seconds` is killed and run
// once more; a second time it counts as killed, its output ending with why.
inline ChildResult runForked(const std::function<int()>& body, ChildLimits limits = {}) {
    for (int attempt = 0; attempt < 2; ++attempt)
        if (std::optional<ChildResult> r = detail::forkOnce(body, limits, limits.seconds)) return *r;
    ChildResult killed;
    killed.signal = SIGKILL;
    killed.output = "(the child did not finish in " + std::to_string(limits.seconds.count()) + " s, twice)";
    return killed;
}

inline ChildResult runChild(const std::vector<std::string>& argv, ChildLimits limits = {}) {
    // Built before the fork: the child only calls execv.
    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    return runForked(
        [&args] {
            ::execv(args[0], args.data());
            return 127;
        },
        limits);
}

}  // namespace arcomp::test
