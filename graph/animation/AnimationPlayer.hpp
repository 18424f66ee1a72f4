#pragma once
// Plays one of a loaded model's animations on a clock: apply() samples every
// channel at the clip time for `seconds` and sets the animated nodes' local
// matrices; scene.update() then carries world matrices and bounds down and
// up the tree as for any other change.
//
//   LoadedModel m = loadModel("walker.gltf", scene, scene.root());
//   AnimationPlayer player(m.animations[0], {.loop = true, .speed = 1.0});
//   player.apply(scene, frameSeconds);
//   scene.update();
//
// The clip time is a function of `seconds` alone, so the same clock gives
// the same pose on every run (a replay is repeatable frame for frame).

#include "graph/animation/ModelAnimation.hpp"

namespace arcomp {

struct PlaybackOptions {
    bool loop = true;    // wrap at the clip's end; false holds the last pose
    double speed = 1.0;  // clip seconds per clock second; must be positive
};

class AnimationPlayer {
public:
    // Throws std::invalid_argument for a speed that is not a positive number.
    explicit AnimationPlayer(ModelAnimation animation, PlaybackOptions options = {});

    void apply(Scene& scene, double seconds);
    // Where in the clip `seconds` falls: [0, duration].
    double clipTime(double seconds) const;

    const ModelAnimation& animation() const { return animation_; }
    const PlaybackOptions& options() const { return options_; }

private:
    ModelAnimation animation_;
    PlaybackOptions options_;
    std::vector<Trs> pose_;  // scratch, one per animated node
};

}  // namespace arcomp
