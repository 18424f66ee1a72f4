#include "runtime/StatusServer.hpp"

#include <httplib.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>

namespace arcomp {

struct StatusServer::Impl {
    httplib::Server server;
    std::thread thread;
    std::atomic<bool> ended{false};
};

StatusServer::StatusServer(const StationMetrics& metrics, const StatusEndpoint& endpoint) : impl_(std::make_unique<Impl>()) {
    httplib::Server& server = impl_->server;
    server.Get("/status", [&metrics](const httplib::Request&, httplib::Response& response) {
        response.set_content(metrics.statusJson(), "application/json");
    });
    server.Get("/metrics", [&metrics](const httplib::Request&, httplib::Response& response) {
        response.set_content(metrics.prometheusText(), "text/plain; version=0.0.4");
    });
    // Two workers are plenty for a scraper and a person with curl, and keep
    // the station's CPU for frames.
    // httplib's default adds SO_REUSEPORT, which would let a second station
    // share the port and answer half the scrapes. Only SO_REUSEADDR, so a
    // restarted station can bind again while old connections linger.
    server.set_socket_options([](socket_t socket) {
        int yes = 1;
        setsockopt(socket, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
    });
    server.new_task_queue = [] { return new httplib::ThreadPool(2); };

    if (endpoint.port == 0) port_ = server.bind_to_any_port(endpoint.bind);
    else port_ = server.bind_to_port(endpoint.bind, endpoint.port) ? endpoint.port : -1;
    if (port_ <= 0)
        throw std::runtime_error("status server: cannot listen on " + endpoint.bind + ":" + std::to_string(endpoint.port) +
                                 " (address in use, or not an address of this machine)");
    std::atomic<bool>& ended = impl_->ended;
    impl_->thread = std::thread([&server, &ended] {
        server.listen_after_bind();
        ended = true;
    });
    // httplib's stop() does nothing until the accept loop runs; wait for it
    // so that a server destroyed at once still shuts down.
    while (!server.is_running() && !ended) std::this_thread::sleep_for(std::chrono::milliseconds(1));
}

StatusServer::~StatusServer() {
    impl_->server.stop();
    if (impl_->thread.joinable()) impl_->thread.join();
}

} // namespace arcomp
