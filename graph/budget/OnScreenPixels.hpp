#pragma once
// The pixels a drawn object shades, as the cost model counts them: the
// select pass's screen area (the whole disc of its bounding sphere, cheap
// enough for every object) less the part of the disc outside the viewport;
// for an object that the disc describes badly (the eye inside its sphere,
// or a disc of more than a sixty-fourth of the screen), no more than the
// screen rectangle around its box.
//
//   const double ms = model.itemMs(level, shading, onScreenPixels(item, scene, view));

#include "graph/core/DrawList.hpp"
#include "graph/core/Scene.hpp"
#include "graph/core/View.hpp"

namespace arcomp {

// The share, 0 to 1, of the sphere's screen disc inside the viewport; 1 when
// the eye is inside the sphere or its centre is not in front of the eye.
float onScreenShare(const Sphere& bound, const View& view);

// The pixels of the screen rectangle around `box` (in the frame `model`
// maps to world) clipped to the near plane and the viewport; 0 when the box
// lies wholly behind the near plane.
float boxRectanglePixels(const Box& box, const glm::mat4& model, const View& view);

float onScreenPixels(const DrawItem& item, const Scene& scene, const View& view);

}  // namespace arcomp
