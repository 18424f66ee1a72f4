#pragma once
// The people in a matte, followed from frame to frame. Each blob of the
// alpha above a minimum area is a person; where their feet touch the floor
// (the foot point) is what a calibrated camera turns into their distance.
// Tracks keep an id and a smoothed foot point, so that the distance does
// not jump when the matte flickers, and outlive a few frames without a blob
// (a person hidden, or merged with another).
//
//   PersonTracker tracker;
//   for (const TrackedPerson& p : tracker.update(alphaOf(personLayer)))
//       if (p.feetVisible) use(p.id, p.foot);
//
// Two people who touch become one blob: it continues the track whose
// predicted foot point is nearest, and the other track waits, unmatched,
// for up to `keepMissedFrames`, marked `merged` with the blob's label while
// it is heading through that blob. When they part, the waiting track takes
// the blob that appears near where it was heading, or a new id starts.

#include <opencv2/core.hpp>

#include <vector>

namespace arcomp {

struct TrackedPerson {
    int id = 0;
    cv::Rect box;              // the blob's bounds this frame (the last seen, while missed)
    cv::Point2f foot;          // smoothed, in pixels
    cv::Point2f footVelocity;  // pixels a frame
    bool feetVisible = false;  // false when the blob reaches the bottom edge: the feet are out of the picture
    int missed = 0;            // frames since a blob last matched; 0 when seen this frame
    int label = 0;             // this frame's blob in labels(); 0 while missed, unless merged
    // Missed, but where it was heading lies inside a seen person's blob: the
    // two walk as one blob, and `label` is that blob's. Its foot point is
    // the prediction, foot + footVelocity * missed.
    bool merged = false;
    int width = 0;  // the blob's width, pixels, when last seen alone (not merged with anyone)

    cv::Point2f predictedFoot() const { return foot + footVelocity * static_cast<float>(missed); }
};

class PersonTracker {
public:
    struct Settings {
        double minAreaFraction = 0.001;  // of the frame: smaller blobs are noise
        float maxStepPx = 80.0f;         // farthest a foot point moves between frames
        int keepMissedFrames = 12;
        float smoothing = 0.5f;  // share of the new measurement in the foot point
    };

    PersonTracker() : PersonTracker(Settings{}) {}
    explicit PersonTracker(Settings settings) : settings_(settings) {}

    // alpha: CV_8UC1, > 127 is person. Gives the tracks, seen and missed.
    const std::vector<TrackedPerson>& update(const cv::Mat& alpha);
    const std::vector<TrackedPerson>& people() const { return people_; }
    // This frame's blobs, CV_32S: 0 background, else a track's `label`.
    const cv::Mat& labels() const { return labels_; }

private:
    struct Blob {
        cv::Rect box;
        cv::Point2f foot;
        bool feetVisible;
        int label;
    };
    std::vector<Blob> findBlobs(const cv::Mat& alpha);

    Settings settings_;
    std::vector<TrackedPerson> people_;
    cv::Mat mask_, labels_, stats_, centroids_;
    int nextId_ = 1;
};

// Where a blob stands: its lowest row at least a sixth as wide as its
// median row (a shadow's thin line or a stray pixel below the feet does not
// count), and the median column of the pixels in the tenth of its height
// above that row.
cv::Point2f footPoint(const cv::Mat& labels, int label, const cv::Rect& box);

}  // namespace arcomp
