#pragma once
// A real MQTT client reading back what the station published, through
// libmosquitto: subscribed to one topic filter at QoS 1 before it returns;
// it also publishes, as show control sending the station a cue would.
//
//   MqttSubscriber sub(broker.port(), "arcomp/#");
//   sub.waitFor([](const auto& got) { return got.size() >= 3; }, std::chrono::seconds(5));

#include <mosquitto.h>

#include <chrono>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

namespace arcomp::test {

class MqttSubscriber {
public:
    struct Message {
        std::string topic, payload;
        int qos = 0;
        bool retained = false;
    };

    MqttSubscriber(int port, const std::string& filter) {
        mosquitto_lib_init();
        client_ = mosquitto_new(nullptr, true, this);
        mosquitto_message_callback_set(client_, [](mosquitto*, void* self, const mosquitto_message* m) {
            auto* s = static_cast<MqttSubscriber*>(self);
            std::lock_guard lock(s->mutex_);
            s->messages_.push_back(
                {m->topic, std::string(static_cast<const char*>(m->payload), m->payloadlen), m->qos, m->retain});
            s->arrived_.notify_all();
        });
        mosquitto_subscribe_callback_set(client_, [](mosquitto*, void* self, int, int, const int*) {
            auto* s = static_cast<MqttSubscriber*>(self);
            std::lock_guard lock(s->mutex_);
            s->subscribed_ = true;
            s->arrived_.notify_all();
        });
        if (mosquitto_connect(client_, "127.0.0.1", port, 10) != MOSQ_ERR_SUCCESS ||
            mosquitto_subscribe(client_, nullptr, filter.c_str(), 1) != MOSQ_ERR_SUCCESS ||
            mosquitto_loop_start(client_) != MOSQ_ERR_SUCCESS)
            throw std::runtime_error("MqttSubscriber: cannot subscribe to " + filter);
        std::unique_lock lock(mutex_);
        if (!arrived_.wait_for(lock, std::chrono::seconds(5), [this] { return subscribed_; }))
            throw std::runtime_error("MqttSubscriber: no SUBACK for " + filter);
    }
    ~MqttSubscriber() {
        mosquitto_disconnect(client_);
        mosquitto_loop_stop(client_, false);
        mosquitto_destroy(client_);
    }

    // As show control would: QoS 1, so it reaches a subscriber that is connected.
    void publish(const std::string& topic, const std::string& payload) {
        if (mosquitto_publish(client_, nullptr, topic.c_str(), static_cast<int>(payload.size()), payload.data(), 1,
                              false) != MOSQ_ERR_SUCCESS)
            throw std::runtime_error("MqttSubscriber: cannot publish to " + topic);
    }

    // Waits until `done` holds for what has arrived, or `wait` passes; gives what arrived.
    std::vector<Message> waitFor(const std::function<bool(const std::vector<Message>&)>& done,
                                 std::chrono::milliseconds wait) {
        std::unique_lock lock(mutex_);
        arrived_.wait_for(lock, wait, [&] { return done(messages_); });
        return messages_;
    }

private:
    mosquitto* client_ = nullptr;
    std::mutex mutex_;
    std::condition_variable arrived_;
    std::vector<Message> messages_;
    bool subscribed_ = false;
};

}  // namespace arcomp::test
