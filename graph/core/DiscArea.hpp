#pragma once
// The pixels a sphere covers on screen: the disc of its projected radius,
// clamped to the viewport; an empty sphere covers none. View::projectedArea
// works it out from a view; the select pass, which already has each
// object's eye distance and the frame's pixel scale, calls this directly
// rather than paying a tangent and a square root again per item.
//
//   const float pixels = projectedDiscArea(s.radius, distance, view.pixelScale(), 1920.0f * 1080.0f);

#include <algorithm>
#include <numbers>

namespace arcomp {

// `distance`: eye to the sphere's centre; `pixelScale`: View::pixelScale().
inline float projectedDiscArea(float radius, float distance, float pixelScale, float viewportPixels) {
    if (radius < 0.0f) return 0.0f;
    if (distance <= radius) return viewportPixels;
    const float radiusPx = radius / distance * pixelScale;
    return std::min(viewportPixels, std::numbers::pi_v<float> * radiusPx * radiusPx);
}

} // namespace arcomp
