#pragma once
// Layered depth images holding a point cloud, split between several LDIs
// by the paper's registration rule: each point goes to the one LDI, and
// the one pixel of it, whose ray passes closest to the point.
//
//   LdiSet set = buildLdis(std::move(cloud), ldiCamerasAround(bound, 6, cloud.pointSize));
//   const Ldi& l = set.ldis[0];
//   for (uint32_t k = l.pixelStart[p]; k < l.pixelStart[p + 1]; ++k) ... l.points[k] ...
//
// An LDI is stored flat: pixelStart (width*height + 1 offsets) into one
// array of point ids, each pixel's run sorted by depth along its ray,
// nearest first, with that depth beside it in rayDepth.

#include "graph/points/LdiCamera.hpp"
#include "graph/points/PointCloud.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace arcomp {

struct Ldi {
    LdiCamera camera;
    std::vector<std::uint32_t> pixelStart;  // width * height + 1
    std::vector<std::uint32_t> points;      // ids into the cloud
    std::vector<float> rayDepth;            // distance along the pixel's unit ray, ascending per pixel

    std::size_t size() const { return points.size(); }
};

struct LdiSet {
    PointCloud cloud;
    std::vector<Ldi> ldis;
    std::vector<std::uint8_t> pointLdi;  // which LDI holds each point; kNoLdi if none could
    std::size_t unregistered = 0;        // points behind every LDI's eye
};
inline constexpr std::uint8_t kNoLdi = 0xff;

// Yoshida et al., "multiple LDIs for translucent points", eq. for Lx: the
// distance from a point to the ray through the nearest pixel centre,
// measured parallel to the screen, from the point's depth Dx, the distance
// Lp from its projection to that pixel centre on the screen, and the
// eye-to-screen-centre distance D0 (which stands in for Dp, the depth of
// the projection, to save work).
inline float rayDistanceLx(float dx, float lp, float d0) { return dx * lp / d0; }

// Where a point would be registered in one LDI: its pixel and its Lx.
struct LdiPlacement {
    std::uint32_t pixel = 0;
    float lx = 0.0f;
    bool valid = false;  // false when the point is behind the eye
};
// Points beyond the screen's edge go to the nearest edge pixel, whose ray
// is still the nearest one; Lx grows with the distance, so another LDI
// that sees the point directly wins.
LdiPlacement placeInLdi(const LdiCamera& camera, const glm::vec3& p);

// Registers every point in the LDI with the smallest Lx (ties: the lower
// index) and sorts each pixel's points by depth.
LdiSet buildLdis(PointCloud cloud, std::vector<LdiCamera> cameras);

}  // namespace arcomp
