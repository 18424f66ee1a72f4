#pragma once
// The pixels a drawn object shades, as the cost model counts them: the
// select pass's screen area (the whole disc of its bounding sphere, cheap
// enough for every object) less the part of the disc outside the viewport.
//
//   const double ms = model.itemMs(level, shading, onScreenPixels(item, scene, view));

#include "graph/core/DrawList.hpp"
#include "graph/core/Scene.hpp"
#include "graph/core/View.hpp"

namespace arcomp {

// The share, 0 to 1, of the sphere's screen disc inside the viewport; 1 when
// the eye is inside the sphere or its centre is not in front of the eye.
float onScreenShare(const Sphere& bound, const View& view);

float onScreenPixels(const DrawItem& item, const Scene& scene, const View& view);

} // namespace arcomp
