#include "runtime/showcontrol/ShowControl.hpp"

#include "runtime/showcontrol/OscBundle.hpp"
#include "runtime/showcontrol/OscPeople.hpp"

#include <stdexcept>

namespace arcomp {

ShowControl::ShowControl(const ShowControlConfig& cfg) : tuio_(cfg.tuio.floorMin, cfg.tuio.floorMax) {
    auto open = [this](const NetworkTarget& target, const char* kind, bool tuio) {
        OutputStatus s;
        s.kind = kind;
        s.target = target.text();
        s.state = "sending";
        Route route{.sender = std::nullopt, .status = status_.size(), .tuio = tuio};
        try {
            route.sender.emplace(target);
        } catch (const ShowControlError& e) {
            s.state = std::string("off: ") + e.what();
            problems_.push_back(std::string(kind) + " output off: " + e.what());
        }
        status_.push_back(std::move(s));
        routes_.push_back(std::move(route));
    };
    for (const NetworkTarget& t : cfg.osc.targets) open(t, "osc", false);
    for (const NetworkTarget& t : cfg.tuio.targets) open(t, "tuio", true);
    if (cfg.mqtt.enabled) {
        try {
            mqtt_ = std::make_unique<MqttPeople>(cfg.mqtt, cfg.cues.mqtt ? cfg.mqtt.topicPrefix + "/cue" : "");
        } catch (const ShowControlError& e) {
            // Off for the run: its status stays as it is now, after the others'.
            OutputStatus s;
            s.kind = "mqtt";
            s.target = cfg.mqtt.broker.text();
            s.state = std::string("off: ") + e.what();
            status_.push_back(std::move(s));
            problems_.push_back(std::string("mqtt output off: ") + e.what());
        }
    }
}

std::vector<OutputStatus> ShowControl::outputs() const {
    std::vector<OutputStatus> out = status_;
    if (mqtt_) {
        const MqttStatus m = mqtt_->status();
        OutputStatus s;
        s.kind = "mqtt";
        s.target = m.broker;
        s.state = m.state;
        s.sent = m.sent;
        s.dropped = m.dropped;
        s.queued = m.queued;
        out.push_back(std::move(s));
    }
    return out;
}

std::chrono::steady_clock::time_point ShowControl::publish(const PeopleFrame& frame) {
    // Each kind's bundle is made once a frame, for all its targets.
    std::optional<std::vector<std::uint8_t>> osc, tuio;
    for (Route& route : routes_) {
        if (!route.sender) continue;
        std::optional<std::vector<std::uint8_t>>& bytes = route.tuio ? tuio : osc;
        if (!bytes) bytes = route.tuio ? tuio_.bundle(frame) : oscPeopleBundle(frame);
        sendOn(route, *bytes);
    }
    const auto sent = std::chrono::steady_clock::now();
    if (mqtt_) mqtt_->publish(frame);
    return sent;
}

}  // namespace arcomp

namespace arcomp {

void ShowControl::send(const TriggerAction& message) {
    if (message.kind == ActionKind::Mqtt) {
        if (mqtt_) mqtt_->publishMessage(message.address, message.payload);
        return;
    }
    if (message.kind != ActionKind::Osc)
        throw std::invalid_argument(std::string("show control sends osc and mqtt messages, not '") +
                                    actionName(message.kind) + "'");
    OscBundle bundle;
    OscBundle::Message m = bundle.add(message.address.c_str());
    for (const OscArgument& a : message.args) {
        if (a.type == OscArgument::Type::Int) m.i(a.i);
        if (a.type == OscArgument::Type::Float) m.f(a.f);
        if (a.type == OscArgument::Type::String) m.s(a.s.c_str());
    }
    const std::vector<std::uint8_t> bytes = bundle.bytes();
    for (Route& route : routes_)
        if (route.sender && !route.tuio) sendOn(route, bytes);
}

void ShowControl::sendOn(Route& route, const std::vector<std::uint8_t>& bytes) {
    OutputStatus& s = status_[route.status];
    if (route.sender->send(bytes)) {
        ++s.sent;
    } else {
        ++s.dropped;
        s.lastError = route.sender->lastError();
    }
}

}  // namespace arcomp
