#include "runtime/app/ZoneOverlay.hpp"
#include "runtime/app/OverlayStyle.hpp"

#include <opencv2/imgproc.hpp>

#include <cmath>
#include <numbers>

namespace arcomp {
namespace {

// Premultiplied RGBA: empty zones amber, occupied ones green.
const cv::Scalar kEmpty{230, 170, 40, 230};
const cv::Scalar kOccupied{60, 220, 90, 255};
constexpr int kPointsPerEdge = 16;  // a floor edge bends through a distorting lens

// The zone's outline as points in its own units, closed.
std::vector<glm::vec2> outline(const Zone& zone) {
    std::vector<glm::vec2> corners = zone.polygon;
    if (corners.empty())
        for (int k = 0; k < 48; ++k) {
            const float a = 2.0f * std::numbers::pi_v<float> * static_cast<float>(k) / 48.0f;
            corners.push_back(zone.center + zone.radius * glm::vec2(std::cos(a), std::sin(a)));
        }
    std::vector<glm::vec2> out;
    for (std::size_t i = 0; i < corners.size(); ++i) {
        const glm::vec2 a = corners[i], b = corners[(i + 1) % corners.size()];
        const int steps = zone.polygon.empty() ? 1 : kPointsPerEdge;
        for (int s = 0; s < steps; ++s)
            out.push_back(glm::mix(a, b, static_cast<float>(s) / static_cast<float>(steps)));
    }
    out.push_back(out.front());
    return out;
}

}  // namespace

void ZoneOverlay::draw(const cv::Mat* below, std::span<const Zone> zones, std::span<const ZoneCount> counts,
                       const std::optional<CalibratedCamera>& camera, glm::ivec2 size) {
    if (below && below->rows == size.y && below->cols == size.x)
        below->copyTo(image_);
    else
        image_ = cv::Mat(size.y, size.x, CV_8UC4, cv::Scalar::all(0));
    std::optional<CalibratedCamera> atSize = camera;
    if (atSize) atSize->intrinsics = camera->intrinsics.scaledTo(size);
    for (std::size_t z = 0; z < zones.size(); ++z) {
        const Zone& zone = zones[z];
        if (zone.space == ZoneSpace::Floor && !atSize) continue;
        const int people = z < counts.size() ? counts[z].people : 0;
        const cv::Scalar colour = people > 0 ? kOccupied : kEmpty;
        // Runs of the outline in front of the lens, in pixels.
        std::vector<std::vector<cv::Point>> runs(1);
        for (const glm::vec2& p : outline(zone)) {
            glm::dvec2 pixel;
            if (zone.space == ZoneSpace::Image) {
                pixel = glm::dvec2(p) * glm::dvec2(size);
            } else {
                const glm::dvec3 floor(p.x, 0.0, p.y);
                if (atSize->depthOf(floor) < kOverlayNearMetres) {
                    if (!runs.back().empty()) runs.emplace_back();
                    continue;
                }
                pixel = atSize->project(floor);
            }
            runs.back().emplace_back(static_cast<int>(std::lround(pixel.x)), static_cast<int>(std::lround(pixel.y)));
        }
        cv::polylines(image_, runs, false, kOverlayOutline, 4, cv::LINE_AA);
        cv::polylines(image_, runs, false, colour, 2, cv::LINE_AA);
        // The label at the outline's topmost visible point.
        const cv::Point* top = nullptr;
        for (const auto& run : runs)
            for (const cv::Point& p : run)
                if (p.x >= 0 && p.y >= 0 && p.x < size.x && p.y < size.y && (!top || p.y < top->y)) top = &p;
        if (!top) continue;
        const std::string label = zone.name + ": " + std::to_string(people);
        const cv::Point at(std::min(top->x, std::max(0, size.x - 8 * static_cast<int>(label.size()))),
                           std::max(top->y - 6, 14));
        cv::putText(image_, label, at, cv::FONT_HERSHEY_SIMPLEX, 0.5, kOverlayOutline, 3, cv::LINE_AA);
        cv::putText(image_, label, at, cv::FONT_HERSHEY_SIMPLEX, 0.5, colour, 1, cv::LINE_AA);
    }
}

}  // namespace arcomp
