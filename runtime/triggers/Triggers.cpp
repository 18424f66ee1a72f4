#include "runtime/triggers/Triggers.hpp"

#include <algorithm>

namespace arcomp {

Triggers::Triggers(std::vector<Trigger> triggers) : triggers_(std::move(triggers)), state_(triggers_.size()) {}

bool Triggers::holdsNow(const Trigger& t, const State& s, const PeopleFrame& frame, const World& world) const {
    const TriggerCondition& c = t.when;
    const auto zone = static_cast<std::size_t>(c.zone);
    switch (c.event) {
    case TriggerEvent::Count: return zone < frame.zones.size() && frame.zones[zone].people >= c.atLeast;
    case TriggerEvent::Dwell:
        if (zone >= inZoneSince_.size()) return false;
        return std::any_of(inZoneSince_[zone].begin(), inZoneSince_[zone].end(),
                           [&](const auto& in) { return frame.seconds - in.second >= c.seconds; });
    case TriggerEvent::Near: {
        const NamedObject* object = findObject(world, c.object);
        if (!object || frame.units != PositionUnits::FloorMetres) return false;
        const glm::vec3 at = world.scene.world(object->node)[3];
        // Out again only beyond the margin, so that someone on the circle's edge does not flicker.
        const float reach = c.metres + (s.held ? c.margin : 0.0f);
        return std::any_of(frame.people.begin(), frame.people.end(),
                           [&](const Person& p) { return glm::length(p.position - glm::vec2(at.x, at.z)) < reach; });
    }
    default: return false;
    }
}

const TriggerFrame& Triggers::update(const PeopleFrame& frame, World& world) {
    frame_.firings.clear();
    frame_.forStation.clear();
    frame_.problems.clear();
    // Who has been in each zone since when.
    inZoneSince_.resize(frame.zones.size());
    for (std::size_t z = 0; z < inZoneSince_.size(); ++z) {
        std::map<int, double>& since = inZoneSince_[z];
        std::erase_if(since, [&](const auto& in) {
            const Person* p = findPerson(frame, in.first);
            return !p || std::find(p->zones.begin(), p->zones.end(), static_cast<int>(z)) == p->zones.end();
        });
        for (const Person& p : frame.people)
            if (std::find(p.zones.begin(), p.zones.end(), static_cast<int>(z)) != p.zones.end())
                since.emplace(p.id, frame.seconds);
    }
    for (std::size_t i = 0; i < triggers_.size(); ++i) {
        const Trigger& t = triggers_[i];
        State& s = state_[i];
        const int index = static_cast<int>(i);
        if (t.when.event == TriggerEvent::Enter || t.when.event == TriggerEvent::Leave) {
            const auto kind = t.when.event == TriggerEvent::Enter ? ZoneEvent::Kind::Enter : ZoneEvent::Kind::Leave;
            for (const ZoneEvent& e : frame.zoneEvents) {
                if (e.kind != kind || e.zone != t.when.zone) continue;
                if (frame.seconds >= s.lastFired + t.cooldownSeconds)
                    fire(index, e.person, frame, world);
                else
                    ++s.counts.cooledDown;
            }
            continue;
        }
        const bool now = holdsNow(t, s, frame, world);
        if (now && !s.held && frame.seconds >= s.lastFired + t.cooldownSeconds)
            fire(index, -1, frame, world);
        else if (!now && s.held)
            end(index, frame, world);
    }
    objects_.advance(world, frame.seconds);
    return frame_;
}

void Triggers::fire(int index, int person, const PeopleFrame& frame, World& world) {
    State& s = state_[static_cast<std::size_t>(index)];
    const Trigger& t = triggers_[static_cast<std::size_t>(index)];
    s.lastFired = frame.seconds;
    s.held = t.when.event != TriggerEvent::Enter && t.when.event != TriggerEvent::Leave;
    ++s.counts.fired;
    frame_.firings.push_back({index, false, person});
    run(index, t.actions, frame.seconds, world, true);
}

void Triggers::end(int index, const PeopleFrame& frame, World& world) {
    State& s = state_[static_cast<std::size_t>(index)];
    s.held = false;
    ++s.counts.ended;
    frame_.firings.push_back({index, true, -1});
    objects_.stopTurn(index);
    run(index, triggers_[static_cast<std::size_t>(index)].onEnd, frame.seconds, world, false);
}

void Triggers::run(int index, const std::vector<TriggerAction>& actions, double seconds, World& world, bool starting) {
    for (const TriggerAction& a : actions) {
        std::string problem;
        switch (a.kind) {
        case ActionKind::Snapshot:
        case ActionKind::Clip:
        case ActionKind::Osc:
        case ActionKind::Mqtt: frame_.forStation.push_back({&a, index}); break;
        case ActionKind::Turn:
            if (starting) problem = objects_.startTurn(world, a, seconds, index);
            break;
        default: problem = objects_.perform(world, a, seconds); break;
        }
        if (!problem.empty())
            frame_.problems.push_back("trigger '" + triggers_[static_cast<std::size_t>(index)].name + "' " +
                                      actionName(a.kind) + ": " + problem);
    }
}

}  // namespace arcomp
