#pragma once
// Debian's opencv-doc ships the real videos the tests replay; tests that
// use one skip when it is absent.

#include <string>

namespace arcomp::test {

inline const std::string kOpencvData = "/usr/share/doc/opencv-doc/examples/data/";
inline const std::string kVtest = kOpencvData + "vtest.avi";

}  // namespace arcomp::test
