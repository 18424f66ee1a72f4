#include "runtime/PersonDepthStage.hpp"

#include <opencv2/imgproc.hpp>

#include <algorithm>

namespace arcomp {

namespace {

constexpr int kMaxTrackingWidth = 960;

PersonTracker::Settings trackingAt(int scale) {
    PersonTracker::Settings s;
    s.maxStepPx /= static_cast<float>(scale);
    return s;
}

} // namespace

PersonDepthStage::PersonDepthStage(const std::optional<CalibratedCamera>& camera, float personPlaneMetres,
                                   glm::ivec2 size)
    : plane_(personPlaneMetres), scale_(std::max(1, (size.x + kMaxTrackingWidth - 1) / kMaxTrackingWidth)),
      tracker_(trackingAt(scale_)) {
    depths_.metres.fill(plane_);
    if (!camera) return;
    camera_ = camera;
    camera_->intrinsics = camera->intrinsics.scaledTo(size);
    depths_.slotScale = scale_;
}

void PersonDepthStage::run(const cv::Mat& person, bool newFrame) {
    if (!camera_ || (!newFrame && !alpha_.empty())) return;
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

    std::unordered_map<int, float> kept;
    standing_.clear();
    for (const TrackedPerson& p : people) {
        // The tracking pixel's centre in frame pixels.
        const float offset = 0.5f * static_cast<float>(scale_ - 1);
        const glm::vec2 foot(p.foot.x * static_cast<float>(scale_) + offset, p.foot.y * static_cast<float>(scale_) + offset);
        bool measured = false;
        if (p.missed == 0 && p.feetVisible) {
            if (const std::optional<glm::dvec3> floor = camera_->floorPointAt(glm::dvec2(foot))) {
                const double depth = camera_->depthOf(*floor);
                if (depth > 0.0) lastDepth_[p.id] = static_cast<float>(depth);
                measured = depth > 0.0;
            }
        }
        const auto d = lastDepth_.find(p.id);
        if (d != lastDepth_.end()) kept.insert(*d);
        if (p.missed == 0)
            standing_.push_back({.id = p.id,
                                 .foot = foot,
                                 .metres = d != lastDepth_.end() ? d->second : plane_,
                                 .depth = measured                 ? StandingPerson::Depth::Measured
                                          : d != lastDepth_.end() ? StandingPerson::Depth::Kept
                                                                  : StandingPerson::Depth::Plane});
    }
    lastDepth_ = std::move(kept);  // tracks that ended forget their depth
    assignSlots();
}

void PersonDepthStage::assignSlots() {
    depths_.slots.create(alpha_.size(), CV_8UC1);
    depths_.slots.setTo(0);
    depths_.people = 0;
    const cv::Mat& labels = tracker_.labels();
    for (const TrackedPerson& p : tracker_.people()) {
        if (p.label == 0 || depths_.people == PersonDepths::kMaxPeople) continue;
        const int slot = ++depths_.people;
        const auto d = lastDepth_.find(p.id);
        depths_.metres[static_cast<std::size_t>(slot)] = d != lastDepth_.end() ? d->second : plane_;
        for (int y = p.box.y; y < p.box.br().y; ++y) {
            const int* in = labels.ptr<int>(y);
            std::uint8_t* out = depths_.slots.ptr<std::uint8_t>(y);
            for (int x = p.box.x; x < p.box.br().x; ++x)
                if (in[x] == p.label) out[x] = static_cast<std::uint8_t>(slot);
        }
    }
    // Tracking takes alpha above half; the matte's soft edge around a blob
    // belongs to the same person, not to the plane.
    if (depths_.people > 0) cv::dilate(depths_.slots, depths_.slots, cv::getStructuringElement(cv::MORPH_RECT, {9, 9}));
}

} // namespace arcomp
