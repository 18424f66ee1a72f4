#pragma once
// Where the viewer looks, for the gaze-directed LOD policies: one interface,
// GazeSource::sample(time), over a fixed direction, the head pose's forward
// vector, a recorded track for replay, or a live eye tracker. (The mouse
// source lives with the window in runtime/: it turns the cursor into a
// direction with gazeThroughPixel() and serves it through this interface.)
//
//   RecordedGaze track(readGazeTrackCsv("session.csv"));   // throws GazeTrackError
//   if (auto g = track.sample(t)) settings.gaze = g->direction;
//   std::unique_ptr<GazeSource> g = makeGazeSource(cfg.gaze, view);   // null: screen centre
//
// Track CSV: one sample a line, `time,eye_x,eye_y,eye_z,gaze_x,gaze_y,gaze_z`
// (seconds, world units, a world direction of any non-zero length); an
// optional header line starting with "time", blank lines and '#' comments.
// Times must increase strictly.

#include "graph/core/BadInput.hpp"
#include "graph/core/View.hpp"
#include "runtime/config/GazeConfig.hpp"

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace arcomp {

struct GazeSample {
    double time = 0.0;
    glm::vec3 eye{0.0f};
    glm::vec3 direction{0.0f, 0.0f, -1.0f};  // unit, world
};

class GazeSource {
public:
    virtual ~GazeSource() = default;
    // The gaze at `timeSeconds` on the station's clock; nothing when the
    // source has none (a tracker that lost the eyes): the caller falls back
    // to the view's forward direction.
    virtual std::optional<GazeSample> sample(double timeSeconds) = 0;
};

// A direction set in the config, e.g. to test a station without a tracker.
class FixedGaze : public GazeSource {
public:
    FixedGaze(const glm::vec3& eye, const glm::vec3& direction);
    std::optional<GazeSample> sample(double timeSeconds) override;

private:
    GazeSample gaze_;
};

// The head's forward vector standing in for the eyes, as in the paper.
// setPose takes the head-to-world matrix; its -Z axis is forward.
class HeadPoseGaze : public GazeSource {
public:
    void setPose(const glm::mat4& headToWorld);
    std::optional<GazeSample> sample(double timeSeconds) override;

private:
    std::optional<GazeSample> gaze_;
};

// A live eye tracker: `poll` returns the newest sample in the tracker's own
// frame (or nothing), `trackerToWorld` places that frame in the scene.
class TrackerGaze : public GazeSource {
public:
    using Poll = std::function<std::optional<GazeSample>()>;
    TrackerGaze(Poll poll, const glm::mat4& trackerToWorld);
    std::optional<GazeSample> sample(double timeSeconds) override;

private:
    Poll poll_;
    glm::mat4 toWorld_;
};

// A recorded track, replayed: linear between samples, held at the ends.
class RecordedGaze : public GazeSource {
public:
    explicit RecordedGaze(std::vector<GazeSample> samples);  // as readGazeTrackCsv gives them
    std::optional<GazeSample> sample(double timeSeconds) override;
    const std::vector<GazeSample>& samples() const { return samples_; }

private:
    std::vector<GazeSample> samples_;
};

// A track file that cannot be used; what() reads "<file>:<line>: <reason>",
// the form config issues take. As BadInput: source the file, where
// "line N" (empty for the file as a whole, line 0).
class GazeTrackError : public BadInput {
public:
    GazeTrackError(std::string file, std::size_t line, std::string reason);
    std::string file;  // the same as source
    std::size_t line;
};

std::vector<GazeSample> readGazeTrackCsv(const std::filesystem::path& file);
// The same on text in memory; `name` stands for the file in errors.
std::vector<GazeSample> parseGazeTrackCsv(std::string_view text, const std::string& name);

// The world direction through a pixel of the view (origin top left), for a
// mouse standing in for the eyes.
glm::vec3 gazeThroughPixel(const View& view, glm::vec2 pixel);

// The source a config's `gaze` section names; null for the screen centre.
// Throws GazeTrackError (with the file and line) for a bad track.
std::unique_ptr<GazeSource> makeGazeSource(const GazeConfig& config, const View& view);

}  // namespace arcomp
