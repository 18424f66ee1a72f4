#pragma once
// The smallest station the CLI tests replay: one box four metres in front
// of a camera at the origin looking down -Z. Tests append the sections
// they need (video, output, ...).

namespace arcomp::test {

inline constexpr const char* kBoxStation = R"(scene:
  objects:
    - shape: box
      position: [0, 0, -4]
camera:
  eye: [0, 0, 0]
  target: [0, 0, -1]
)";

}  // namespace arcomp::test
