#include "runtime/config/GazeConfig.hpp"

#include "runtime/config/YamlMap.hpp"

namespace arcomp {

void readGazeConfig(YamlMap& root, GazeConfig& out) {
    YamlMap gaze = root.map("gaze");
    std::string source = "screen_centre";
    gaze.choice("source", source, {"screen_centre", "fixed", "track"});
    out.kind = source == "fixed" ? GazeKind::Fixed : source == "track" ? GazeKind::Track : GazeKind::ScreenCentre;
    gaze.vec3("direction", out.direction, out.kind == GazeKind::Fixed ? Required::Yes : Required::No);
    gaze.path("track", out.track, true, out.kind == GazeKind::Track ? Required::Yes : Required::No);
    if (out.kind == GazeKind::Fixed && glm::length(out.direction) == 0.0f)
        gaze.report().add(gaze.mark(), "gaze.direction: must not be zero");
    gaze.finish();
}

}  // namespace arcomp
