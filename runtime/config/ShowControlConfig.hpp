#pragma once
// The config's `show_control` section: where the station sends its people
// (runtime/showcontrol/ShowControl.hpp). Absent: it sends nothing.
//
//   show_control:
//     osc:  {targets: ["127.0.0.1:9000", "10.0.0.20:7000"]}    # the /arcomp address space
//     tuio: {targets: ["127.0.0.1:3333"], floor: {min: [-4, -6], max: [4, 3]}}
//     mqtt: {broker: "127.0.0.1:1883", topic_prefix: arcomp/entrance, rate_hz: 5}
//     cues:                                                      # show control in (runtime/triggers/Cue.hpp)
//       osc: {listen: "127.0.0.1:9100", allow: ["127.0.0.1"]}    # loopback by default
//       mqtt: true                                               # <topic_prefix>/cue on the broker above
//       snapshot_folder: snapshots
//
// OSC has no credentials: listening beyond loopback needs `allow`, the
// senders' addresses, and then only they are heard (loopback's too only
// when listed). The MQTT cue topic uses the broker's own credentials.
//
// TUIO's floor is the rectangle (x, z in metres, the calibration's floor
// frame) that TUIO's 0..1 square covers: x to the right, z towards the
// camera downwards. Without a calibrated camera TUIO sends the picture's
// 0..1 and the floor is not used.

#include <glm/vec2.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace arcomp {

class YamlMap;

// One place to send to, as the config wrote it.
struct NetworkTarget {
    std::string host;
    int port = 0;
    std::string where;  // "show_control.osc.targets[0]", for messages about it
    std::string text() const { return host + ":" + std::to_string(port); }
};

struct OscOutputConfig {
    std::vector<NetworkTarget> targets;
};

struct TuioOutputConfig {
    std::vector<NetworkTarget> targets;
    glm::vec2 floorMin{-5.0f, -5.0f}, floorMax{5.0f, 5.0f};  // x, z
};

// The station as a client of an MQTT broker (never a broker itself).
// Credentials and TLS come from files, so that the config can be shared
// and no secret is ever in it, a log line or /status.
struct MqttOutputConfig {
    bool enabled = false;
    NetworkTarget broker;
    std::string topicPrefix = "arcomp";  // topics: <prefix>/people, /enter, /leave, /state
    std::string clientId;                // empty: arcomp-<host name>-<process id>
    double rateHz = 5.0;                 // people messages a second of video time
    int keepaliveSeconds = 10;
    int eventQueue = 1000;                             // enter and leave events held while the broker is away
    std::filesystem::path usernameFile, passwordFile;  // first line each; both or neither
    std::filesystem::path caFile, certFile, keyFile;   // caFile: TLS on; cert and key: a client certificate
};

struct CueInputConfig {
    bool osc = false;
    NetworkTarget listen{.host = "127.0.0.1", .port = 0, .where = "show_control.cues.osc.listen"};
    std::vector<std::string> allow{};  // IPv4 senders; empty: any on loopback (bound there only)
    bool mqtt = false;                 // <topic_prefix>/cue
    std::filesystem::path snapshotFolder{};
};

struct ShowControlConfig {
    OscOutputConfig osc;
    TuioOutputConfig tuio;
    MqttOutputConfig mqtt;
    CueInputConfig cues;
};

void readShowControlConfig(YamlMap& root, ShowControlConfig& out);

}  // namespace arcomp
