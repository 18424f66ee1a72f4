#pragma once
// Each person's distance, from where their feet meet the floor. The
// matte's blobs are tracked (video/matte/PersonTracker.hpp), with a
// calibrated camera or without (the station publishes its people either
// way, runtime/people/FloorPeople.hpp). With one, each foot point's ray is
// met with the floor (graph/camera/CalibratedCamera.hpp); the point's depth
// along the view axis is that person's. Without one, everyone stands on the
// config's person plane.
//
//   PersonDepthStage depths(cfg.camera.calibrated, personPlaneMetres, videoSize);
//   depths.run(matte.person(), newFrame);
//   compositor.person(matte.person(), depths.depths(), view.projection);
//
// A person whose feet are out of the picture, or whose foot ray misses the
// floor, keeps the last depth measured for their track; a track that never
// had one, and a matte blob too small to track, stands on the plane.
// Tracking runs on the matte at most 480 pixels wide (768x576 at half size,
// 1080p at a quarter): a foot point to a few pixels is plenty (at 10 m,
// 4 px of a 1080p picture are a few centimetres), and the cost falls with
// the square of the scale.
// standing() says, per person seen this frame, where their feet are and
// which distance they got, so that an overlay can show it on the video.

#include "graph/camera/CalibratedCamera.hpp"
#include "runtime/composite/PersonDepths.hpp"
#include "video/matte/PersonTracker.hpp"

#include <glm/glm.hpp>

#include <optional>
#include <unordered_map>
#include <vector>

namespace arcomp {

// A tracked person seen this frame and the distance they are drawn at.
struct StandingPerson {
    enum class Depth { Measured, Kept, Plane };  // from this frame's feet, an earlier frame's, or the person plane
    int id = 0;
    glm::vec2 foot{0.0f};  // frame pixels
    float metres = 0.0f;
    Depth depth = Depth::Plane;
};

class PersonDepthStage {
public:
    PersonDepthStage(const std::optional<CalibratedCamera>& camera, float personPlaneMetres, glm::ivec2 size);

    // `person`: the matte's premultiplied BGRA at the video's size. A frame
    // that did not change keeps the last depths.
    void run(const cv::Mat& person, bool newFrame);
    const PersonDepths& depths() const { return depths_; }
    // The tracks behind the depths, in tracking pixels (frame pixels / scale()).
    const std::vector<TrackedPerson>& people() const { return tracker_.people(); }
    int scale() const { return scale_; }
    // The tracks seen this frame (in the tracker's order), in frame pixels.
    const std::vector<StandingPerson>& standing() const { return standing_; }

private:
    void assignSlots();
    glm::vec3 cardThrough(const glm::dvec3& feet) const;

    std::optional<CalibratedCamera> camera_;  // intrinsics at the video's size
    float plane_;
    int scale_ = 1;
    PersonTracker tracker_;
    cv::Mat alpha_;
    // Where a track last stood: the depth at its feet and its card (runtime/composite/PersonDepths.hpp).
    struct Stand {
        float metres;
        glm::vec3 inverseDepth;
    };
    std::unordered_map<int, Stand> lastStand_;  // by track id
    PersonDepths depths_;
    std::vector<StandingPerson> standing_;
};

}  // namespace arcomp
