#include "video/matte/ConsensusMatte.hpp"

#include "video/pixels/AreaShrink.hpp"
#include "video/pixels/VideoError.hpp"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>

namespace arcomp {

namespace {

// Connected components of `mask` (255) smaller than `minArea` are cleared;
// returns the bounding box of those kept. ids, stats and centroids are
// scratch kept by the caller.
cv::Rect dropSmallComponents(cv::Mat& mask, double minArea, cv::Mat& ids, cv::Mat& stats, cv::Mat& centroids) {
    const int count = cv::connectedComponentsWithStats(mask, ids, stats, centroids, 8, CV_32S);
    std::vector<std::uint8_t> drop(count, 0);
    bool any = false;
    cv::Rect kept;
    for (int i = 1; i < count; ++i) {
        if (stats.at<int>(i, cv::CC_STAT_AREA) < minArea) {
            drop[i] = 1, any = true;
            continue;
        }
        const cv::Rect box(stats.at<int>(i, cv::CC_STAT_LEFT), stats.at<int>(i, cv::CC_STAT_TOP),
                           stats.at<int>(i, cv::CC_STAT_WIDTH), stats.at<int>(i, cv::CC_STAT_HEIGHT));
        kept = kept.empty() ? box : kept | box;
    }
    if (!any) return kept;
    for (int y = 0; y < mask.rows; ++y) {
        const int* id = ids.ptr<int>(y);
        std::uint8_t* m = mask.ptr<std::uint8_t>(y);
        for (int x = 0; x < mask.cols; ++x)
            if (drop[id[x]]) m[x] = 0;
    }
    return kept;
}

// alpha = a * grey + b at every frame pixel, with a and b (model scale)
// interpolated bilinearly and grey the frame's luma: one pass, no full-size
// intermediate images. Away from people a and b are 0, so each row is only
// computed between the first and last columns where they are not.
void applyAtFullSize(const cv::Mat& frame, const cv::Mat& a, const cv::Mat& b, cv::Mat& alpha) {
    alpha.create(frame.size(), CV_8UC1);
    const double sx = static_cast<double>(a.cols) / frame.cols, sy = static_cast<double>(a.rows) / frame.rows;
    std::vector<int> x0(frame.cols), x1(frame.cols);
    std::vector<float> wx(frame.cols);
    for (int x = 0; x < frame.cols; ++x) {
        const double fx = std::clamp((x + 0.5) * sx - 0.5, 0.0, a.cols - 1.0);
        x0[x] = static_cast<int>(fx);
        x1[x] = std::min(x0[x] + 1, a.cols - 1);
        wx[x] = static_cast<float>(fx - x0[x]);
    }
    // Per model row, the span of columns where alpha can be above 0.
    constexpr float kNothing = 0.5f / 255.0f;
    std::vector<int> first(a.rows, a.cols), last(a.rows, -1);
    for (int y = 0; y < a.rows; ++y) {
        const float *ar = a.ptr<float>(y), *br = b.ptr<float>(y);
        for (int x = 0; x < a.cols; ++x)
            if (std::abs(ar[x]) + std::abs(br[x]) > kNothing) {
                first[y] = std::min(first[y], x);
                last[y] = x;
            }
    }
    cv::parallel_for_(cv::Range(0, frame.rows), [&](const cv::Range& rows) {
        for (int y = rows.start; y < rows.end; ++y) {
            const double fy = std::clamp((y + 0.5) * sy - 0.5, 0.0, a.rows - 1.0);
            const int y0 = static_cast<int>(fy), y1 = std::min(y0 + 1, a.rows - 1);
            std::uint8_t* out = alpha.ptr<std::uint8_t>(y);
            const int from = std::min(first[y0], first[y1]), to = std::max(last[y0], last[y1]);
            if (to < from) {
                std::fill(out, out + frame.cols, 0);
                continue;
            }
            // Frame columns that read model columns from..to.
            const int begin = static_cast<int>(std::lower_bound(x1.begin(), x1.end(), from) - x1.begin());
            const int end = static_cast<int>(std::upper_bound(x0.begin(), x0.end(), to) - x0.begin());
            std::fill(out, out + begin, 0);
            std::fill(out + end, out + frame.cols, 0);
            const float wy = static_cast<float>(fy - y0);
            const float *a0 = a.ptr<float>(y0), *a1 = a.ptr<float>(y1), *b0 = b.ptr<float>(y0), *b1 = b.ptr<float>(y1);
            const std::uint8_t* c = frame.ptr<std::uint8_t>(y) + 3 * begin;
            for (int x = begin; x < end; ++x, c += 3) {
                const int l = x0[x], r = x1[x];
                const float w = wx[x];
                const float av = (1 - wy) * (a0[l] + w * (a0[r] - a0[l])) + wy * (a1[l] + w * (a1[r] - a1[l]));
                const float bv = (1 - wy) * (b0[l] + w * (b0[r] - b0[l])) + wy * (b1[l] + w * (b1[r] - b1[l]));
                // BT.601 luma, as cvtColor(BGR2GRAY) gave the guide at model scale.
                const float grey = (0.114f * c[0] + 0.587f * c[1] + 0.299f * c[2]) * (1.0f / 255.0f);
                out[x] = cv::saturate_cast<std::uint8_t>(255.0f * (av * grey + bv));
            }
        }
    });
}

}  // namespace

ConsensusMatte::ConsensusMatte(const BackgroundSpec& spec) : spec_(spec), model_(spec.consensus) {
    if (spec.scale < 0.1 || spec.scale > 1.0)
        throw VideoError("background matte", "settings", "scale must lie in 0.1..1");
    const ConsensusSpec& c = spec.consensus;
    if (c.minBlobArea < 0.0 || c.minBlobArea >= 1.0 || c.maxHoleArea < 0.0 || c.maxHoleArea >= 1.0)
        throw VideoError("background matte", "settings", "min_blob_area and max_hole_area must lie in 0..1");
    if (c.edgeRadiusPx < 0) throw VideoError("background matte", "settings", "edge_radius_px must be >= 0");
    if (c.gapPx < 0) throw VideoError("background matte", "settings", "gap_px must be >= 0");
    const int gap = static_cast<int>(c.gapPx * spec.scale + 0.5);
    if (gap > 1) closeKernel_ = cv::getStructuringElement(cv::MORPH_ELLIPSE, {gap, gap});
    if (!spec.cleanPlate.empty()) {
        const cv::Mat plate = cv::imread(spec.cleanPlate, cv::IMREAD_COLOR);
        if (plate.empty()) throw VideoError(spec.cleanPlate, "clean plate", "cannot read the image");
        model_.setPlate(plate);
    }
}

void ConsensusMatte::cleanUp() {
    cv::compare(labels_, ConsensusModel::kPerson, mask_, cv::CMP_EQ);
    const double area = static_cast<double>(mask_.total());
    const cv::Rect people =
        spec_.consensus.minBlobArea > 0.0
            ? dropSmallComponents(mask_, spec_.consensus.minBlobArea * area, ids_, stats_, centroids_)
            : cv::boundingRect(mask_);
    // Everything after this only changes pixels near people: it works in
    // their bounding box, grown by what closing and the guided filter reach.
    const int margin = closeKernel_.cols + 2 * guidedRadius() + 2;
    work_ = people.empty() ? cv::Rect()
                           : (people + cv::Size(2 * margin, 2 * margin) - cv::Point(margin, margin)) &
                                 cv::Rect(0, 0, mask_.cols, mask_.rows);
    if (work_.empty()) return;
    cv::Mat region = mask_(work_);
    if (!closeKernel_.empty()) cv::morphologyEx(region, region, cv::MORPH_CLOSE, closeKernel_);
    if (spec_.consensus.maxHoleArea > 0.0) {
        // A hole is a small background component that does not reach the
        // edge of the work box (the margin keeps people off that edge).
        cv::bitwise_not(region, holes_);
        const int count = cv::connectedComponentsWithStats(holes_, ids_, stats_, centroids_, 4, CV_32S);
        std::vector<std::uint8_t> fill(count, 0);
        for (int i = 1; i < count; ++i) {
            const int x = stats_.at<int>(i, cv::CC_STAT_LEFT), y = stats_.at<int>(i, cv::CC_STAT_TOP);
            const int w = stats_.at<int>(i, cv::CC_STAT_WIDTH), h = stats_.at<int>(i, cv::CC_STAT_HEIGHT);
            const bool touchesEdge = x == 0 || y == 0 || x + w == region.cols || y + h == region.rows;
            fill[i] = !touchesEdge && stats_.at<int>(i, cv::CC_STAT_AREA) < spec_.consensus.maxHoleArea * area;
        }
        for (int y = 0; y < region.rows; ++y) {
            const int* id = ids_.ptr<int>(y);
            std::uint8_t* m = region.ptr<std::uint8_t>(y);
            for (int x = 0; x < region.cols; ++x)
                if (fill[id[x]]) m[x] = 255;
        }
    }
}

void ConsensusMatte::forgetGhosts() {
    // Only blobs that have stood still for a second are judged: a ghost
    // does not move, and a moving person is never taken for one.
    const int stillEnough = std::max(1, static_cast<int>(spec_.consensus.fps));
    cv::Mat region = mask_(work_);
    const int count = cv::connectedComponents(region, ids_, 8, CV_32S);
    if (count <= 1) return;
    cv::cvtColor(small_(work_), grey_, cv::COLOR_BGR2GRAY);
    cv::cvtColor(model_.background()(work_), modelGrey_, cv::COLOR_BGR2GRAY);
    const cv::Mat still = model_.stillFrames()(work_);
    std::vector<double> sharpNow(count, 0.0), sharpModel(count, 0.0);
    std::vector<int> area(count, 0), stillArea(count, 0);
    const auto sharpness = [](const cv::Mat& g, int x, int y) {
        return std::abs(g.at<std::uint8_t>(y, x + 1) - g.at<std::uint8_t>(y, x - 1)) +
               std::abs(g.at<std::uint8_t>(y + 1, x) - g.at<std::uint8_t>(y - 1, x));
    };
    // The work box's margin keeps every blob off its edge.
    for (int y = 1; y + 1 < region.rows; ++y) {
        const int* id = ids_.ptr<int>(y);
        for (int x = 1; x + 1 < region.cols; ++x) {
            const int i = id[x];
            if (i == 0) continue;
            ++area[i];
            stillArea[i] += still.at<std::uint16_t>(y, x) >= stillEnough;
            const bool outline =
                id[x - 1] == 0 || id[x + 1] == 0 || ids_.at<int>(y - 1, x) == 0 || ids_.at<int>(y + 1, x) == 0;
            if (!outline) continue;
            sharpNow[i] += sharpness(grey_, x, y);
            sharpModel[i] += sharpness(modelGrey_, x, y);
        }
    }
    std::vector<std::uint8_t> ghost(count, 0);
    bool any = false;
    for (int i = 1; i < count; ++i) {
        ghost[i] = stillArea[i] >= 0.7 * area[i] && sharpNow[i] < 0.5 * sharpModel[i];
        any = any || ghost[i];
    }
    if (!any) return;
    ghosts_.create(mask_.size(), CV_8UC1);
    ghosts_.setTo(0);
    cv::Mat ghostRegion = ghosts_(work_);
    for (int y = 0; y < region.rows; ++y) {
        const int* id = ids_.ptr<int>(y);
        std::uint8_t* g = ghostRegion.ptr<std::uint8_t>(y);
        std::uint8_t* m = region.ptr<std::uint8_t>(y);
        for (int x = 0; x < region.cols; ++x)
            if (ghost[id[x]]) g[x] = 255, m[x] = 0;
    }
    model_.relearn(ghosts_);
}

int ConsensusMatte::guidedRadius() const {
    return std::max(1, static_cast<int>(spec_.consensus.edgeRadiusPx * spec_.scale + 0.5));
}

void ConsensusMatte::guidedEdges(const cv::Mat& frame) {
    // Guided filter with the grey image as guide: within each window alpha
    // is a linear function of the guide, a*I + b, fitted to the mask, so
    // alpha's edge goes where the image's edge is.
    const int r = guidedRadius();
    const cv::Size window(2 * r + 1, 2 * r + 1);
    meanA_.create(small_.size(), CV_32FC1);
    meanB_.create(small_.size(), CV_32FC1);
    meanA_.setTo(0);
    meanB_.setTo(0);
    if (work_.empty()) {  // nobody: a = b = 0, alpha 0
        applyAtFullSize(frame, meanA_, meanB_, alpha_);
        return;
    }
    const cv::Mat smallWork = small_(work_), maskWork = mask_(work_);
    // (8 levels of 255)^2, the order of the sensor's noise: weaker edges are smoothed over.
    const double eps = (8.0 / 255.0) * (8.0 / 255.0);
    // Every image here is a member reused from frame to frame: at these
    // sizes a fresh allocation per step costs more than the arithmetic.
    cv::cvtColor(smallWork, grey_, cv::COLOR_BGR2GRAY);
    guide_.create(work_.size(), CV_32FC1);
    target_.create(work_.size(), CV_32FC1);
    guideSquared_.create(work_.size(), CV_32FC1);
    guideTarget_.create(work_.size(), CV_32FC1);
    for (int y = 0; y < work_.height; ++y) {
        const std::uint8_t* g = grey_.ptr<std::uint8_t>(y);
        const std::uint8_t* m = maskWork.ptr<std::uint8_t>(y);
        float *i = guide_.ptr<float>(y), *p = target_.ptr<float>(y);
        float *ii = guideSquared_.ptr<float>(y), *ip = guideTarget_.ptr<float>(y);
        for (int x = 0; x < work_.width; ++x) {
            i[x] = g[x] * (1.0f / 255.0f);
            p[x] = m[x] ? 1.0f : 0.0f;
            ii[x] = i[x] * i[x];
            ip[x] = i[x] * p[x];
        }
    }
    cv::boxFilter(guide_, meanI_, CV_32F, window);
    cv::boxFilter(target_, meanP_, CV_32F, window);
    cv::boxFilter(guideSquared_, guideSquared_, CV_32F, window);
    cv::boxFilter(guideTarget_, guideTarget_, CV_32F, window);
    // a = cov(I, p) / (var(I) + eps), b = mean(p) - a mean(I), in place.
    for (int y = 0; y < work_.height; ++y) {
        const float *mi = meanI_.ptr<float>(y), *ii = guideSquared_.ptr<float>(y);
        float *a = guideTarget_.ptr<float>(y), *b = meanP_.ptr<float>(y);
        for (int x = 0; x < work_.width; ++x) {
            a[x] = (a[x] - mi[x] * b[x]) / (ii[x] - mi[x] * mi[x] + static_cast<float>(eps));
            b[x] -= a[x] * mi[x];
        }
    }
    cv::Mat aWork = meanA_(work_), bWork = meanB_(work_);
    cv::boxFilter(guideTarget_, aWork, CV_32F, window);
    cv::boxFilter(meanP_, bWork, CV_32F, window);
    applyAtFullSize(frame, meanA_, meanB_, alpha_);
}

void ConsensusMatte::apply(const cv::Mat& frame, cv::Mat& person) {
    CV_Assert(frame.type() == CV_8UC3);
    if (spec_.scale < 1.0)
        shrinkByArea(frame, spec_.scale, small_);
    else
        small_ = frame;
    model_.apply(small_, labels_);
    cleanUp();
    if (!work_.empty()) forgetGhosts();
    if (spec_.consensus.edgeRadiusPx > 0) {
        guidedEdges(frame);
    } else if (mask_.size() != frame.size()) {
        cv::resize(mask_, alpha_, frame.size(), 0, 0, cv::INTER_LINEAR);
    } else {
        mask_.copyTo(alpha_);
    }
    premultiply(frame, alpha_, person);
}

}  // namespace arcomp
