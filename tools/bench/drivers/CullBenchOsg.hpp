#pragma once
// The cull bench's peer: OpenSceneGraph on the same scene.

#include "tools/bench/scenes/CullScene.hpp"

#include <memory>
#include <utility>

namespace arcomp {

// OpenSceneGraph's CullVisitor on the same scene and path, built once and
// timed one frame at a time, so that the bench can alternate between the
// two sides; defined only where OpenSceneGraph was found (ARCOMP_HAVE_OSG,
// tools/CMakeLists.txt).
class OsgCull {
public:
    explicit OsgCull(const CullScene& s);
    ~OsgCull();
    OsgCull(const OsgCull&) = delete;
    OsgCull& operator=(const OsgCull&) = delete;

    // Culls frame `frame` of `frames` of the path: its wall milliseconds
    // (the cull alone) and what it found.
    std::pair<double, CullFrameCounts> frame(int frame, int frames);

private:
    struct State;
    std::unique_ptr<State> state_;
};

}  // namespace arcomp
