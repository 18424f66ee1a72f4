#pragma once
// Parsing the small value formats the command line takes ("640x480",
// "1,2,3"); each throws InputError naming the option and what was expected.

#include "runtime/gl/FrameTimer.hpp"

#include <glm/glm.hpp>

#include <string>

namespace arcomp {

glm::ivec2 parseSize(const std::string& text, const std::string& option);
glm::vec3 parseVec3(const std::string& text, const std::string& option);
// finish, cpu, query or auto (runtime/gl/FrameTimer.hpp).
TimerMode parseTimerMode(const std::string& text, const std::string& option);
inline constexpr const char* kTimerModeHelp =
    "finish (wall clock to glFinish), cpu (this process's CPU time to glFinish: llvmpipe's busy time, "
    "without other programs' share of the cores), auto or query (GL_TIME_ELAPSED where available; on "
    "llvmpipe it leaves out most of the work)";

}  // namespace arcomp
