#include "runtime/station/GazeSource.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <iterator>

namespace arcomp {

FixedGaze::FixedGaze(const glm::vec3& eye, const glm::vec3& direction) {
    gaze_.eye = eye;
    gaze_.direction = glm::length(direction) > 0.0f ? glm::normalize(direction) : glm::vec3(0, 0, -1);
}

std::optional<GazeSample> FixedGaze::sample(double timeSeconds) {
    GazeSample g = gaze_;
    g.time = timeSeconds;
    return g;
}

void HeadPoseGaze::setPose(const glm::mat4& headToWorld) {
    const glm::vec3 forward = -glm::vec3(headToWorld[2]);
    if (glm::length(forward) <= 0.0f) return;  // a degenerate pose keeps the last good one
    gaze_ = GazeSample{0.0, glm::vec3(headToWorld[3]), glm::normalize(forward)};
}

std::optional<GazeSample> HeadPoseGaze::sample(double timeSeconds) {
    if (!gaze_) return std::nullopt;
    GazeSample g = *gaze_;
    g.time = timeSeconds;
    return g;
}

TrackerGaze::TrackerGaze(Poll poll, const glm::mat4& trackerToWorld)
    : poll_(std::move(poll)), toWorld_(trackerToWorld) {}

std::optional<GazeSample> TrackerGaze::sample(double timeSeconds) {
    std::optional<GazeSample> s = poll_ ? poll_() : std::nullopt;
    if (!s) return std::nullopt;
    const glm::vec3 direction = glm::mat3(toWorld_) * s->direction;
    if (!(glm::length(direction) > 0.0f)) return std::nullopt;
    return GazeSample{timeSeconds, glm::vec3(toWorld_ * glm::vec4(s->eye, 1.0f)), glm::normalize(direction)};
}

RecordedGaze::RecordedGaze(std::vector<GazeSample> samples) : samples_(std::move(samples)) {}

std::optional<GazeSample> RecordedGaze::sample(double timeSeconds) {
    if (samples_.empty()) return std::nullopt;
    if (timeSeconds <= samples_.front().time) return samples_.front();
    if (timeSeconds >= samples_.back().time) return samples_.back();
    const auto next = std::upper_bound(samples_.begin(), samples_.end(), timeSeconds,
                                       [](double t, const GazeSample& s) { return t < s.time; });
    const GazeSample& a = *(next - 1);
    const GazeSample& b = *next;
    const auto u = static_cast<float>((timeSeconds - a.time) / (b.time - a.time));
    const glm::vec3 direction = glm::mix(a.direction, b.direction, u);
    // Opposite directions blend to zero halfway; hold the earlier one there.
    const float length = glm::length(direction);
    return GazeSample{timeSeconds, glm::mix(a.eye, b.eye, u), length > 1e-6f ? direction / length : a.direction};
}

GazeTrackError::GazeTrackError(std::string file_, std::size_t line_, std::string reason_)
    : BadInput(file_, line_ == 0 ? "" : "line " + std::to_string(line_), reason_,
               file_ + ":" + std::to_string(line_) + ": " + reason_),
      file(std::move(file_)), line(line_) {}

namespace {

std::string_view trimmed(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
    return s;
}

constexpr const char* kFieldNames[7] = {"time", "eye_x", "eye_y", "eye_z", "gaze_x", "gaze_y", "gaze_z"};

}  // namespace

std::vector<GazeSample> parseGazeTrackCsv(std::string_view text, const std::string& name) {
    std::vector<GazeSample> samples;
    std::size_t lineNumber = 0;
    bool sawData = false;
    while (!text.empty()) {
        const std::size_t cut = text.find('\n');
        const std::string_view raw = text.substr(0, cut);
        text = cut == std::string_view::npos ? std::string_view{} : text.substr(cut + 1);
        ++lineNumber;
        const std::string_view line = trimmed(raw);
        if (line.empty() || line.front() == '#') continue;
        if (!sawData && samples.empty() && line.starts_with("time")) continue;  // the header
        sawData = true;
        const auto fail = [&](const std::string& reason) { throw GazeTrackError(name, lineNumber, reason); };

        double values[7];
        std::string_view rest = line;
        for (int f = 0; f < 7; ++f) {
            const std::size_t comma = rest.find(',');
            if (f < 6 && comma == std::string_view::npos)
                fail("expected 7 comma-separated fields (time, eye xyz, gaze xyz), found " + std::to_string(f + 1));
            if (f == 6 && comma != std::string_view::npos) fail("expected 7 fields, found more");
            const std::string_view field = trimmed(rest.substr(0, comma));
            rest = comma == std::string_view::npos ? std::string_view{} : rest.substr(comma + 1);
            const auto [end, ec] = std::from_chars(field.data(), field.data() + field.size(), values[f]);
            if (field.empty() || ec != std::errc{} || end != field.data() + field.size())
                fail(std::string(kFieldNames[f]) + ": \"" + std::string(field.substr(0, 32)) + "\" is not a number");
            if (!std::isfinite(values[f])) fail(std::string(kFieldNames[f]) + " is not finite");
        }
        GazeSample s;
        s.time = values[0];
        s.eye = glm::vec3(values[1], values[2], values[3]);
        const glm::dvec3 gaze(values[4], values[5], values[6]);
        const double length = glm::length(gaze);
        if (!(length > 1e-9) || !std::isfinite(length)) fail("gaze direction has no length");
        s.direction = glm::vec3(gaze / length);
        if (!std::isfinite(s.eye.x) || !std::isfinite(s.eye.y) || !std::isfinite(s.eye.z))
            fail("eye position out of range");
        if (!samples.empty() && !(s.time > samples.back().time))
            fail("time " + std::to_string(s.time) + " does not follow " + std::to_string(samples.back().time));
        samples.push_back(s);
    }
    if (samples.empty()) throw GazeTrackError(name, lineNumber, "no samples in the track");
    return samples;
}

std::vector<GazeSample> readGazeTrackCsv(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw GazeTrackError(file.string(), 0, "cannot open");
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    return parseGazeTrackCsv(text, file.string());
}

glm::vec3 gazeThroughPixel(const View& view, glm::vec2 pixel) {
    const glm::vec2 ndc{2.0f * pixel.x / static_cast<float>(view.viewport.x) - 1.0f,
                        1.0f - 2.0f * pixel.y / static_cast<float>(view.viewport.y)};
    const glm::mat4 inverse = glm::inverse(view.viewProjection());
    const glm::vec4 near = inverse * glm::vec4(ndc, -1.0f, 1.0f);
    const glm::vec4 far = inverse * glm::vec4(ndc, 1.0f, 1.0f);
    const glm::vec3 d = glm::vec3(far) / far.w - glm::vec3(near) / near.w;
    return glm::length(d) > 0.0f ? glm::normalize(d) : view.forward;
}

std::unique_ptr<GazeSource> makeGazeSource(const GazeConfig& config, const View& view) {
    switch (config.kind) {
    case GazeKind::ScreenCentre: return nullptr;
    case GazeKind::Fixed: return std::make_unique<FixedGaze>(view.eye, glm::normalize(config.direction));
    case GazeKind::Track: return std::make_unique<RecordedGaze>(readGazeTrackCsv(config.track));
    }
    return nullptr;
}

}  // namespace arcomp
