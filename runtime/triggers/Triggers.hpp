#pragma once
// The config's triggers, run once a new video frame: each condition
// (runtime/triggers/Trigger.hpp) read from the frame's people and their
// zones, each firing doing its actions. Object actions happen here
// (runtime/triggers/ObjectActions.hpp); snapshots, clips and messages are
// handed to the station, which owns the outputs they go through.
//
//   Triggers triggers(cfg.triggers);
//   const TriggerFrame& t = triggers.update(station.people(), world);
//   for (const StationAction& a : t.forStation) outputs.run(*a.action);
//   for (const TriggerFiring& f : t.firings) log.write(f);
//
// Everything is on the frame's video time: dwell, cooldown, fades and
// turns, so two replays of a file fire the same triggers on the same
// frames. A dwell, count or near condition fires once when it becomes true
// and holds; its cooldown delays a firing rather than losing it (someone
// still there when it has passed sets it off). An enter or a leave within
// the cooldown is not fired, and counted.

#include "graph/core/World.hpp"
#include "runtime/people/PeopleFrame.hpp"
#include "runtime/triggers/ObjectActions.hpp"
#include "runtime/triggers/Trigger.hpp"

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace arcomp {

struct TriggerFiring {
    int trigger = 0;     // index into the triggers
    bool ended = false;  // true: a held condition stopped, its on_end ran
    int person = -1;     // enter, leave: who crossed; else -1
};

// An action the station carries out: a snapshot, a clip, an OSC or MQTT message.
struct StationAction {
    const TriggerAction* action;
    int trigger;
};

struct TriggerFrame {
    std::vector<TriggerFiring> firings;
    std::vector<StationAction> forStation;
    std::vector<std::string> problems;  // actions that could not be done, and why
};

struct TriggerCounts {
    std::uint64_t fired = 0;
    std::uint64_t ended = 0;
    std::uint64_t cooledDown = 0;  // an enter or a leave within the cooldown
};

class Triggers {
public:
    explicit Triggers(std::vector<Trigger> triggers);

    // Runs every trigger on `frame` (a new video frame, its zones filled)
    // and does the object actions on `world`, then brings fades and turns
    // to the frame's time.
    const TriggerFrame& update(const PeopleFrame& frame, World& world);

    const std::vector<Trigger>& triggers() const { return triggers_; }
    const TriggerFrame& last() const { return frame_; }
    const TriggerCounts& counts(std::size_t trigger) const { return state_[trigger].counts; }
    bool holds(std::size_t trigger) const { return state_[trigger].held; }
    // The same object actions, for cues from show control.
    ObjectActions& objects() { return objects_; }

private:
    struct State {
        bool held = false;
        double lastFired = -1e300;
        TriggerCounts counts;
    };
    // Whether the dwell, count or near condition is true this frame.
    bool holdsNow(const Trigger& t, const State& s, const PeopleFrame& frame, const World& world) const;
    void fire(int index, int person, const PeopleFrame& frame, World& world);
    void end(int index, const PeopleFrame& frame, World& world);
    void run(int index, const std::vector<TriggerAction>& actions, double seconds, World& world, bool starting);

    std::vector<Trigger> triggers_;
    std::vector<State> state_;
    // Per zone: who is in it, since which video second (for dwell).
    std::vector<std::map<int, double>> inZoneSince_;
    ObjectActions objects_;
    TriggerFrame frame_;
};

}  // namespace arcomp
