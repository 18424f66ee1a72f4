#pragma once
// The config's `triggers` list (runtime/triggers/Trigger.hpp): a condition
// on the visitors and what it sets off.
//
//   triggers:
//     - name: sign
//       when: {count: front, at_least: 1}       # or {enter: Z}, {leave: Z}, {dwell: Z, seconds: 3}, {near: dino,
//       metres: 1.5} do: [{show: sign}] on_end: [{hide: sign}]                  # once a dwell, count or near stops
//       holding cooldown: 1                             # video seconds between firings (default 1)
//
// Actions: {play: obj} (with animation: name), {pause: obj}, {stop: obj},
// {jump: obj, to: seconds}, {show: obj}, {hide: obj}, {fade: obj, to: 0..1,
// seconds: s}, {turn: obj, degrees_per_second: d} (while it holds),
// {snapshot: folder}, {clip: folder, seconds: s}, {osc: /address, args: [...]},
// {mqtt: topic, payload: text}. Each name is checked where it is written:
// a zone of `zones`, exactly one object of `scene.objects` by that name,
// an OSC or MQTT output to send through, a calibrated camera for `near`.

#include "runtime/triggers/Trigger.hpp"

#include <vector>

namespace arcomp {

class YamlMap;
struct ObjectConfig;
struct ShowControlConfig;
struct Zone;

struct TriggerContext {
    const std::vector<ObjectConfig>& objects;
    const std::vector<Zone>& zones;
    const ShowControlConfig& showControl;
    bool calibrated = false;
};

void readTriggerConfig(YamlMap& root, const TriggerContext& context, std::vector<Trigger>& out);

}  // namespace arcomp
