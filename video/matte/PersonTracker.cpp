#include "video/matte/PersonTracker.hpp"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <limits>

namespace arcomp {

cv::Point2f footPoint(const cv::Mat& labels, int label, const cv::Rect& box) {
    std::vector<int> rowCounts(static_cast<std::size_t>(box.height), 0);
    for (int y = 0; y < box.height; ++y) {
        const int* row = labels.ptr<int>(box.y + y) + box.x;
        for (int x = 0; x < box.width; ++x) rowCounts[static_cast<std::size_t>(y)] += row[x] == label;
    }
    // The lowest row at least a sixth as wide as the blob's typical row: a
    // shadow's thin line or a stray pixel below the feet is narrower.
    std::vector<int> widths;
    for (int c : rowCounts)
        if (c > 0) widths.push_back(c);
    if (widths.empty()) return {box.x + box.width / 2.0f, static_cast<float>(box.br().y - 1)};
    std::nth_element(widths.begin(), widths.begin() + static_cast<long>(widths.size() / 2), widths.end());
    const int wideEnough = std::max(2, widths[widths.size() / 2] / 6);
    int bottom = box.height - 1;
    while (bottom > 0 && rowCounts[static_cast<std::size_t>(bottom)] < wideEnough) --bottom;
    // The lowest tenth of the blob's height up from there: both feet, not just the lower one.
    const int top = std::max(0, bottom - std::max(1, box.height / 10));
    std::vector<int> columns;
    for (int y = top; y <= bottom; ++y) {
        const int* row = labels.ptr<int>(box.y + y) + box.x;
        for (int x = 0; x < box.width; ++x)
            if (row[x] == label) columns.push_back(x);
    }
    if (columns.empty()) return {box.x + box.width / 2.0f, static_cast<float>(box.y + bottom)};
    std::nth_element(columns.begin(), columns.begin() + static_cast<long>(columns.size() / 2), columns.end());
    return {static_cast<float>(box.x + columns[columns.size() / 2]), static_cast<float>(box.y + bottom)};
}

std::vector<PersonTracker::Blob> PersonTracker::findBlobs(const cv::Mat& alpha) {
    cv::compare(alpha, 127, mask_, cv::CMP_GT);
    const int count = cv::connectedComponentsWithStats(mask_, labels_, stats_, centroids_, 8, CV_32S);
    const double minArea = settings_.minAreaFraction * static_cast<double>(alpha.total());
    std::vector<Blob> blobs;
    for (int i = 1; i < count; ++i) {
        if (stats_.at<int>(i, cv::CC_STAT_AREA) < minArea) continue;
        const cv::Rect box(stats_.at<int>(i, cv::CC_STAT_LEFT), stats_.at<int>(i, cv::CC_STAT_TOP),
                           stats_.at<int>(i, cv::CC_STAT_WIDTH), stats_.at<int>(i, cv::CC_STAT_HEIGHT));
        blobs.push_back({box, footPoint(labels_, i, box), box.br().y < alpha.rows, i});
    }
    return blobs;
}

const std::vector<TrackedPerson>& PersonTracker::update(const cv::Mat& alpha) {
    CV_Assert(alpha.type() == CV_8UC1);
    std::vector<Blob> blobs = findBlobs(alpha);
    for (TrackedPerson& p : people_) {
        p.label = 0;
        p.merged = false;
        ++p.missed;
    }
    // Greedy matching, closest pair first, of each track's predicted foot point to the blobs'.
    struct Pair {
        float distance;
        std::size_t person, blob;
    };
    std::vector<Pair> pairs;
    for (std::size_t p = 0; p < people_.size(); ++p) {
        const cv::Point2f predicted = people_[p].predictedFoot();
        for (std::size_t b = 0; b < blobs.size(); ++b) {
            const float d = static_cast<float>(cv::norm(blobs[b].foot - predicted));
            if (d <= settings_.maxStepPx * static_cast<float>(people_[p].missed)) pairs.push_back({d, p, b});
        }
    }
    std::sort(pairs.begin(), pairs.end(), [](const Pair& a, const Pair& b) { return a.distance < b.distance; });
    std::vector<bool> blobTaken(blobs.size(), false);
    for (const Pair& pair : pairs) {
        TrackedPerson& p = people_[pair.person];
        if (p.missed == 0 || blobTaken[pair.blob]) continue;
        const Blob& b = blobs[pair.blob];
        blobTaken[pair.blob] = true;
        const cv::Point2f previous = p.foot;
        // A blob whose feet are cut off by the frame's edge says nothing about where the feet are.
        if (b.feetVisible) {
            const float k = settings_.smoothing;
            const cv::Point2f predicted = p.predictedFoot();
            p.foot = predicted + k * (b.foot - predicted);
            p.footVelocity = (1.0f - k) * p.footVelocity + k * (p.foot - previous) / static_cast<float>(p.missed);
        }
        p.box = b.box;
        p.feetVisible = b.feetVisible;
        p.label = b.label;
        p.missed = 0;
    }
    std::erase_if(people_, [this](const TrackedPerson& p) { return p.missed > settings_.keepMissedFrames; });
    // A missed track heading into a seen person's blob (its feet within the
    // blob's bounds, or just below them) walks merged with that person.
    for (TrackedPerson& p : people_) {
        if (p.missed == 0) continue;
        const cv::Point2f feet = p.predictedFoot();
        for (const TrackedPerson& q : people_) {
            if (q.missed != 0) continue;
            const int below = q.box.height / 10;
            if (cv::Rect(q.box.x, q.box.y, q.box.width, q.box.height + below).contains(cv::Point(feet))) {
                p.label = q.label;
                p.merged = true;
                break;
            }
        }
    }
    for (TrackedPerson& p : people_) {
        if (p.missed != 0) continue;
        const bool alone = std::none_of(people_.begin(), people_.end(),
                                        [&p](const TrackedPerson& q) { return q.merged && q.label == p.label; });
        if (alone || p.width == 0) p.width = p.box.width;
    }
    for (std::size_t b = 0; b < blobs.size(); ++b)
        if (!blobTaken[b])
            people_.push_back({nextId_++,
                               blobs[b].box,
                               blobs[b].foot,
                               {0.0f, 0.0f},
                               blobs[b].feetVisible,
                               0,
                               blobs[b].label,
                               false,
                               blobs[b].box.width});
    // Labels that no track took (none, after the loop above) and small blobs read as background.
    std::vector<int> keep(static_cast<std::size_t>(stats_.rows), 0);
    for (const TrackedPerson& p : people_)
        if (p.label > 0) keep[static_cast<std::size_t>(p.label)] = p.label;
    labels_.forEach<int>([&keep](int& l, const int*) { l = keep[static_cast<std::size_t>(l)]; });
    return people_;
}

}  // namespace arcomp
