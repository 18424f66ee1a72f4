#pragma once
// The config sections of a compositing station: `video` (where frames come
// from), `matte` (how the person is cut from them), `compositor` (where the
// person stands among the CG) and `output` (where composited frames go).
// Field-by-field documentation: configs/README.md. An absent section keeps
// the station as it was without it: no video, no matte, nothing written.
//
//   readCompositingConfig(root, cfg.compositing);   // inside loadStationConfig

#include "runtime/config/StreamConfig.hpp"
#include "video/matte/MatteSpec.hpp"
#include "video/sources/SourceSpec.hpp"
#include "video/streams/H264Settings.hpp"

#include <glm/glm.hpp>

#include <filesystem>
#include <optional>
#include <vector>

namespace arcomp {

class YamlMap;

// Which mesh cuts the person where a CG object stands in front: the
// silhouette mesh of the viewpoint region holding the camera (cheap), or the
// full mesh (the reference).
enum class HoldoutMesh { Silhouette, Full };

// Contact shadows: CG objects darken the video's floor (y = 0) where they
// shade it from the light.
struct ShadowConfig {
    std::optional<bool> enabled;  // unset: on with a calibrated camera (the floor is known), off without
    glm::vec3 light = glm::normalize(glm::vec3(-0.4f, 0.8f, 0.45f));  // towards the light, floor frame, unit length
    float strength = 0.45f;  // the full shadow keeps 1 - strength of the video's light
};

struct CompositorConfig {
    // The person layer stands on a plane this far along the camera's view
    // axis; CG objects whose centre is nearer are in front of the person.
    float personPlaneMetres = 5.0f;
    // With a calibrated camera each person stands where their feet meet
    // the floor; false puts everyone on the plane (a camera that does not
    // see the floor, or to compare).
    bool personDepthFromFeet = true;
    // The silhouette meshes are baked for eyes within a box this many metres
    // either side of the camera position, in each axis.
    float holdoutRegionMetres = 0.5f;
    HoldoutMesh holdout = HoldoutMesh::Silhouette;
    // Baked silhouette meshes and generated LOD levels are kept here and
    // loaded at the next start when they match the model (and region).
    // Empty: systemd's cache folder for a service, else the user's
    // (~/.cache/arcomp); "none": bake at every start.
    std::filesystem::path bakeCache;
    // What lies behind everything: the video frame itself, or a colour
    // (studio chroma key, where the backing must not show).
    bool backdropVideo = true;
    glm::vec4 backdropColor{0.0f, 0.0f, 0.0f, 1.0f};
    ShadowConfig shadow;
};

struct OutputConfig {
    std::filesystem::path pngDir;  // frame-000000.png ...; empty: none
    // empty: none. .mp4 (fragmented), .m4v, .mov or .mkv: H.264 through
    // GStreamer (video/streams/H264Recording.hpp); any other: OpenCV's
    // writer with videoFourcc.
    std::filesystem::path videoFile;
    std::string videoFileAt;  // "station.yaml:5:3", for what only the machine can say (no encoder)
    std::string videoFourcc = "MJPG";
    H264Settings videoEncoding{};
    std::vector<StreamConfig> streams;  // SRT and RTSP out, beside the files
    std::filesystem::path matteDir;     // the matte's alpha per frame, for inspection; empty: none
    std::filesystem::path events;       // the zone events as JSON Lines (runtime/station/EventLog.hpp); empty: none
    bool window = false;                // for `arcomp run`; replay ignores it
};

struct CompositingConfig {
    std::optional<SourceSpec> video;  // absent: no video section
    MatteSpec matte;
    CompositorConfig compositor;
    OutputConfig output;
};

void readCompositingConfig(YamlMap& root, CompositingConfig& out);

}  // namespace arcomp
