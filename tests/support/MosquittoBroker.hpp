#pragma once
// A real mosquitto broker for the tests, on loopback only, on a free port,
// started and stopped by the test (Debian's `mosquitto` package).
//
//   MosquittoBroker broker(dir.path());              // anonymous clients
//   MosquittoBroker strict(dir.path(), "user", "pw"); // only this user
//   broker.stop();  broker.start();                  // the same port again

#include <netinet/in.h>
#include <signal.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <thread>

extern char** environ;

namespace arcomp::test {

// A TCP port on 127.0.0.1 that nothing listens on now.
inline int freeLoopbackPort() {
    const int fd = socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t length = sizeof a;
    bind(fd, reinterpret_cast<sockaddr*>(&a), sizeof a);
    getsockname(fd, reinterpret_cast<sockaddr*>(&a), &length);
    close(fd);
    return ntohs(a.sin_port);
}

inline bool acceptsConnections(int port) {
    const int fd = socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in a{};
    a.sin_family = AF_INET;
    a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    a.sin_port = htons(static_cast<std::uint16_t>(port));
    const bool ok = connect(fd, reinterpret_cast<sockaddr*>(&a), sizeof a) == 0;
    close(fd);
    return ok;
}

class MosquittoBroker {
public:
    static constexpr const char* kBinary = "/usr/sbin/mosquitto";
    static bool installed() { return std::filesystem::exists(kBinary); }

    explicit MosquittoBroker(const std::filesystem::path& folder, const std::string& user = "",
                             const std::string& password = "", int port = 0)
        : folder_(folder), port_(port ? port : freeLoopbackPort()) {
        std::ofstream conf(folder_ / "mosquitto.conf");
        conf << "listener " << port_ << " 127.0.0.1\n";
        if (user.empty()) {
            conf << "allow_anonymous true\n";
        } else {
            const std::string passwd = (folder_ / "passwd").string();
            const std::string command = "mosquitto_passwd -b -c '" + passwd + "' '" + user + "' '" + password + "'";
            if (std::system(command.c_str()) != 0) throw std::runtime_error("MosquittoBroker: " + command);
            conf << "allow_anonymous false\npassword_file " << passwd << "\n";
        }
        conf.close();
        start();
    }
    ~MosquittoBroker() { stop(); }
    MosquittoBroker(const MosquittoBroker&) = delete;
    MosquittoBroker& operator=(const MosquittoBroker&) = delete;

    int port() const { return port_; }
    std::string address() const { return "127.0.0.1:" + std::to_string(port_); }

    // Starts it and waits until it takes connections.
    void start() {
        const std::string conf = (folder_ / "mosquitto.conf").string();
        const char* argv[] = {kBinary, "-c", conf.c_str(), nullptr};
        if (posix_spawn(&pid_, kBinary, nullptr, nullptr, const_cast<char**>(argv), environ) != 0)
            throw std::runtime_error("MosquittoBroker: cannot start mosquitto");
        for (int i = 0; i < 100 && !acceptsConnections(port_); ++i)
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
        if (!acceptsConnections(port_)) throw std::runtime_error("MosquittoBroker: not listening on " + address());
    }
    void stop() {
        if (pid_ <= 0) return;
        kill(pid_, SIGTERM);
        int status = 0;
        waitpid(pid_, &status, 0);
        pid_ = -1;
    }

private:
    std::filesystem::path folder_;
    int port_ = 0;
    pid_t pid_ = -1;
};

}  // namespace arcomp::test
