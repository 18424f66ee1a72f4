#pragma once
// Where the station's people go each frame: OSC bundles in the /arcomp
// address space (runtime/showcontrol/OscPeople.hpp) and TUIO 1.1 cursors
// (runtime/showcontrol/TuioCursors.hpp) to every target, and JSON to an
// MQTT broker (runtime/showcontrol/MqttPeople.hpp), as the config's
// `show_control` section says (runtime/config/ShowControlConfig.hpp).
//
//   ShowControl show(cfg.showControl);
//   for (const std::string& p : show.problems()) log.warn(p);   // a target that is off, and why
//   show.publish(station.people());                              // each new frame; never blocks
//
// A target whose host does not resolve, or an MQTT output whose
// credentials cannot be read, is off for the run, and says so in
// problems() and in its status; the others go on. A datagram the socket
// cannot take at once is dropped and counted, never waited for.

#include "runtime/config/ShowControlConfig.hpp"
#include "runtime/people/PeopleFrame.hpp"
#include "runtime/showcontrol/MqttPeople.hpp"
#include "runtime/showcontrol/TuioCursors.hpp"
#include "runtime/showcontrol/UdpSender.hpp"
#include "runtime/triggers/Trigger.hpp"

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace arcomp {

// One output's state, as /status and /metrics show it.
struct OutputStatus {
    std::string kind;    // "osc", "tuio", "mqtt"
    std::string target;  // "127.0.0.1:9000"; mqtt: the broker
    std::string state;   // "sending", "off: <why>"; mqtt: "connected", "connecting", "disconnected: <why>"
    std::uint64_t sent = 0, dropped = 0;
    std::uint64_t queued = 0;  // mqtt: enter and leave events waiting for the broker
    std::string lastError;     // why the last datagram was dropped
};

class ShowControl {
public:
    explicit ShowControl(const ShowControlConfig& cfg);

    // Gives when the OSC and TUIO datagrams had left (MQTT's leave on its own thread).
    std::chrono::steady_clock::time_point publish(const PeopleFrame& frame);

    // A trigger's OSC message (to every OSC target, not TUIO's) or MQTT
    // message; other actions are not messages and are refused
    // (std::invalid_argument). Never blocks, as publish().
    void send(const TriggerAction& message);

    // The MQTT cue topic's payloads since the last call (show_control.cues.mqtt).
    std::vector<std::string> takeMqttCues() { return mqtt_ ? mqtt_->takeCues() : std::vector<std::string>{}; }

    // Every output's state now (MQTT's changes on its own thread).
    std::vector<OutputStatus> outputs() const;
    const std::vector<std::string>& problems() const { return problems_; }
    bool empty() const { return routes_.empty() && !mqtt_; }  // nothing to send to

private:
    struct Route {
        std::optional<UdpSender> sender;  // none: off
        std::size_t status;               // index in status_
        bool tuio;
    };
    void sendOn(Route& route, const std::vector<std::uint8_t>& bytes);

    TuioCursors tuio_;
    std::vector<Route> routes_;
    std::vector<OutputStatus> status_;  // OSC and TUIO in routes_' order, then an MQTT output that is off
    std::unique_ptr<MqttPeople> mqtt_;
    std::vector<std::string> problems_;
};

}  // namespace arcomp
