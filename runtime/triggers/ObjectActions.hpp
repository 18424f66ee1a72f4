#pragma once
// What triggers and cues do to the scene's objects: play, pause, stop or
// jump in a model's animation, show, hide or fade an object, turn one at a
// set rate. Everything runs on the video's clock, so a replay does the same
// to the same frame.
//
//   ObjectActions objects;
//   std::string why = objects.perform(world, {.kind = ActionKind::Show, .object = "sign"}, seconds);
//   objects.advance(world, seconds);       // each frame: fades and turns in progress
//   animateObjects(world, seconds);        // then the players pose their models
//
// An action on an object the world does not have (a model that failed to
// load, a cue with a wrong name) does nothing and says why.

#include "graph/core/World.hpp"
#include "runtime/triggers/Trigger.hpp"

#include <string>
#include <vector>

namespace arcomp {

class ObjectActions {
public:
    // Play .. hide and fade; a turn goes through startTurn. Empty when done,
    // else why not ("no object 'x'; the objects: ...").
    std::string perform(World& world, const TriggerAction& action, double seconds);
    // Turns the object from `seconds` on until stopTurn(owner): `owner` is
    // the trigger that holds it (or the cue's own number).
    std::string startTurn(World& world, const TriggerAction& action, double seconds, int owner);
    void stopTurn(int owner);
    // Brings fades and turns to `seconds`.
    void advance(World& world, double seconds);

    std::size_t turning() const { return turns_.size(); }
    std::size_t fading() const { return fades_.size(); }

private:
    struct Fade {
        NodeId node;
        float from, to;
        double start, seconds;
    };
    struct Turn {
        int owner;
        NodeId node;
        glm::mat4 rest;  // the local matrix the turn started from
        glm::vec3 axis;
        float degreesPerSecond;
        double start;
    };
    std::string animate(World& world, const NamedObject& object, const TriggerAction& action, double seconds);

    std::vector<Fade> fades_;
    std::vector<Turn> turns_;
};

}  // namespace arcomp
