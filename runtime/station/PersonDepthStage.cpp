#include "runtime/station/PersonDepthStage.hpp"

#include "runtime/people/FloorPeople.hpp"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <map>

namespace arcomp {

namespace {

constexpr int kMaxTrackingWidth = 480;
constexpr int kSoftEdgePx = 4;  // how far, in frame pixels, a person's soft edge reaches beyond alpha one half

PersonTracker::Settings trackingAt(int scale) {
    PersonTracker::Settings s;
    s.maxStepPx /= static_cast<float>(scale);
    return s;
}

}  // namespace

PersonDepthStage::PersonDepthStage(const std::optional<CalibratedCamera>& camera, float personPlaneMetres,
                                   glm::ivec2 size)
    : plane_(personPlaneMetres), scale_(std::max(1, (size.x + kMaxTrackingWidth - 1) / kMaxTrackingWidth)),
      tracker_(trackingAt(scale_)) {
    depths_ = PersonDepths::everyoneAt(plane_);
    if (!camera) return;
    camera_ = camera;
    camera_->intrinsics = camera->intrinsics.scaledTo(size);
    depths_.slotScale = scale_;
}

glm::vec3 PersonDepthStage::cardThrough(const glm::dvec3& feet) const {
    // The card's normal: level, from the camera towards the feet.
    glm::dvec3 towards = feet - camera_->position();
    towards.y = 0.0;
    if (glm::length(towards) < 1e-6) return {0.0f, 0.0f, static_cast<float>(1.0 / camera_->depthOf(feet))};
    const glm::dvec3 n = camera_->rotation * glm::normalize(towards);               // camera axes
    const double d = glm::dot(n, camera_->rotation * feet + camera_->translation);  // the card: n . X = d
    // A pixel's ray is s ((u - cx) / fx, (v - cy) / fy, 1) at depth s, and meets the card where 1 / s = n . ray / d.
    const CameraIntrinsics& k = camera_->intrinsics;
    return glm::vec3(static_cast<float>(n.x / (k.fx * d)), static_cast<float>(n.y / (k.fy * d)),
                     static_cast<float>((n.z - n.x * k.cx / k.fx - n.y * k.cy / k.fy) / d));
}

void PersonDepthStage::run(const cv::Mat& person, bool newFrame) {
    if (!newFrame && !alpha_.empty()) return;
    CV_Assert(person.type() == CV_8UC4);
    // The alpha of every scale-th pixel: the tracking image, rounded up so
    // that every frame pixel has a tracking pixel.
    alpha_.create((person.rows + scale_ - 1) / scale_, (person.cols + scale_ - 1) / scale_, CV_8UC1);
    for (int y = 0; y < alpha_.rows; ++y) {
        const std::uint8_t* in = person.ptr<std::uint8_t>(std::min(y * scale_, person.rows - 1));
        std::uint8_t* out = alpha_.ptr<std::uint8_t>(y);
        for (int x = 0; x < alpha_.cols; ++x) out[x] = in[4 * std::min(x * scale_, person.cols - 1) + 3];
    }
    const std::vector<TrackedPerson>& people = tracker_.update(alpha_);
    // Without a calibration everyone stands on the plane; the tracks are
    // still followed, for the people the station publishes in the picture.
    if (!camera_) return;

    std::unordered_map<int, Stand> kept;
    standing_.clear();
    for (const TrackedPerson& p : people) {
        const glm::vec2 foot = framePixel(p.foot, scale_);
        bool measured = false;
        if (p.missed == 0 && p.feetVisible) {
            if (const std::optional<glm::dvec3> floor = camera_->floorPointAt(glm::dvec2(foot))) {
                const double depth = camera_->depthOf(*floor);
                if (depth > 0.0) lastStand_[p.id] = {static_cast<float>(depth), cardThrough(*floor)};
                measured = depth > 0.0;
            }
        }
        const auto d = lastStand_.find(p.id);
        if (d != lastStand_.end()) kept.insert(*d);
        if (p.missed == 0)
            standing_.push_back({.id = p.id,
                                 .foot = foot,
                                 .metres = d != lastStand_.end() ? d->second.metres : plane_,
                                 .depth = measured                ? StandingPerson::Depth::Measured
                                          : d != lastStand_.end() ? StandingPerson::Depth::Kept
                                                                  : StandingPerson::Depth::Plane});
    }
    lastStand_ = std::move(kept);  // tracks that ended forget their depth
    assignSlots();
}

void PersonDepthStage::assignSlots() {
    depths_.slots.create(alpha_.size(), CV_8UC1);
    depths_.slots.setTo(0);
    depths_.people = 0;
    // The people standing in each blob: one, or several walking merged.
    struct Member {
        float footX, halfWidth, metres;
        std::uint8_t slot;
    };
    std::map<int, std::vector<Member>> members;  // by label
    std::map<int, cv::Rect> boxes;
    for (const TrackedPerson& p : tracker_.people()) {
        if (p.label == 0 || depths_.people == PersonDepths::kMaxPeople) continue;
        const int slot = ++depths_.people;
        if (const auto d = lastStand_.find(p.id); d != lastStand_.end()) {
            depths_.metres[static_cast<std::size_t>(slot)] = d->second.metres;
            depths_.inverseDepth[static_cast<std::size_t>(slot)] = d->second.inverseDepth;
        } else {
            depths_.setFlat(slot, plane_);
        }
        members[p.label].push_back({p.merged ? p.predictedFoot().x : p.foot.x, 0.5f * static_cast<float>(p.width),
                                    depths_.metres[static_cast<std::size_t>(slot)], static_cast<std::uint8_t>(slot)});
        if (!p.merged) boxes[p.label] = p.box;
    }
    const cv::Mat& labels = tracker_.labels();
    for (auto& [label, people] : members) {
        const auto box = boxes.find(label);
        if (box == boxes.end()) continue;  // a merged track always shares a seen one's blob; no pixels otherwise
        // A merged blob's pixel goes to the nearest person standing over its
        // column (their own width about their feet), as the nearer person
        // hides the farther; a pixel over nobody's column goes to the person
        // whose feet are nearest across.
        std::sort(people.begin(), people.end(), [](const Member& a, const Member& b) { return a.metres < b.metres; });
        for (int x = box->second.x; x < box->second.br().x; ++x) {
            const float column = static_cast<float>(x);
            const Member* owner = nullptr;
            for (const Member& m : people)
                if (std::abs(m.footX - column) <= m.halfWidth) {
                    owner = &m;
                    break;
                }
            if (!owner) {
                owner = &people.front();
                for (const Member& m : people)
                    if (std::abs(m.footX - column) < std::abs(owner->footX - column)) owner = &m;
            }
            for (int y = box->second.y; y < box->second.br().y; ++y)
                if (labels.at<int>(y, x) == label) depths_.slots.at<std::uint8_t>(y, x) = owner->slot;
        }
    }
    // Tracking takes alpha above half; the matte's soft edge around a blob
    // belongs to the same person, not to the plane (at 2 px, streaks of a
    // walker's edge still showed over the CG in front of them).
    if (depths_.people > 0) {
        const int reach = std::max(1, (kSoftEdgePx + scale_ - 1) / scale_);  // in tracking pixels
        cv::dilate(depths_.slots, depths_.slots,
                   cv::getStructuringElement(cv::MORPH_RECT, {2 * reach + 1, 2 * reach + 1}));
    }
}

}  // namespace arcomp
