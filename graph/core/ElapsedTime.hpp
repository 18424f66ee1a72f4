#pragma once
// Milliseconds for timing a stage of a frame or a benchmark: wall time on
// the steady clock, and the CPU time of the whole process (all its threads),
// which other programs' use of the machine's cores does not inflate.
//
//   const auto t0 = std::chrono::steady_clock::now();
//   const double c0 = processCpuMs();
//   ... work ...
//   double wall = msSince(t0), cpu = processCpuMs() - c0;

#include <chrono>
#include <ctime>

namespace arcomp {

inline double msSince(std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count();
}

inline double processCpuMs() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) * 1e-6;
}

}  // namespace arcomp
