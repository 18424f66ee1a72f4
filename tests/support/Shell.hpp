#pragma once
// Runs a command line as a script would, for the tests of the arcomp and
// arcomp-bench executables: exit code and output (stderr folded in unless
// asked not to).
//
//   const ShellResult r = arcompCommand("check configs/demo-replay.yaml");
//   EXPECT_EQ(r.code, 0) << r.out;
//   const ShellResult b = benchCommand("load --repeats 1 --model bunny.obj");

#include <array>
#include <cstdio>
#include <string>
#include <sys/wait.h>

namespace arcomp::test {

struct ShellResult {
    int code = -1;  // -1: did not exit normally (a crash or a signal)
    std::string out;
};

inline ShellResult shell(const std::string& command, bool withStderr = true) {
    ShellResult r;
    FILE* pipe = popen((command + (withStderr ? " 2>&1" : " 2>/dev/null")).c_str(), "r");
    if (!pipe) return r;
    std::array<char, 4096> buffer;
    while (std::size_t n = std::fread(buffer.data(), 1, buffer.size(), pipe)) r.out.append(buffer.data(), n);
    const int status = pclose(pipe);
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

inline ShellResult arcompCommand(const std::string& args, bool withStderr = true) {
    return shell(std::string(ARCOMP_BINARY) + " " + args, withStderr);
}

inline ShellResult benchCommand(const std::string& args, bool withStderr = true) {
    return shell(std::string(ARCOMP_BENCH_BINARY) + " " + args, withStderr);
}

// The last non-empty line: where a benchmark prints its JSON.
inline std::string lastLine(const std::string& text) {
    const std::size_t end = text.find_last_not_of('\n');
    if (end == std::string::npos) return {};
    const std::size_t start = text.rfind('\n', end);
    return text.substr(start == std::string::npos ? 0 : start + 1,
                       end - (start == std::string::npos ? 0 : start + 1) + 1);
}

}  // namespace arcomp::test
