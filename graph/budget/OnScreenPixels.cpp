#include "graph/budget/OnScreenPixels.hpp"

#include <algorithm>
#include <cmath>

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

float onScreenPixels(const DrawItem& item, const Scene& scene, const View& view) {
    return item.screenArea * onScreenShare(scene.worldBound(item.node), view);
}

} // namespace arcomp
