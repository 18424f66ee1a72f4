#include "runtime/people/FloorPeople.hpp"

#include <algorithm>

namespace arcomp {

const char* unitsName(PositionUnits units) { return units == PositionUnits::FloorMetres ? "floor_m" : "image"; }

glm::vec2 framePixel(cv::Point2f trackingPixel, int scale) {
    const float offset = 0.5f * static_cast<float>(scale - 1);
    return {trackingPixel.x * static_cast<float>(scale) + offset, trackingPixel.y * static_cast<float>(scale) + offset};
}

FloorPeople::FloorPeople(const std::optional<CalibratedCamera>& camera, glm::ivec2 size, Settings settings)
    : size_(glm::vec2(size)), settings_(settings) {
    if (camera) {
        camera_ = camera;
        camera_->intrinsics = camera->intrinsics.scaledTo(size);
    }
    now_.units = camera_ ? PositionUnits::FloorMetres : PositionUnits::ImageNormalised;
}

std::optional<glm::dvec3> FloorPeople::middleOnFloor(glm::vec2 foot) const {
    const std::optional<glm::dvec3> near = camera_->floorPointAt(glm::dvec2(foot));
    if (!near) return std::nullopt;
    glm::dvec3 away = *near - camera_->position();
    away.y = 0.0;
    const double length = glm::length(away);
    if (length < 1e-9) return near;  // straight below the lens: no way is away
    return *near + away * (0.5 * settings_.bodyDepthMetres / length);
}

std::optional<float> FloorPeople::heightAt(const glm::dvec3& middle, glm::vec2 foot, const PixelBox& box) const {
    if (box.y <= 0) return std::nullopt;  // the blob reaches the top edge: the head is cut off
    const glm::dvec3 lens = camera_->position();
    glm::dvec3 facing = middle - lens;
    facing.y = 0.0;
    const glm::dvec3 ray = camera_->rayThrough({foot.x, static_cast<double>(box.y)});
    const double across = glm::dot(facing, ray);
    if (across <= 1e-9) return std::nullopt;
    const double top = lens.y + ray.y * glm::dot(facing, facing) / across;
    if (top <= 0.0) return std::nullopt;
    return static_cast<float>(top);
}

void FloorPeople::moveTo(Followed& f, glm::vec2 position, double seconds) const {
    const double dt = seconds - f.measuredAt;
    if (f.placed && dt > 0.0) {
        const glm::vec2 step = (position - f.position) / static_cast<float>(dt);
        f.velocity = f.moving ? glm::mix(f.velocity, step, settings_.velocitySmoothing) : step;
        f.moving = true;
    }
    f.position = position;
    f.measuredAt = seconds;
    f.placed = true;
}

const PeopleFrame& FloorPeople::update(const std::vector<TrackedPerson>& tracks, int scale, std::uint64_t frame,
                                       double seconds, bool newFrame) {
    now_.frame = frame;
    now_.seconds = seconds;
    now_.entered.clear();
    now_.left.clear();
    if (!newFrame) {
        for (Person& p : now_.people) p.ageSeconds = seconds - followed_.at(p.id).since;
        return now_;
    }

    std::unordered_map<int, Followed> followed;
    for (const TrackedPerson& t : tracks) {
        Followed f;
        if (const auto known = followed_.find(t.id); known != followed_.end()) f = known->second;
        const bool published = f.placed;
        const glm::vec2 foot = framePixel(t.foot, scale);
        f.box = {t.box.x * scale, t.box.y * scale, t.box.width * scale, t.box.height * scale};
        if (t.missed == 0 && t.feetVisible) {
            f.picture = foot / size_;
            if (!camera_) {
                moveTo(f, foot / size_, seconds);
            } else if (const std::optional<glm::dvec3> middle = middleOnFloor(foot)) {
                moveTo(f, {static_cast<float>(middle->x), static_cast<float>(middle->z)}, seconds);
                if (const std::optional<float> height = heightAt(*middle, foot, f.box))
                    f.height = f.height > 0.0f ? glm::mix(f.height, *height, settings_.heightSmoothing) : *height;
            }
        }
        if (!published) f.since = seconds;  // enters, and is aged from, the frame it is first placed
        followed[t.id] = f;
    }

    std::vector<int> before;
    for (const Person& p : now_.people) before.push_back(p.id);
    now_.people.clear();
    for (const TrackedPerson& t : tracks) {
        const Followed& f = followed[t.id];
        if (!f.placed) continue;
        now_.people.push_back({.id = t.id,
                               .ageSeconds = seconds - f.since,
                               .seen = t.missed == 0,
                               .position = f.position,
                               .velocity = f.velocity,
                               .heightMetres = f.height,
                               .box = f.box,
                               .picture = f.picture,
                               .zones = {}});
    }
    std::sort(now_.people.begin(), now_.people.end(), [](const Person& a, const Person& b) { return a.id < b.id; });
    for (const Person& p : now_.people)
        if (!std::binary_search(before.begin(), before.end(), p.id)) now_.entered.push_back(p.id);
    for (const int id : before)
        if (!findPerson(now_, id)) now_.left.push_back(id);
    followed_ = std::move(followed);
    return now_;
}

}  // namespace arcomp
