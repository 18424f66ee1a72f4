#pragma once
// The station the whole-pipeline benches run when given no config: the demo
// scene (three shapes, MOG2 matte) composited over vtest.avi, or over a
// clip generated into `dir` on machines without opencv-doc.
//
//   const std::string video = demoVideo(dir, "bench soak");   // says on stderr when it generates
//   std::ofstream(dir / "station.yaml") << demoStationYaml(video);

#include <filesystem>
#include <string>

namespace arcomp {

inline constexpr const char* kDemoVideo = "/usr/share/doc/opencv-doc/examples/data/vtest.avi";

// `preferred` when it exists; otherwise a generated clip in `dir`.
std::string demoVideo(const std::filesystem::path& dir, const std::string& bench,
                      const std::string& preferred = kDemoVideo);
std::string demoStationYaml(const std::string& video);

}  // namespace arcomp
