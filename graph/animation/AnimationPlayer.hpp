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
// The clip time is a function of `seconds` and of the transport calls
// made on that clock (play, pause, stop, jump; a trigger or a cue makes
// them), so the same clock and the same calls give the same pose on every
// run (a replay is repeatable frame for frame). A new player is playing,
// from clip time 0 at clock 0.
//
//   player.stop();                // holds the clip's first pose
//   player.play(12.0);            // from the start, at clock second 12
//   player.pause(13.5);           // holds clip second 1.5 (at speed 1)
//   player.jump(0.25, 14.0);      // clip second 0.25, still held

#include "graph/animation/ModelAnimation.hpp"

#include <cstdint>

namespace arcomp {

struct PlaybackOptions {
    bool loop = true;    // wrap at the clip's end; false holds the last pose
    double speed = 1.0;  // clip seconds per clock second; must be positive
};

enum class Transport : std::uint8_t { Playing, Paused, Stopped };
const char* transportName(Transport t);  // "playing", "paused", "stopped"

class AnimationPlayer {
public:
    // Throws std::invalid_argument for a speed that is not a positive number.
    explicit AnimationPlayer(ModelAnimation animation, PlaybackOptions options = {});

    void apply(Scene& scene, double seconds);
    // Where in the clip `seconds` falls: [0, duration].
    double clipTime(double seconds) const;

    // From a stop: from the clip's start at `seconds`; from a pause: on from
    // where it was held; playing: nothing changes, unless a clip without
    // loop has reached its end, which starts again.
    void play(double seconds);
    void pause(double seconds);
    void stop();
    // Moves to `clipSeconds` (clamped to the clip) at `seconds`: playing on
    // from there, or held there (a stopped clip is then paused).
    void jump(double clipSeconds, double seconds);
    Transport transport() const { return transport_; }

    const ModelAnimation& animation() const { return animation_; }
    const PlaybackOptions& options() const { return options_; }

private:
    ModelAnimation animation_;
    PlaybackOptions options_;
    std::vector<Trs> pose_;  // scratch, one per animated node
    Transport transport_ = Transport::Playing;
    double origin_ = 0.0;  // the clock second at which play went on from held_
    double held_ = 0.0;    // clip seconds: where play went on from, or where it is held
};

}  // namespace arcomp
