#pragma once
// ARCOMP_CHECK(condition, why): for broken invariants, the program's own
// mistakes, never for bad input (that is an exception that names the file
// and the place). A failed check writes the file, the line, the condition
// and why to stderr before it aborts, so the station's log says what broke.
//
//   ARCOMP_CHECK(parent < id, "parents exist before children");

#include <cstdio>
#include <cstdlib>

namespace arcomp::detail {

[[noreturn]] inline void checkFailed(const char* file, int line, const char* condition, const char* why) {
    std::fprintf(stderr, "arcomp: broken invariant at %s:%d: %s (%s)\n", file, line, condition, why);
    std::fflush(stderr);
    std::abort();
}

}  // namespace arcomp::detail

#define ARCOMP_CHECK(condition, why)                                                                                   \
    do {                                                                                                               \
        if (!(condition)) [[unlikely]]                                                                                 \
            ::arcomp::detail::checkFailed(__FILE__, __LINE__, #condition, why);                                        \
    } while (false)
