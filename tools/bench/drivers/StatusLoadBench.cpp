// arcomp-bench status-load [--seconds S] [--idle N] [--slow N] [--garbage N]:
// does the status endpoint keep answering, and the station keep its frame
// time, while hostile clients hold connections to it?
//
// A headless station loops the demo scene (tools/bench/scenes/DemoStation.hpp)
// with its status endpoint on 127.0.0.1, paced at --fps as a camera would
// pace it; the frame time is each frame's work (StationRunner::step). With
// --fps 0 it runs flat out, and the frame time then also shows how much of
// the machine the clients and the server take. A scraper asks for /metrics and
// /status ten times a second, from 127.0.0.1. The run alternates quiet and
// loaded slices of 2 s (quiet first and last, S seconds of each in all), so
// that the machine's own drift falls on both alike. In the loaded slices
// these clients are connected as well, all to 127.0.0.1, from many loopback
// source addresses (127.0.0.0/8 is all loopback) so that the per-client
// bound is exercised:
//   - idle: connect and send nothing;
//   - slow: send a request one byte a second;
//   - garbage: send 512 random bytes ending in a blank line every 100 ms.
// Each reconnects a second (garbage: 100 ms) after the server closes it, so
// the pressure stays on for the whole slice. Every loop is bounded by the
// run's clock.
//
// Targets (issue #24): scrape p99 <= 1000 ms under load, no failed scrape,
// and the station's median frame time in the loaded slices within 5 % of
// the quiet slices' median. The last line is one JSON object.

#include "runtime/app/StationRunner.hpp"
#include "runtime/gl/GlContext.hpp"
#include "runtime/station/ReplayInput.hpp"
#include "tools/bench/probes/HttpProbe.hpp"
#include "tools/bench/report/BenchJson.hpp"
#include "tools/bench/report/Stats.hpp"
#include "tools/bench/scenes/DemoStation.hpp"
#include "tools/cli/Command.hpp"

#include <poll.h>
#include <pthread.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <exception>
#include <fstream>
#include <mutex>
#include <random>
#include <sstream>
#include <thread>
#include <vector>

namespace arcomp {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using std::chrono::milliseconds;

struct StatusLoadOptions {
    int seconds = 20;
    int idle = 1000;
    int slow = 100;
    int garbage = 50;
    double fps = 25.0;  // the station's pace, as a camera would set it; 0: as fast as it can
};

constexpr double kScrapeP99LimitMs = 1000.0;
constexpr double kFrameTimeChangeLimitPct = 5.0;
constexpr milliseconds kScrapeTimeout{5000};

// The hostile clients, driven by one thread polling all their sockets.
class HostileClients {
public:
    enum Kind { Idle, Slow, Garbage };

    HostileClients(int port, const StatusLoadOptions& o) : port_(port) {
        // Idle clients from 64 addresses, slow from 16, garbage from 8.
        const auto add = [this](Kind kind, int count, int subnet, int addresses) {
            for (int i = 0; i < count; ++i)
                clients_.push_back({kind, "127.0." + std::to_string(subnet) + "." + std::to_string(2 + i % addresses)});
        };
        add(Idle, o.idle, 1, 64);
        add(Slow, o.slow, 2, 16);
        add(Garbage, o.garbage, 3, 8);
    }

    // Runs until `stop`, and never past `deadline`; connected only while
    // `active`.
    void run(const std::atomic<bool>& stop, const std::atomic<bool>& active, Clock::time_point deadline) {
        std::mt19937 random(7);
        std::vector<pollfd> polled;
        std::vector<std::size_t> polledClient;
        while (!stop && Clock::now() < deadline) {
            const Clock::time_point now = Clock::now();
            if (!active) {
                for (Client& c : clients_) {
                    c.socket.reset();
                    c.next = now;
                }
                std::this_thread::sleep_for(milliseconds(10));
                continue;
            }
            polled.clear();
            polledClient.clear();
            std::size_t open = 0;
            for (std::size_t i = 0; i < clients_.size(); ++i) {
                Client& c = clients_[i];
                if (!c.socket && now >= c.next) connect(c, now);
                if (!c.socket) continue;
                ++open;
                if (now >= c.next) send(c, now, random);
                polled.push_back({c.socket.get(), POLLIN, 0});
                polledClient.push_back(i);
            }
            mostOpen_ = std::max(mostOpen_, open);
            if (::poll(polled.data(), polled.size(), 0) > 0)
                for (std::size_t k = 0; k < polled.size(); ++k)
                    if (polled[k].revents != 0) readOrNoticeClose(clients_[polledClient[k]], Clock::now());
            // A hundred rounds a second at most: the clients' own CPU is taken
            // from the station on this machine, and would count against the server.
            std::this_thread::sleep_until(now + milliseconds(10));
        }
        for (Client& c : clients_) c.socket.reset();
        timespec cpu{};
        ::clock_gettime(CLOCK_THREAD_CPUTIME_ID, &cpu);
        cpuMs_ = static_cast<double>(cpu.tv_sec) * 1e3 + static_cast<double>(cpu.tv_nsec) * 1e-6;
    }

    std::uint64_t connects() const { return connects_; }
    std::uint64_t closedByServer() const { return closedByServer_; }
    std::uint64_t connectFailures() const { return connectFailures_; }
    std::size_t mostOpen() const { return mostOpen_; }
    double cpuMs() const { return cpuMs_; }  // after run()

private:
    struct Client {
        Kind kind;
        std::string from;
        FileDescriptor socket{};
        Clock::time_point next{};  // when to connect (closed) or send (open)
        std::size_t sent = 0;      // a slow client's position in its request
    };

    void connect(Client& c, Clock::time_point now) {
        try {
            c.socket = connectLoopback(port_, c.from);
            ++connects_;
            c.sent = 0;
            c.next = now + (c.kind == Idle ? std::chrono::hours(1) : milliseconds(c.kind == Slow ? 1000 : 100));
        } catch (const std::exception&) {
            ++connectFailures_;
            c.next = now + milliseconds(1000);
        }
    }

    void send(Client& c, Clock::time_point now, std::mt19937& random) {
        static const std::string request = "GET /status HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n";
        if (c.kind == Slow) {
            ::send(c.socket.get(), request.data() + c.sent % request.size(), 1, MSG_NOSIGNAL | MSG_DONTWAIT);
            ++c.sent;
            c.next = now + milliseconds(1000);
        } else if (c.kind == Garbage) {
            // Random bytes, then a blank line so the server has a whole "head" to refuse.
            char bytes[512];
            for (char& b : bytes) b = static_cast<char>(random());
            std::copy_n("\r\n\r\n", 4, bytes + sizeof bytes - 4);
            ::send(c.socket.get(), bytes, sizeof bytes, MSG_NOSIGNAL | MSG_DONTWAIT);
            c.next = now + milliseconds(100);
        }
    }

    void readOrNoticeClose(Client& c, Clock::time_point now) {
        char buffer[4096];
        const ssize_t n = ::recv(c.socket.get(), buffer, sizeof buffer, MSG_DONTWAIT);
        if (n > 0 || (n < 0 && (errno == EAGAIN || errno == EINTR))) return;  // a 400 or 431 reply; the close follows
        c.socket.reset();
        ++closedByServer_;
        c.next = now + milliseconds(c.kind == Garbage ? 100 : 1000);
    }

    int port_;
    std::vector<Client> clients_;
    std::uint64_t connects_ = 0, closedByServer_ = 0, connectFailures_ = 0;
    std::size_t mostOpen_ = 0;
    double cpuMs_ = 0.0;
};

// CPU time so far of this process's threads with the given name, from
// /proc (the status server's thread is not ours to instrument).
double threadCpuMs(const std::string& name) {
    double ticks = 0.0;
    for (const auto& task : fs::directory_iterator("/proc/self/task")) {
        std::string comm;
        std::getline(std::ifstream(task.path() / "comm"), comm);
        if (comm != name) continue;
        std::string stat;
        std::getline(std::ifstream(task.path() / "stat"), stat);
        // Fields after the ")" closing the name: state is the 3rd, utime the 14th, stime the 15th.
        std::istringstream rest(stat.substr(stat.rfind(')') + 2));
        std::string field;
        double utime = 0.0, stime = 0.0;
        for (int i = 3; i <= 15 && rest >> field; ++i) {
            if (i == 14) utime = std::stod(field);
            if (i == 15) stime = std::stod(field);
        }
        ticks += utime + stime;
    }
    return ticks * 1000.0 / static_cast<double>(::sysconf(_SC_CLK_TCK));
}

struct Samples {
    std::vector<double> frameMs;
    std::vector<double> scrapeMs;
    int scrapeFailures = 0;
    std::string firstFailure;
};

constexpr auto kSlice = std::chrono::seconds(2);

int statusLoad(const StatusLoadOptions& o) {
    if (o.seconds < 2 || o.seconds > 600) throw InputError("--seconds must be 2 to 600");
    // Every client holds a descriptor, and so does every connection the server accepts.
    rlimit files{};
    ::getrlimit(RLIMIT_NOFILE, &files);
    const rlim_t needed = static_cast<rlim_t>(o.idle + o.slow + o.garbage) + 512;
    if (files.rlim_cur < needed) {
        files.rlim_cur = std::min(needed, files.rlim_max);
        ::setrlimit(RLIMIT_NOFILE, &files);
        if (files.rlim_cur < needed)
            throw InputError("bench status-load needs " + std::to_string(needed) + " open files; the limit is " +
                             std::to_string(files.rlim_max) + " (ulimit -n)");
    }

    const fs::path dir = fs::temp_directory_path() / ("arcomp-bench-status-load-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const fs::path configFile = dir / "station.yaml";
    std::ofstream(configFile) << demoStationYaml(demoVideo(dir, "bench status-load"));
    StationConfig cfg = loadStationConfig(configFile);
    cfg.operation.statusEnabled = true;
    cfg.operation.status = {.bind = "127.0.0.1", .port = 0};

    auto context = HeadlessContext::create(GlRequest::Auto);
    StationRunner runner(cfg, nullptr, [](const StationConfig& c) {
        std::vector<std::string> warnings;
        return openReplayInput(*c.compositing.video, warnings);
    });
    const int port = runner.statusPort();
    if (port <= 0) throw std::runtime_error("the station's status endpoint did not start");
    for (int i = 0; i < 30; ++i) runner.step();  // warm-up: the matte's model, driver caches

    // Slices: quiet, loaded, quiet, ..., quiet.
    const int loadedSlices = std::max(1, static_cast<int>(std::chrono::seconds(o.seconds) / kSlice));
    const int slices = 2 * loadedSlices + 1;
    const std::chrono::duration<double> framePeriod(o.fps > 0.0 ? 1.0 / o.fps : 0.0);
    std::atomic<bool> loaded{false}, done{false};
    std::array<Samples, 2> samples;  // [0] quiet, [1] loaded
    std::mutex samplesMutex;
    const Clock::time_point start = Clock::now();
    const Clock::time_point end = start + slices * kSlice;

    std::thread scraper([&] {
        pthread_setname_np(pthread_self(), "scraper");
        for (int n = 0; !done && Clock::now() < end + kScrapeTimeout; ++n) {
            const bool underLoad = loaded;
            const Clock::time_point t0 = Clock::now();
            const HttpProbeReply r = httpGet(port, n % 2 ? "/status" : "/metrics", {.timeout = kScrapeTimeout});
            const double ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
            {
                std::lock_guard lock(samplesMutex);
                Samples& s = samples[underLoad ? 1 : 0];
                s.scrapeMs.push_back(ms);
                if ((r.status != 200 || r.body.empty()) && s.scrapeFailures++ == 0)
                    s.firstFailure = r.status ? "HTTP " + std::to_string(r.status) : r.error;
            }
            std::this_thread::sleep_until(t0 + milliseconds(100));
        }
    });
    HostileClients hostile(port, o);
    std::thread attacker([&] {
        pthread_setname_np(pthread_self(), "hostile-clients");
        hostile.run(done, loaded, end);
    });

    // A station that fails mid-run stops the clients before the error goes
    // on: thrown past running threads, it would end the process unreported.
    std::exception_ptr failure;
    try {
        for (int slice = 0; slice < slices; ++slice) {
            loaded = slice % 2 == 1;
            const Clock::time_point sliceEnd = start + (slice + 1) * kSlice;
            while (Clock::now() < sliceEnd) {
                const Clock::time_point t0 = Clock::now();
                if (!runner.step()) throw std::runtime_error("the looping input ended");
                const double ms = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
                {
                    std::lock_guard lock(samplesMutex);
                    samples[slice % 2].frameMs.push_back(ms);
                }
                if (o.fps > 0.0)
                    std::this_thread::sleep_until(t0 + std::chrono::duration_cast<Clock::duration>(framePeriod));
            }
        }
    } catch (...) {
        failure = std::current_exception();
    }
    done = true;
    const double serverCpuMs = threadCpuMs("arcomp-status");
    const double runMs = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    attacker.join();
    const double clientsCpuMs = hostile.cpuMs();
    scraper.join();
    if (failure) {
        fs::remove_all(dir);
        std::rethrow_exception(failure);
    }
    const StatusServerCounters server = runner.statusCounters();
    runner.finish();
    fs::remove_all(dir);

    const Samples& quiet = samples[0];
    const Samples& underLoad = samples[1];
    const double quietFrameMs = median(quiet.frameMs), loadedFrameMs = median(underLoad.frameMs);
    const double changePct = (loadedFrameMs / quietFrameMs - 1.0) * 100.0;
    const double p99 = percentile(underLoad.scrapeMs, 99), worst = percentile(underLoad.scrapeMs, 100);
    const bool latencyOk = p99 <= kScrapeP99LimitMs && underLoad.scrapeFailures == 0;
    const bool frameOk = changePct <= kFrameTimeChangeLimitPct;
    for (const Samples* s : {&quiet, &underLoad})
        if (s->scrapeFailures > 0)
            std::fprintf(stderr, "bench status-load: %d failed scrapes %s, the first: %s\n", s->scrapeFailures,
                         s == &quiet ? "while quiet" : "under load", s->firstFailure.c_str());

    BenchJson j;
    j.field("bench", "status-load")
        .field("fps", o.fps)
        .field("loaded_seconds", loadedSlices * static_cast<int>(kSlice.count()))
        .field("quiet_seconds", (loadedSlices + 1) * static_cast<int>(kSlice.count()));
    j.beginObject("hostile_clients")
        .field("connects", hostile.connects())
        .field("closed_by_server", hostile.closedByServer())
        .field("connect_failures", hostile.connectFailures())
        .field("most_open_at_once", hostile.mostOpen())
        .field("cpu_pct_of_a_core", Fixed{100.0 * clientsCpuMs / runMs, 2})
        .end();
    j.beginObject("server")
        .field("served", server.served)
        .field("refused_4xx", server.refused)
        .field("evicted", server.evicted)
        .field("timed_out", server.timedOut)
        .field("cpu_pct_of_a_core", Fixed{100.0 * serverCpuMs / runMs, 2})
        .end();
    j.beginObject("quiet")
        .field("scrapes", quiet.scrapeMs.size())
        .field("scrape_p50_ms", Fixed{median(quiet.scrapeMs), 2})
        .field("scrape_p99_ms", Fixed{percentile(quiet.scrapeMs, 99), 2})
        .field("scrape_failures", quiet.scrapeFailures)
        .field("frame_ms_median", Fixed{quietFrameMs, 3})
        .field("frames", quiet.frameMs.size())
        .end();
    j.field("scrapes", underLoad.scrapeMs.size())
        .field("scrape_p50_ms", Fixed{median(underLoad.scrapeMs), 2})
        .field("scrape_p99_ms", Fixed{p99, 2})
        .field("scrape_max_ms", Fixed{worst, 2})
        .field("scrape_failures", underLoad.scrapeFailures)
        .field("idle_connections", o.idle)
        .field("slow_clients", o.slow)
        .field("garbage_clients", o.garbage)
        .field("frame_ms_median", Fixed{loadedFrameMs, 3})
        .field("frames", underLoad.frameMs.size())
        .field("frame_time_change_pct", Fixed{changePct, 2});
    j.beginObject("targets")
        .field("scrape_p99_ms_max", kScrapeP99LimitMs)
        .field("frame_time_change_pct_max", kFrameTimeChangeLimitPct)
        .field("scrapes_ok", latencyOk)
        .field("frame_time_ok", frameOk)
        .end();
    j.field("ok", latencyOk && frameOk);
    std::printf("%s\n", j.str().c_str());
    return kExitOk;
}

const bool registered = registerCommand(
    {"status-load", "Scrape the status endpoint while idle, slow and garbage clients hold connections to it",
     [](CommandLine& line) {
         auto o = std::make_shared<StatusLoadOptions>();
         line.option("--seconds", o->seconds, "Seconds under load, in 2 s slices between quiet ones")
             .showDefault()
             .range(2, 600);
         line.option("--idle", o->idle, "Clients that connect and send nothing").showDefault().range(0, 20000);
         line.option("--slow", o->slow, "Clients that send a request one byte a second").showDefault().range(0, 5000);
         line.option("--garbage", o->garbage, "Clients that send random bytes").showDefault().range(0, 5000);
         line.option("--fps", o->fps, "The station's frame rate, as a camera paces it (0: as fast as it can)")
             .showDefault()
             .range(0.0, 240.0);
         return [o] { return statusLoad(*o); };
     }});

}  // namespace
}  // namespace arcomp
