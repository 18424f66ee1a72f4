#include "graph/budget/OnScreenPixels.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace arcomp {

// An object entering at the screen edge shades only its pixels on screen;
// charging it the whole disc over-predicted those frames (issue #23), and
// the calibration's largest discs overflow a 16:9 screen vertically. Summed
// over horizontal strips of the disc, each clipped to the viewport: a few
// dozen items a frame, so a near-exact area is cheaper than a clever one.
float onScreenShare(const Sphere& s, const View& view) {
    const glm::vec4 clip = view.viewProjection() * glm::vec4(s.center, 1.0f);
    // The eye inside the sphere, or its centre near or behind the eye: no
    // single disc describes what it covers, so it keeps the whole estimate.
    if (s.empty() || clip.w <= s.radius) return 1.0f;
    const glm::vec2 size(view.viewport);
    const glm::vec2 centre = (glm::vec2(clip) / clip.w * 0.5f + 0.5f) * size;
    const float radius = s.radius / clip.w * view.pixelScale();
    const bool wholly = glm::all(glm::greaterThanEqual(centre - radius, glm::vec2(0.0f))) &&
                        glm::all(glm::lessThanEqual(centre + radius, size));
    if (wholly) return 1.0f;
    constexpr int kStrips = 32;
    const float height = 2.0f * radius / kStrips;
    float inside = 0.0f, whole = 0.0f;
    for (int i = 0; i < kStrips; ++i) {
        const float y0 = centre.y - radius + height * static_cast<float>(i);
        const float dy = y0 + 0.5f * height - centre.y;
        const float half = std::sqrt(std::max(radius * radius - dy * dy, 0.0f));
        const float width = std::clamp(centre.x + half, 0.0f, size.x) - std::clamp(centre.x - half, 0.0f, size.x);
        const float rows = std::clamp(y0 + height, 0.0f, size.y) - std::clamp(y0, 0.0f, size.y);
        inside += width * rows;
        whole += 2.0f * half * height;
    }
    return whole > 0.0f ? inside / whole : 1.0f;
}

float boxRectanglePixels(const Box& box, const glm::mat4& model, const View& view) {
    if (box.empty()) return 0.0f;
    const glm::mat4 toClip = view.viewProjection() * model;
    std::array<glm::vec4, 8> corner;
    for (std::size_t i = 0; i < corner.size(); ++i)
        corner[i] = toClip * glm::vec4(i & 1 ? box.max.x : box.min.x, i & 2 ? box.max.y : box.min.y,
                                       i & 4 ? box.max.z : box.min.z, 1.0f);
    // In clip space a point is in front of the near plane where z + w ≥ 0
    // (w > 0 there). The box clipped to that half-space is spanned by its
    // corners in front and the points where its edges cross the plane.
    glm::vec2 low(std::numeric_limits<float>::max()), high(std::numeric_limits<float>::lowest());
    const auto span = [&](const glm::vec4& c) {
        const glm::vec2 ndc = glm::vec2(c) / c.w;
        low = glm::min(low, ndc);
        high = glm::max(high, ndc);
    };
    for (std::size_t i = 0; i < corner.size(); ++i) {
        const float in = corner[i].z + corner[i].w;
        if (in >= 0.0f) span(corner[i]);
        for (std::size_t axis = 1; axis < corner.size(); axis <<= 1) {
            if (i & axis) continue;
            const float other = corner[i | axis].z + corner[i | axis].w;
            if ((in >= 0.0f) != (other >= 0.0f)) span(glm::mix(corner[i], corner[i | axis], in / (in - other)));
        }
    }
    if (low.x > high.x) return 0.0f;
    const glm::vec2 extent =
        (glm::clamp(high, -1.0f, 1.0f) - glm::clamp(low, -1.0f, 1.0f)) * 0.5f * glm::vec2(view.viewport);
    return extent.x * extent.y;
}

float onScreenPixels(const DrawItem& item, const Scene& scene, const View& view) {
    const Sphere& bound = scene.worldBound(item.node);
    const float disc = item.screenArea * onScreenShare(bound, view);
    // A mountain passed close by in bench budget: its sphere holds the eye,
    // and it was charged the whole screen (a quarter of the flight's frames
    // had such an item) while it filled a corner. The online gain absorbed
    // the error, and was wrong the other way once the mountain left the
    // view: frames 10-30% over the target. With its box: 59 frames of 600
    // still charge a whole screen (the eye inside the box too), and p95
    // |dev| fell from 13-21% to 11-12% in three interleaved runs each.
    // Small discs are left as they are: the box's eight corners would cost
    // more than their error. Proxies bring their own matrix, and a skinned
    // mesh's poses may leave its bind-pose box, so both keep the disc.
    const float viewportPixels = static_cast<float>(view.viewport.x) * static_cast<float>(view.viewport.y);
    if (item.model != nullptr || item.part.skin != kNoSkin || view.projectedArea(bound) <= viewportPixels / 64.0f)
        return disc;
    return std::min(disc, boxRectanglePixels(scene.geometry(item.part.geometry).box, scene.world(item.node), view));
}

}  // namespace arcomp
