#include "runtime/showcontrol/MqttPeople.hpp"

#include "runtime/showcontrol/UdpSender.hpp"

#include <mosquitto.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>

namespace arcomp {
namespace {

// The first line of a credentials file; its contents never reach a message.
std::string firstLine(const std::filesystem::path& file, const std::string& key) {
    std::ifstream in(file);
    std::string line;
    if (!in || !std::getline(in, line) || in.bad())
        throw ShowControlError("show_control.mqtt." + key + ": cannot read '" + file.string() + "' (" +
                               std::strerror(errno ? errno : EIO) + ")");
    if (!line.empty() && line.back() == '\r') line.pop_back();
    return line;
}

std::string defaultClientId() {
    char host[256] = "station";
    gethostname(host, sizeof host - 1);
    return "arcomp-" + std::string(host) + "-" + std::to_string(getpid());
}

void check(int rc, const std::string& what) {
    if (rc != MOSQ_ERR_SUCCESS) throw ShowControlError("show_control.mqtt: " + what + ": " + mosquitto_strerror(rc));
}

nlohmann::json personJson(const Person& p, const std::vector<ZoneCount>& zones) {
    nlohmann::json in = nlohmann::json::array();
    for (const int z : p.zones) in.push_back(zones[static_cast<std::size_t>(z)].name);
    return {{"id", p.id},
            {"x", p.position.x},
            {"y", p.position.y},
            {"vx", p.velocity.x},
            {"vy", p.velocity.y},
            {"height_m", p.heightMetres},
            {"age_s", p.ageSeconds},
            {"seen", p.seen},
            {"box", {p.box.x, p.box.y, p.box.width, p.box.height}},
            {"zones", std::move(in)}};
}

}  // namespace

MqttPeople::MqttPeople(const MqttOutputConfig& cfg, std::string cueTopic)
    : cfg_(cfg), stateTopic_(cfg.topicPrefix + "/state"), cueTopic_(std::move(cueTopic)) {
    static std::once_flag initialised;
    std::call_once(initialised, [] { mosquitto_lib_init(); });
    status_.broker = cfg_.broker.text();
    status_.state = "connecting";
    std::string username, password;
    if (!cfg_.usernameFile.empty()) {
        username = firstLine(cfg_.usernameFile, "username_file");
        password = firstLine(cfg_.passwordFile, "password_file");
    }
    const std::string id = cfg_.clientId.empty() ? defaultClientId() : cfg_.clientId;
    client_ = mosquitto_new(id.c_str(), true, this);
    if (!client_)
        throw ShowControlError("show_control.mqtt: no MQTT client (" + std::string(std::strerror(errno)) + ")");
    try {
        mosquitto_connect_callback_set(client_, &MqttPeople::onConnect);
        mosquitto_disconnect_callback_set(client_, &MqttPeople::onDisconnect);
        mosquitto_message_callback_set(client_, &MqttPeople::onMessage);
        check(mosquitto_reconnect_delay_set(client_, 1, 30, true), "reconnect delay");
        static const char offline[] = "offline";
        check(mosquitto_will_set(client_, stateTopic_.c_str(), sizeof offline - 1, offline, 1, true), "last will");
        if (!username.empty())
            check(mosquitto_username_pw_set(client_, username.c_str(), password.c_str()), "username and password");
        if (!cfg_.caFile.empty())
            check(mosquitto_tls_set(client_, cfg_.caFile.c_str(), nullptr,
                                    cfg_.certFile.empty() ? nullptr : cfg_.certFile.c_str(),
                                    cfg_.keyFile.empty() ? nullptr : cfg_.keyFile.c_str(), nullptr),
                  "TLS files");
        // The network thread first: a first connect that fails is then retried
        // by it, with the backoff, like any later one.
        check(mosquitto_loop_start(client_), "network thread");
    } catch (...) {
        mosquitto_destroy(client_);
        throw;
    }
    const int rc = mosquitto_connect_async(client_, cfg_.broker.host.c_str(), cfg_.broker.port, cfg_.keepaliveSeconds);
    if (rc != MOSQ_ERR_SUCCESS) {
        std::lock_guard lock(mutex_);
        status_.state =
            std::string("disconnected: ") + (rc == MOSQ_ERR_ERRNO ? std::strerror(errno) : mosquitto_strerror(rc));
    }
}

MqttPeople::~MqttPeople() {
    bool connected = false;
    {
        std::lock_guard lock(mutex_);
        connected = status_.connected;
    }
    if (connected) {
        static const char offline[] = "offline";
        mosquitto_publish(client_, nullptr, stateTopic_.c_str(), sizeof offline - 1, offline, 1, true);
    }
    mosquitto_disconnect(client_);
    // A thread still trying to connect is stopped rather than waited for.
    mosquitto_loop_stop(client_, !connected);
    mosquitto_destroy(client_);
}

void MqttPeople::onConnect(mosquitto* client, void* self, int rc) {
    auto* m = static_cast<MqttPeople*>(self);
    std::lock_guard lock(m->mutex_);
    if (rc != 0) {
        m->refusal_ = mosquitto_connack_string(rc);
        m->status_.state = "disconnected: " + m->refusal_;
        return;
    }
    m->refusal_.clear();
    m->status_.connected = true;
    m->status_.state = "connected";
    if (m->connects_++ > 0) ++m->status_.reconnects;
    static const char online[] = "online";
    mosquitto_publish(client, nullptr, m->stateTopic_.c_str(), sizeof online - 1, online, 1, true);
    if (!m->cueTopic_.empty()) mosquitto_subscribe(client, nullptr, m->cueTopic_.c_str(), 1);
    while (!m->events_.empty() && m->send(m->events_.front(), 1)) m->events_.pop_front();
    m->status_.queued = m->events_.size();
}

void MqttPeople::onDisconnect(mosquitto*, void* self, int rc) {
    auto* m = static_cast<MqttPeople*>(self);
    std::lock_guard lock(m->mutex_);
    m->status_.connected = false;
    // The broker's own reason for refusing the connection says more than the code that follows it.
    const std::string why = !m->refusal_.empty() ? m->refusal_ : rc != 0 ? mosquitto_strerror(rc) : "";
    m->status_.state = why.empty() ? "disconnected" : "disconnected: " + why;
}

void MqttPeople::onMessage(mosquitto*, void* self, const mosquitto_message* message) {
    auto* m = static_cast<MqttPeople*>(self);
    std::lock_guard lock(m->mutex_);
    if (m->cueTopic_.empty() || message->topic != m->cueTopic_) return;
    m->cues_.push_back(message->payloadlen > 0 ? std::string(static_cast<const char*>(message->payload),
                                                             static_cast<std::size_t>(message->payloadlen))
                                               : std::string());
    if (m->cues_.size() > kHeldCues) {
        m->cues_.pop_front();
        ++m->status_.cuesDropped;
    }
}

std::vector<std::string> MqttPeople::takeCues() {
    std::lock_guard lock(mutex_);
    std::vector<std::string> out(std::make_move_iterator(cues_.begin()), std::make_move_iterator(cues_.end()));
    cues_.clear();
    return out;
}

bool MqttPeople::send(const Message& m, int qos) {
    if (!status_.connected) return false;
    const int rc = mosquitto_publish(client_, nullptr, m.topic.c_str(), static_cast<int>(m.payload.size()),
                                     m.payload.data(), qos, false);
    if (rc != MOSQ_ERR_SUCCESS) return false;
    ++status_.sent;
    return true;
}

void MqttPeople::sendEvent(Message m) {
    // Behind events already waiting, so that the order holds.
    if (events_.empty() && send(m, 1)) return;
    events_.push_back(std::move(m));
    while (events_.size() > static_cast<std::size_t>(cfg_.eventQueue)) {
        events_.pop_front();
        ++status_.dropped;
    }
    status_.queued = events_.size();
}

void MqttPeople::publishMessage(std::string topic, std::string payload) {
    std::lock_guard lock(mutex_);
    sendEvent({std::move(topic), std::move(payload)});
}

void MqttPeople::publish(const PeopleFrame& frame) {
    const std::string units = unitsName(frame.units);
    std::lock_guard lock(mutex_);
    for (const int id : frame.entered)
        if (const Person* p = findPerson(frame, id)) {
            nlohmann::json e = personJson(*p, frame.zones);
            e["frame"] = frame.frame;
            e["seconds"] = frame.seconds;
            e["units"] = units;
            sendEvent({cfg_.topicPrefix + "/enter", e.dump()});
        }
    for (const int id : frame.left)
        sendEvent({cfg_.topicPrefix + "/leave",
                   nlohmann::json{{"id", id}, {"frame", frame.frame}, {"seconds", frame.seconds}}.dump()});

    // Due at every 1 / rate seconds of video: the same frames on every replay.
    const auto slot = static_cast<std::int64_t>(std::floor(frame.seconds * cfg_.rateHz));
    if (slot <= lastPeopleSlot_) return;
    lastPeopleSlot_ = slot;
    nlohmann::json people = nlohmann::json::array();
    for (const Person& p : frame.people) people.push_back(personJson(p, frame.zones));
    nlohmann::json zones = nlohmann::json::array();
    for (const ZoneCount& z : frame.zones)
        zones.push_back({{"name", z.name}, {"people", z.people}, {"entries", z.entries}});
    const Message m{
        cfg_.topicPrefix + "/people",
        nlohmann::json{
            {"frame", frame.frame}, {"seconds", frame.seconds}, {"units", units}, {"people", people}, {"zones", zones}}
            .dump()};
    if (!send(m, 0)) ++status_.dropped;
}

MqttStatus MqttPeople::status() const {
    std::lock_guard lock(mutex_);
    return status_;
}

}  // namespace arcomp
