#include "runtime/app/CalibrationOverlay.hpp"
#include "runtime/app/OverlayStyle.hpp"

#include <opencv2/imgproc.hpp>

#include <cmath>
#include <cstdio>

namespace arcomp {

namespace {

// Premultiplied RGBA. The grid is faint so that the floor it lies on stays visible.
const cv::Scalar kGrid{99, 99, 99, 110};
const cv::Scalar kXAxis{180, 47, 39, 200};
const cv::Scalar kZAxis{55, 110, 200, 200};
const cv::Scalar kMeasured{90, 230, 90, 255};
const cv::Scalar kKept{240, 200, 60, 255};
const cv::Scalar kPlane{235, 70, 60, 255};

// cv::line's fractional bits: ends to 1/16 pixel, as project() gives them.
constexpr int kShift = 4;

cv::Point fixedPoint(const glm::dvec2& pixel) {
    return {static_cast<int>(std::lround(pixel.x * (1 << kShift))),
            static_cast<int>(std::lround(pixel.y * (1 << kShift)))};
}

// The stretch of floor segment a-b in front of the lens, projected. A
// straight floor line is a straight line in the undistorted picture, so its
// clipped ends are all it takes.
void floorLine(cv::Mat& image, const CalibratedCamera& camera, const glm::dvec3& a, const glm::dvec3& b,
               const cv::Scalar& colour) {
    const double za = camera.depthOf(a), zb = camera.depthOf(b);
    if (za < kOverlayNearMetres && zb < kOverlayNearMetres) return;
    glm::dvec3 from = a, to = b;
    if (za < kOverlayNearMetres) from = a + (b - a) * ((kOverlayNearMetres - za) / (zb - za));
    if (zb < kOverlayNearMetres) to = b + (a - b) * ((kOverlayNearMetres - zb) / (za - zb));
    const glm::dvec2 p = camera.project(from), q = camera.project(to);
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(q.x) || !std::isfinite(q.y)) return;
    cv::line(image, fixedPoint(p), fixedPoint(q), colour, 1, cv::LINE_AA, kShift);
}

// Where the grid is centred: where the optical axis meets the floor, but
// no farther than the grid's half width from the point below the lens.
glm::dvec3 gridCentre(const CalibratedCamera& camera) {
    const glm::dvec3 lens = camera.position();
    const glm::dvec3 below(lens.x, 0.0, lens.z);
    glm::dvec3 centre = below;
    const CameraIntrinsics& k = camera.intrinsics;
    if (const std::optional<glm::dvec3> axis = camera.floorPointAt({k.cx, k.cy})) {
        glm::dvec3 out = *axis - below;
        const double length = glm::length(out);
        if (length > CalibrationOverlay::kGridHalfMetres) out *= CalibrationOverlay::kGridHalfMetres / length;
        centre += out;
    }
    // Lines on whole metres, so that the floor frame's origin is a crossing.
    return {std::round(centre.x), 0.0, std::round(centre.z)};
}

bool sameCamera(const CalibratedCamera& a, const CalibratedCamera& b) {
    const CameraIntrinsics &i = a.intrinsics, &j = b.intrinsics;
    return i.imageSize == j.imageSize && i.fx == j.fx && i.fy == j.fy && i.cx == j.cx && i.cy == j.cy &&
           a.rotation == b.rotation && a.translation == b.translation;
}

}  // namespace

void drawFloorGrid(cv::Mat& image, const CalibratedCamera& camera) {
    CV_Assert(image.type() == CV_8UC4);
    const glm::dvec3 c = gridCentre(camera);
    const double h = CalibrationOverlay::kGridHalfMetres;
    // The axes last, over the lines they cross.
    for (int pass = 0; pass < 2; ++pass) {
        for (double i = -h; i <= h; i += 1.0) {
            const double x = c.x + i, z = c.z + i;
            if ((x == 0.0) == (pass == 1))
                floorLine(image, camera, {x, 0.0, c.z - h}, {x, 0.0, c.z + h}, pass ? kZAxis : kGrid);
            if ((z == 0.0) == (pass == 1))
                floorLine(image, camera, {c.x - h, 0.0, z}, {c.x + h, 0.0, z}, pass ? kXAxis : kGrid);
        }
    }
}

std::string standingLabel(const StandingPerson& person) {
    const char* source = person.depth == StandingPerson::Depth::Measured ? ""
                         : person.depth == StandingPerson::Depth::Kept   ? " (kept)"
                                                                         : " (plane)";
    char label[64];
    std::snprintf(label, sizeof label, "#%d %.1f m%s", person.id, static_cast<double>(person.metres), source);
    return label;
}

void CalibrationOverlay::draw(const CalibratedCamera& camera, glm::ivec2 size, std::span<const StandingPerson> people) {
    CalibratedCamera atSize = camera;
    atSize.intrinsics = camera.intrinsics.scaledTo(size);
    if (grid_.empty() || !sameCamera(atSize, gridCamera_)) {
        grid_.create(size.y, size.x, CV_8UC4);
        grid_.setTo(cv::Scalar::all(0));
        drawFloorGrid(grid_, atSize);
        gridCamera_ = atSize;
    }
    grid_.copyTo(image_);

    for (const StandingPerson& p : people) {
        if (!std::isfinite(p.foot.x) || !std::isfinite(p.foot.y)) continue;
        const cv::Scalar colour = p.depth == StandingPerson::Depth::Measured ? kMeasured
                                  : p.depth == StandingPerson::Depth::Kept   ? kKept
                                                                             : kPlane;
        const cv::Point foot = fixedPoint(glm::dvec2(p.foot));
        cv::circle(image_, foot, 7 << kShift, kOverlayOutline, 4, cv::LINE_AA, kShift);
        cv::circle(image_, foot, 7 << kShift, colour, 2, cv::LINE_AA, kShift);
        cv::circle(image_, foot, 2 << kShift, colour, cv::FILLED, cv::LINE_AA, kShift);
        // The label to the right of the marker, or to its left near the
        // frame's right edge, centred on the foot's row.
        const std::string label = standingLabel(p);
        int baseline = 0;
        const cv::Size text = cv::getTextSize(label, cv::FONT_HERSHEY_SIMPLEX, 0.5, 3, &baseline);
        const int x = static_cast<int>(std::lround(p.foot.x)), y = static_cast<int>(std::lround(p.foot.y));
        const cv::Point at(x + 12 + text.width > image_.cols ? x - 12 - text.width : x + 12, y + 5);
        cv::putText(image_, label, at, cv::FONT_HERSHEY_SIMPLEX, 0.5, kOverlayOutline, 3, cv::LINE_AA);
        cv::putText(image_, label, at, cv::FONT_HERSHEY_SIMPLEX, 0.5, colour, 1, cv::LINE_AA);
    }
}

}  // namespace arcomp
