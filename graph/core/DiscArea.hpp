#pragma once
// The pixels a sphere covers on screen: the disc of its projected radius,
// clamped to the viewport; an empty sphere covers none. View::projectedArea
// works it out from a view; the select pass, which already has each
// object's squared eye distance and the frame's pixel scale, calls this
// directly rather than paying a tangent again per item. It takes the
// distance squared so that no square root lies on the way to the answer.
//
//   const float pixels = projectedDiscArea(s.radius, glm::dot(d, d), view.pixelScale(), 1920.0f * 1080.0f);

#include <algorithm>
#include <numbers>

namespace arcomp {

// `distanceSquared`: eye to the sphere's centre, squared; `pixelScale`: View::pixelScale().
inline float projectedDiscArea(float radius, float distanceSquared, float pixelScale, float viewportPixels) {
    if (radius < 0.0f) return 0.0f;
    const float radiusSquared = radius * radius;
    if (distanceSquared <= radiusSquared) return viewportPixels;
    return std::min(viewportPixels,
                    std::numbers::pi_v<float> * pixelScale * pixelScale * radiusSquared / distanceSquared);
}

}  // namespace arcomp
