#include "runtime/config/TriggerConfig.hpp"

#include "runtime/config/ShowControlConfig.hpp"
#include "runtime/config/StationConfig.hpp"
#include "runtime/config/YamlMap.hpp"

#include <algorithm>
#include <cstring>
#include <set>

namespace arcomp {
namespace {

// The one key of `keys` that the map has; reports none or several.
std::optional<std::string> oneOf(YamlMap& m, const std::vector<std::string>& keys, const std::string& what) {
    std::vector<std::string> given;
    for (const std::string& k : keys)
        if (m.has(k.c_str())) given.push_back(k);
    if (given.size() == 1) return given[0];
    std::string list;
    for (const std::string& k : keys) list += (list.empty() ? "" : ", ") + k;
    m.report().add(m.mark(), m.where() + ": expected one " + what + " of " + list + "; it has " +
                                 (given.empty() ? std::string("none") : std::to_string(given.size())));
    return std::nullopt;
}

// A name at `key` that must be one of `names`; reported at its place.
std::string knownName(YamlMap& m, const char* key, const std::vector<std::string>& names, const char* what,
                      const char* listName) {
    const YAML::Node n = m.take(key);
    const std::string where = m.where() + "." + key;
    if (!n.IsScalar() || n.Scalar().empty()) {
        m.report().add(n.Mark(), where + ": expected the name of a " + what);
        return {};
    }
    const std::string name = n.Scalar();
    const auto count = std::count(names.begin(), names.end(), name);
    if (count == 1) return name;
    std::string known;
    for (const std::string& s : std::set<std::string>(names.begin(), names.end()))
        if (!s.empty()) known += (known.empty() ? "" : ", ") + s;
    m.report().add(n.Mark(), where + ": " + (count == 0 ? "no " : "more than one ") + what + " is named '" + name +
                                 "' in " + listName + (known.empty() ? " (it has none)" : "; the names: " + known));
    return {};
}

std::vector<std::string> objectNames(const TriggerContext& c) {
    std::vector<std::string> out;
    for (const ObjectConfig& o : c.objects) out.push_back(o.name);
    return out;
}

std::vector<std::string> zoneNames(const TriggerContext& c) {
    std::vector<std::string> out;
    for (const Zone& z : c.zones) out.push_back(z.name);
    return out;
}

std::optional<TriggerCondition> readCondition(YamlMap& m, const TriggerContext& context) {
    const auto event = oneOf(m, {"enter", "leave", "dwell", "count", "near"}, "event");
    if (!event) return std::nullopt;
    TriggerCondition c;
    bool ok = true;
    if (*event == "near") {
        c.event = TriggerEvent::Near;
        c.object = knownName(m, "near", objectNames(context), "object", "scene.objects");
        ok = !c.object.empty();
        m.number("metres", c.metres, 0.01, 1000.0, Required::Yes);
        m.number("margin", c.margin, 0.0, 100.0);
        if (!context.calibrated) {
            m.report().add(m.mark(), m.where() + ".near: a distance on the floor needs camera.calibration");
            ok = false;
        }
    } else {
        c.event = *event == "enter"   ? TriggerEvent::Enter
                  : *event == "leave" ? TriggerEvent::Leave
                  : *event == "dwell" ? TriggerEvent::Dwell
                                      : TriggerEvent::Count;
        const std::vector<std::string> zones = zoneNames(context);
        const std::string zone = knownName(m, event->c_str(), zones, "zone", "zones");
        ok = !zone.empty();
        if (ok) c.zone = static_cast<int>(std::find(zones.begin(), zones.end(), zone) - zones.begin());
        if (c.event == TriggerEvent::Dwell) m.number("seconds", c.seconds, 0.0, 86400.0, Required::Yes);
        if (c.event == TriggerEvent::Count) m.integer("at_least", c.atLeast, 1, 1000, Required::Yes);
    }
    m.finish();
    return ok ? std::optional(c) : std::nullopt;
}

std::vector<OscArgument> oscArguments(const YAML::Node& list, const std::string& where, ConfigReport& report) {
    std::vector<OscArgument> out;
    if (!list.IsSequence()) {
        report.add(list.Mark(), where + ": expected a list of integers, numbers and texts, e.g. [1, 0.5, go]");
        return out;
    }
    for (const YAML::Node& a : list) {
        OscArgument arg;
        if (!a.IsScalar()) {
            report.add(a.Mark(), where + ": expected an integer, a number or a text");
            continue;
        }
        std::int32_t i = 0;
        float f = 0.0f;
        // YAML gives no types to plain scalars: an integer first, then a number, else a text.
        if (a.Tag() != "!" && YAML::convert<std::int32_t>::decode(a, i))
            arg = {.type = OscArgument::Type::Int, .i = i};
        else if (a.Tag() != "!" && YAML::convert<float>::decode(a, f))
            arg = {.type = OscArgument::Type::Float, .f = f};
        else
            arg = {.type = OscArgument::Type::String, .s = a.Scalar()};
        out.push_back(std::move(arg));
    }
    return out;
}

// `when`: the trigger's condition; null when it was wrong, which leaves
// out the checks that depend on it.
std::optional<TriggerAction> readAction(YamlMap& m, const TriggerContext& context, const TriggerCondition* when) {
    std::vector<std::string> keys;
    for (int k = 0; k < kActionKinds; ++k) keys.emplace_back(actionName(static_cast<ActionKind>(k)));
    const auto word = oneOf(m, keys, "action");
    if (!word) {
        for (const std::string& k : keys) m.take(k.c_str());
        return std::nullopt;
    }
    TriggerAction a;
    a.kind = *actionKind(*word);
    bool ok = true;
    ConfigReport& report = m.report();
    const std::string where = m.where() + "." + *word;
    switch (a.kind) {
    case ActionKind::Play:
    case ActionKind::Pause:
    case ActionKind::Stop:
    case ActionKind::Jump:
    case ActionKind::Show:
    case ActionKind::Hide:
    case ActionKind::Fade:
    case ActionKind::Turn: {
        a.object = knownName(m, word->c_str(), objectNames(context), "object", "scene.objects");
        ok = !a.object.empty();
        const auto object = std::find_if(context.objects.begin(), context.objects.end(),
                                         [&](const ObjectConfig& o) { return o.name == a.object; });
        const bool animates = a.kind == ActionKind::Play || a.kind == ActionKind::Pause || a.kind == ActionKind::Stop ||
                              a.kind == ActionKind::Jump;
        if (ok && animates && object->model.empty()) {
            report.add(m.mark(), where + ": object '" + a.object + "' is a shape; only a model has animations");
            ok = false;
        }
        if (a.kind == ActionKind::Play) m.text("animation", a.animation);
        if (a.kind == ActionKind::Jump) m.number("to", a.seconds, 0.0, 86400.0, Required::Yes);
        if (a.kind == ActionKind::Fade) {
            m.number("to", a.opacity, 0.0, 1.0, Required::Yes);
            m.number("seconds", a.seconds, 0.0, 3600.0, Required::Yes);
        }
        if (a.kind == ActionKind::Turn) {
            m.number("degrees_per_second", a.degreesPerSecond, -3600.0, 3600.0, Required::Yes);
            m.vec3("axis", a.axis);
            if (!(glm::length(a.axis) > 1e-6f)) {
                report.add(m.mark(), where + ".axis: expected a direction, not zero");
                ok = false;
            }
            if (when && (when->event == TriggerEvent::Enter || when->event == TriggerEvent::Leave)) {
                report.add(m.mark(), where + ": turns while its trigger holds, and an " + eventName(when->event) +
                                         " holds for one frame; use count, dwell or near");
                ok = false;
            }
            if (ok && glm::length(object->velocity) > 0.0f) {
                report.add(m.mark(), where + ": object '" + a.object +
                                         "' is a mover (velocity), whose place is set each frame; turn another");
                ok = false;
            }
        }
        break;
    }
    case ActionKind::Snapshot:
    case ActionKind::Clip:
        m.path(word->c_str(), a.folder, false, Required::Yes);
        if (a.kind == ActionKind::Clip) m.number("seconds", a.seconds, 0.1, 600.0, Required::Yes);
        break;
    case ActionKind::Osc: {
        m.text("osc", a.address, Required::Yes);
        if (a.address.empty() || a.address[0] != '/' || a.address.find_first_of(" #*,?[]{}") != std::string::npos) {
            report.add(m.mark(), where + ": expected an OSC address such as /show/cue (starts with /, no spaces or "
                                         "#*,?[]{})");
            ok = false;
        }
        if (m.has("args")) a.args = oscArguments(m.take("args"), where + ".args", report);
        if (context.showControl.osc.targets.empty()) {
            report.add(m.mark(), where + ": there is no show_control.osc target to send it to");
            ok = false;
        }
        break;
    }
    case ActionKind::Mqtt:
        m.text("mqtt", a.address, Required::Yes);
        if (a.address.empty() || a.address.find_first_of("+#") != std::string::npos) {
            report.add(m.mark(), where + ": expected a topic to publish to (no + or # wildcards)");
            ok = false;
        }
        m.text("payload", a.payload);
        if (!context.showControl.mqtt.enabled) {
            report.add(m.mark(), where + ": show_control.mqtt is not configured; there is no broker to publish to");
            ok = false;
        }
        break;
    }
    m.finish();
    return ok ? std::optional(std::move(a)) : std::nullopt;
}

}  // namespace

void readTriggerConfig(YamlMap& root, const TriggerContext& context, std::vector<Trigger>& out) {
    std::set<std::string> names;
    auto triggers = root.list("triggers");
    for (std::size_t i = 0; i < triggers.size(); ++i) {
        YamlMap& t = triggers[i];
        Trigger trigger;
        trigger.line = t.mark().line + 1;
        t.text("name", trigger.name, Required::Yes);
        if (t.has("name") && trigger.name.empty())
            t.report().add(t.mark(), t.where() + ".name: empty; a trigger needs a name for its events and metrics");
        if (!trigger.name.empty() && !names.insert(trigger.name).second)
            t.report().add(t.mark(), t.where() + " '" + trigger.name +
                                         "': the name is used by an earlier trigger; each trigger needs its own");
        YamlMap when = t.map("when", Required::Yes);
        const std::optional<TriggerCondition> condition = readCondition(when, context);
        bool ok = condition.has_value();
        if (condition) trigger.when = *condition;
        auto actions = [&](const char* key, std::vector<TriggerAction>& into) {
            for (YamlMap& a : t.list(key, std::strcmp(key, "do") == 0 ? Required::Yes : Required::No)) {
                if (auto action = readAction(a, context, condition ? &*condition : nullptr))
                    into.push_back(std::move(*action));
                else
                    ok = false;
            }
        };
        actions("do", trigger.actions);
        actions("on_end", trigger.onEnd);
        if (std::any_of(trigger.onEnd.begin(), trigger.onEnd.end(),
                        [](const TriggerAction& a) { return a.kind == ActionKind::Turn; })) {
            t.report().add(t.mark(), t.where() + ".on_end: a turn lasts while its trigger holds; put it in 'do'");
            ok = false;
        }
        if (condition && !trigger.onEnd.empty() &&
            (trigger.when.event == TriggerEvent::Enter || trigger.when.event == TriggerEvent::Leave)) {
            t.report().add(t.mark(), t.where() + ".on_end: an " + eventName(trigger.when.event) +
                                         " does not hold, so it never ends; use count, dwell or near");
            ok = false;
        }
        t.number("cooldown", trigger.cooldownSeconds, 0.0, 86400.0);
        t.finish();
        if (ok) out.push_back(std::move(trigger));
    }
}

}  // namespace arcomp
