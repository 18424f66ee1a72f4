#pragma once
// The tracker's people (video/matte/PersonTracker.hpp) as visitors on the
// floor: each one's place in metres, velocity, height and age, and who
// entered and left, frame by frame (runtime/people/PeopleFrame.hpp).
//
//   FloorPeople floor(cfg.camera.calibrated, videoSize);
//   const PeopleFrame& now = floor.update(tracker.people(), scale, frameNumber, videoSeconds, true);
//
// With a calibrated camera a foot point's ray meets the floor. The feet the
// camera sees are a person's near side: their middle stands about half a
// body's depth farther away, along the floor from the camera, and is moved
// there (the people bench reports what bias remains). Height: the blob's top
// row, met on the upright plane through that middle, facing the camera.
// Without a calibration, positions are the foot point in the picture,
// normalised to 0..1.
// A person is published from the first frame their feet were in the
// picture; while the tracker holds them unseen (hidden, merged with
// someone), they keep their last place and velocity, marked not seen.
// Velocities are per second of video time, smoothed over a few frames.

#include "graph/camera/CalibratedCamera.hpp"
#include "runtime/people/PeopleFrame.hpp"
#include "video/matte/PersonTracker.hpp"

#include <glm/glm.hpp>

#include <cstdint>
#include <optional>
#include <unordered_map>
#include <vector>

namespace arcomp {

class FloorPeople {
public:
    struct Settings {
        float bodyDepthMetres = 0.3f;    // front to back, at the feet
        float velocitySmoothing = 0.3f;  // share of the newest step in the velocity
        float heightSmoothing = 0.2f;    // share of the newest frame in the height
    };

    // `camera` at any resolution (its intrinsics are scaled to `size`, the
    // video's); none for positions in the picture.
    FloorPeople(const std::optional<CalibratedCamera>& camera, glm::ivec2 size) : FloorPeople(camera, size, {}) {}
    FloorPeople(const std::optional<CalibratedCamera>& camera, glm::ivec2 size, Settings settings);

    // `tracks`: the tracker's people, in tracking pixels of `scale` frame
    // pixels each. On a frame whose video did not change (`newFrame`
    // false), the people stay where they were, only their ages move on, and
    // nobody enters or leaves.
    const PeopleFrame& update(const std::vector<TrackedPerson>& tracks, int scale, std::uint64_t frame, double seconds,
                              bool newFrame);
    const PeopleFrame& people() const { return now_; }

private:
    struct Followed {
        double since = 0.0, measuredAt = 0.0;  // video seconds: entered, last measured
        glm::vec2 position{0.0f}, velocity{0.0f};
        float height = 0.0f;
        PixelBox box;
        glm::vec2 picture{0.0f};              // the foot point, 0..1
        bool placed = false, moving = false;  // a position measured; a velocity measured
    };
    // The middle of a person whose feet are at `foot` (frame pixels); none
    // when the foot's ray misses the floor.
    std::optional<glm::dvec3> middleOnFloor(glm::vec2 foot) const;
    // How tall a person standing at `middle` is whose blob is `box`; none
    // when their head is out of the picture.
    std::optional<float> heightAt(const glm::dvec3& middle, glm::vec2 foot, const PixelBox& box) const;
    void moveTo(Followed& f, glm::vec2 position, double seconds) const;

    std::optional<CalibratedCamera> camera_;
    glm::vec2 size_;
    Settings settings_;
    std::unordered_map<int, Followed> followed_;  // by track id
    PeopleFrame now_;
};

// A tracking pixel's centre in frame pixels, tracking at 1 / `scale` of the frame.
glm::vec2 framePixel(cv::Point2f trackingPixel, int scale);

}  // namespace arcomp
