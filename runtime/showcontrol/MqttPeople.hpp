#pragma once
// The station's people to an MQTT broker, through libmosquitto: the station
// is the broker's client, never a broker, and a fleet of stations shares
// one (mosquitto, or a cluster such as EMQX). Topics under the config's
// prefix:
//   <prefix>/people  JSON, QoS 0, at rate_hz in video time (a replay repeats)
//   <prefix>/enter   JSON, QoS 1, each id's first frame
//   <prefix>/leave   JSON, QoS 1, the frame after its last
//   <prefix>/state   "online", or the broker's "offline" when the station is gone (retained)
//
//   MqttPeople mqtt(cfg.showControl.mqtt);   // throws ShowControlError: a credentials file it cannot read
//   mqtt.publish(station.people());          // each new frame; never waits on the network
//
// libmosquitto's own network thread connects, and reconnects with backoff
// (1 s doubling to 30 s) while the broker is away; the frame never waits
// on it. Meanwhile people messages are dropped (a stale position is no
// use), and enter and leave events are held, up to `event_queue`, then
// sent in order once the broker is back; the oldest beyond that bound are
// dropped. Every drop is counted.

#include "runtime/config/ShowControlConfig.hpp"
#include "runtime/people/PeopleFrame.hpp"

#include <cstdint>
#include <deque>
#include <mutex>
#include <string>
#include <vector>

struct mosquitto;
struct mosquitto_message;

namespace arcomp {

struct MqttStatus {
    std::string broker;  // host:port
    std::string state;   // "connected", "connecting", "disconnected: <why>"
    bool connected = false;
    std::uint64_t sent = 0;     // handed to the client for the broker
    std::uint64_t dropped = 0;  // people while away, events beyond the queue
    std::uint64_t queued = 0;   // events waiting for the broker
    std::uint64_t reconnects = 0;
    std::uint64_t cuesDropped = 0;  // cue messages beyond kHeldCues between two frames
};

class MqttPeople {
public:
    // `cueTopic`: subscribed to (QoS 1) on each connect; its messages wait
    // for takeCues(), at most kHeldCues (the oldest go, counted).
    explicit MqttPeople(const MqttOutputConfig& cfg, std::string cueTopic = {});
    ~MqttPeople();
    MqttPeople(const MqttPeople&) = delete;
    MqttPeople& operator=(const MqttPeople&) = delete;

    void publish(const PeopleFrame& frame);
    // A trigger's message to its own topic, QoS 1, held like an enter event
    // while the broker is away.
    void publishMessage(std::string topic, std::string payload);
    MqttStatus status() const;
    // The cue topic's payloads since the last call, oldest first.
    std::vector<std::string> takeCues();
    static constexpr std::size_t kHeldCues = 256;

private:
    struct Message {
        std::string topic, payload;
    };
    static void onConnect(mosquitto*, void* self, int rc);
    static void onDisconnect(mosquitto*, void* self, int rc);
    static void onMessage(mosquitto*, void* self, const struct mosquitto_message* message);
    // Hands one message to the client; false when it is not connected.
    bool send(const Message& m, int qos);
    void sendEvent(Message m);

    MqttOutputConfig cfg_;
    mosquitto* client_ = nullptr;
    std::string stateTopic_;
    mutable std::mutex mutex_;  // the frame's thread and the client's network thread
    MqttStatus status_;
    std::deque<Message> events_;  // held while the broker is away, oldest first
    std::int64_t lastPeopleSlot_ = -1;
    std::uint64_t connects_ = 0;
    std::string refusal_;  // the broker's reason, while it refuses the connection
    std::string cueTopic_;
    std::deque<std::string> cues_;
};

}  // namespace arcomp
