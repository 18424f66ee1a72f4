// arcomp-bench people [--frames 750] [--out DIR]: the people the station
// publishes (runtime/people/PeopleFrame.hpp) against the true walkers of
// the `ar` installation (tools/bench/drivers/ArInstallation.hpp).
//  - Two stations replay the same video with the station's own calibration
//    of the camera: one is given the walkers' true masks (`matte: masks`),
//    the other mattes against a clean plate, as an installation would.
//  - Each frame, each walker whose middle is in the picture is matched to
//    the nearest published person seen this frame, within 1 m.
//  - Position error: the distance from the published position to the
//    walker's true middle. Bias along the view: the error's mean component
//    along the floor direction from the camera to the walker (positive:
//    placed too far); also without FloorPeople's half-body correction, to
//    show what it removes.
//  - Velocity error: the length of the difference from the true velocity,
//    for people followed for at least half a second, away from a walker's
//    turn (where the smoothed velocity lags by design).
//  - Ids: a switch is a walker matched to another id than at its last
//    match; a loss is a walker matched in one frame and not in the next
//    while in the picture. Both per walker per minute of video.
//  - Cost: the median of the station's people stage (FrameStats::peopleMs):
//    placing the people on the floor and sending them, OSC and TUIO, to a
//    UDP socket on loopback that the bench reads. Delay: from a frame's
//    capture to its people's last datagram leaving the socket
//    (FrameStats::captureToPeopleSentMs), median and p95.
//  - Zones: a third station, the own-matte one with three floor zones
//    across the walkers' paths and a trigger on each. Its enter and leave
//    events against the true ones: the walkers' true middles run through
//    the same hysteresis (in once inside by the enter margin, out once
//    outside by the leave margin). Each true event of a walker in the
//    full view (fullView: in the picture, no other walker in its column)
//    is matched to the nearest of the station's events of that zone and
//    kind within kEventFrames; the timing error is the frames between them.
//    Missed: a true event in full view without one; spurious: a station
//    event that no true event matches, of a person whose nearest walker is
//    in full view. Cost: that
//    station's people stage against the own-matte one's, the same frames.
//
//   arcomp-bench people --out build/bench-people

#include "runtime/gl/GlContext.hpp"
#include "runtime/station/ReplayInput.hpp"
#include "runtime/station/Station.hpp"
#include "runtime/zones/Zone.hpp"
#include "tools/bench/drivers/ArInstallation.hpp"
#include "tools/bench/probes/LoopbackUdp.hpp"
#include "tools/bench/report/BenchJson.hpp"
#include "tools/bench/report/Stats.hpp"
#include "tools/cli/Command.hpp"
#include "video/matte/MaskFolderMatte.hpp"

#include <opencv2/imgcodecs.hpp>

#include <iostream>

namespace arcomp {
namespace {

namespace fs = std::filesystem;
using namespace ar;

struct Options {
    int frames = 750;
    std::string out = "build/bench-people";
};

constexpr float kMatchMetres = 1.0f;
constexpr double kSettledSeconds = 0.5;  // followed this long before its velocity is scored
constexpr double kTurnSeconds = 0.5;     // velocity not scored this close to a walker's turn

constexpr int kEventFrames = 12;  // a station event further than this from a true one is not it

// Three floor zones, each across one walker's path, and a trigger on each
// that hides and shows one of the CG objects, as an installation's would.
constexpr const char* kZonesAndTriggers = R"(zones:
  - {name: left, polygon: [[-2.5, -3], [-0.5, -3], [-0.5, -1], [-2.5, -1]]}
  - {name: right, circle: {center: [2.5, 2.2], radius: 1.0}}
  - {name: lane, polygon: [[0.3, -5.5], [1.6, -5.5], [1.6, -3.5], [0.3, -3.5]]}
triggers:
  - {name: left, when: {count: left, at_least: 1}, do: [{hide: sphere}], on_end: [{show: sphere}]}
  - {name: right, when: {enter: right}, do: [{fade: box, to: 0.5, seconds: 1}]}
  - {name: lane, when: {dwell: lane, seconds: 0.5}, do: [{show: box}]}
)";

struct WalkerIds {
    int lastId = -1;
    bool matchedBefore = false;
};

struct Score {
    std::vector<double> positionErr, velocityErr, along, alongUncorrected, peopleMs, delayMs;
    int switches = 0, losses = 0, visible = 0, matched = 0;
    std::size_t datagramsSent = 0;
    std::vector<WalkerIds> ids;
};

// The show control at the other end: a UDP socket on loopback, read after
// every frame so that nothing waits in its buffer.
class LoopbackSink {
public:
    int port() const { return socket_.port(); }
    void drain() {
        while (socket_.receive(buffer_, std::chrono::milliseconds(0)) > 0) ++received_;
    }
    std::size_t received() const { return received_; }

private:
    LoopbackUdp socket_;
    std::vector<std::uint8_t> buffer_ = std::vector<std::uint8_t>(65536);
    std::size_t received_ = 0;
};

glm::vec2 unit(glm::vec2 v) { return glm::length(v) > 1e-6f ? glm::normalize(v) : glm::vec2(0.0f); }

bool inPicture(const CalibratedCamera& camera, glm::vec2 floor) {
    const glm::dvec3 point(floor.x, 0.0, floor.y);
    if (camera.depthOf(point) <= 0.0) return false;
    const glm::dvec2 pixel = camera.project(point);
    return pixel.x >= 0 && pixel.y >= 0 && pixel.x < kLens.size.width && pixel.y < kLens.size.height;
}

struct ZoneCrossing {
    int frame;
    int zone;
    ZoneEvent::Kind kind;
    bool inView;  // the walker in full view around it (fullView)
};

// Whether walker `w` is in full view from `frame - kEventFrames` to
// `frame + kEventFrames`: its middle in the picture, and no other walker
// in front of or behind it there (their columns in the picture, a body's
// width each, apart). A walker hidden by another, or merged with them into
// one shape, is not one the station can see cross.
bool fullView(const std::vector<ObjectConfig>& walking, std::size_t w, int frame, const CalibratedCamera& truth) {
    constexpr double kHalfWidthMetres = 0.3;
    for (int i = frame - kEventFrames; i <= frame + kEventFrames; ++i) {
        const auto column = [&](std::size_t k) {
            const glm::vec2 at = walkerAt(walking[k], i / kFps).position;
            const glm::dvec3 floor(at.x, 0.0, at.y);
            const double halfWidth = kHalfWidthMetres * truth.intrinsics.fx / std::max(truth.depthOf(floor), 0.1);
            return std::pair(truth.project(floor).x, halfWidth);
        };
        if (!inPicture(truth, walkerAt(walking[w], i / kFps).position)) return false;
        const auto [x, half] = column(w);
        for (std::size_t k = 0; k < walking.size(); ++k) {
            if (k == w) continue;
            const auto [otherX, otherHalf] = column(k);
            if (std::abs(otherX - x) < half + otherHalf) return false;
        }
    }
    return true;
}

// The true events of `walking` in `zones`, frame by frame, through the zones' hysteresis.
std::vector<ZoneCrossing> trueCrossings(const std::vector<ObjectConfig>& walking, const std::vector<Zone>& zones,
                                        const CalibratedCamera& truth, int frames) {
    std::vector<ZoneCrossing> out;
    std::vector<std::vector<bool>> in(walking.size(), std::vector<bool>(zones.size(), false));
    for (int i = 0; i < frames; ++i)
        for (std::size_t w = 0; w < walking.size(); ++w) {
            const glm::vec2 at = walkerAt(walking[w], i / kFps).position;
            for (std::size_t z = 0; z < zones.size(); ++z) {
                const float d = signedDistance(zones[z], at);
                const bool was = in[w][z];
                if (!was && d < -zones[z].enterMargin) in[w][z] = true;
                if (was && d > zones[z].leaveMargin) in[w][z] = false;
                if (in[w][z] != was)
                    out.push_back({i, static_cast<int>(z), was ? ZoneEvent::Kind::Leave : ZoneEvent::Kind::Enter,
                                   fullView(walking, w, i, truth)});
            }
        }
    return out;
}

struct ZoneScore {
    std::vector<double> errFrames;
    int trueEvents = 0, stationEvents = 0, missed = 0, spurious = 0;
    int hiddenEvents = 0, hiddenMissed = 0;  // true events of a walker not in full view
};

// `station`'s inView: whether the walker nearest the person who crossed is in full view.
ZoneScore scoreZones(const std::vector<ZoneCrossing>& truth, const std::vector<ZoneCrossing>& station) {
    ZoneScore s;
    s.stationEvents = static_cast<int>(station.size());
    std::vector<bool> used(station.size(), false);
    for (const ZoneCrossing& t : truth) {
        int best = -1, bestErr = kEventFrames + 1;
        for (std::size_t k = 0; k < station.size(); ++k) {
            const int err = std::abs(station[k].frame - t.frame);
            if (!used[k] && station[k].zone == t.zone && station[k].kind == t.kind && err < bestErr)
                best = static_cast<int>(k), bestErr = err;
        }
        if (best >= 0) used[static_cast<std::size_t>(best)] = true;
        if (!t.inView) {
            ++s.hiddenEvents;
            s.hiddenMissed += best < 0;
            continue;
        }
        ++s.trueEvents;
        if (best < 0)
            ++s.missed;
        else
            s.errFrames.push_back(bestErr);
    }
    for (std::size_t k = 0; k < station.size(); ++k)
        if (!used[k] && station[k].inView) ++s.spurious;
    return s;
}

// Whether walker `w`'s path turns round within kTurnSeconds of `seconds`.
bool nearTurn(const ObjectConfig& w, double seconds) {
    return walkerAt(w, seconds - kTurnSeconds).velocity != walkerAt(w, seconds + kTurnSeconds).velocity;
}

void scoreFrame(const PeopleFrame& people, const std::vector<ObjectConfig>& walkers, const CalibratedCamera& truth,
                double bodyDepthMetres, Score& s) {
    const glm::dvec3 lens = truth.position();
    const glm::vec2 lensOnFloor(static_cast<float>(lens.x), static_cast<float>(lens.z));
    std::vector<bool> taken(people.people.size(), false);
    for (std::size_t w = 0; w < walkers.size(); ++w) {
        const FloorTruth t = walkerAt(walkers[w], people.seconds);
        WalkerIds& ids = s.ids[w];
        if (!inPicture(truth, t.position)) {
            ids.matchedBefore = false;
            continue;
        }
        ++s.visible;
        int best = -1;
        float bestDistance = kMatchMetres;
        for (std::size_t i = 0; i < people.people.size(); ++i) {
            const Person& p = people.people[i];
            const float d = glm::distance(p.position, t.position);
            if (p.seen && !taken[i] && d < bestDistance) best = static_cast<int>(i), bestDistance = d;
        }
        if (best < 0) {
            if (ids.matchedBefore) ++s.losses;
            ids.matchedBefore = false;
            continue;
        }
        taken[static_cast<std::size_t>(best)] = true;
        const Person& p = people.people[static_cast<std::size_t>(best)];
        ++s.matched;
        if (ids.lastId >= 0 && ids.lastId != p.id) ++s.switches;
        ids.lastId = p.id;
        ids.matchedBefore = true;

        const glm::vec2 away = unit(t.position - lensOnFloor);
        s.positionErr.push_back(bestDistance);
        s.along.push_back(glm::dot(p.position - t.position, away));
        const glm::vec2 nearFoot =
            p.position - unit(p.position - lensOnFloor) * static_cast<float>(0.5 * bodyDepthMetres);
        s.alongUncorrected.push_back(glm::dot(nearFoot - t.position, away));
        if (p.ageSeconds >= kSettledSeconds && !nearTurn(walkers[w], people.seconds))
            s.velocityErr.push_back(glm::distance(p.velocity, t.velocity));
    }
}

double mean(const std::vector<double>& v) {
    double sum = 0.0;
    for (const double x : v) sum += x;
    return v.empty() ? std::nan("") : sum / static_cast<double>(v.size());
}

void report(BenchJson& json, const std::string& name, const Score& s, double walkerMinutes) {
    json.beginObject(name)
        .field("position_err_m_median", Fixed{median(s.positionErr), 3})
        .field("position_err_m_p95", Fixed{percentile(s.positionErr, 95), 3})
        .field("bias_along_view_m", Fixed{mean(s.along), 3})
        .field("bias_along_view_m_uncorrected", Fixed{mean(s.alongUncorrected), 3})
        .field("velocity_err_mps_median", Fixed{median(s.velocityErr), 3})
        .field("id_switches_per_walker_min", Fixed{s.switches / walkerMinutes, 2})
        .field("losses_per_walker_min", Fixed{s.losses / walkerMinutes, 2})
        .field("matched_pct", Fixed{s.visible ? 100.0 * s.matched / s.visible : 0.0, 1})
        .field("people_ms_median", Fixed{median(s.peopleMs), 3})
        .field("capture_to_sent_ms_median", Fixed{median(s.delayMs), 2})
        .field("capture_to_sent_ms_p95", Fixed{percentile(s.delayMs, 95), 2})
        .field("datagrams_sent", static_cast<int>(s.datagramsSent))
        .end();
}

int run(const Options& o) {
    const fs::path dir = o.out;
    fs::create_directories(dir / "masks");
    auto context = HeadlessContext::create(GlRequest::Auto);
    const SyntheticCamera lens(kLens);
    const Calibration calibration = calibrate(lens, dir);
    const CalibratedCamera truth = trueCamera();

    // The walkers through the true lens over the floor, and their masks.
    const cv::Mat plate = floorPlate(lens);
    cv::imwrite((dir / "plate.png").string(), plate);
    const std::vector<ObjectConfig> walking = walkers();
    ObjectPainter painter(walking, truth.view({kLens.size.width, kLens.size.height}, 0.1f, 100.0f));
    std::vector<cv::Mat> video;
    for (int i = 0; i < o.frames; ++i) {
        const cv::Mat layer = lens.throughLens(painter.paint(i / kFps, Shading::Phong));
        video.push_back(over(layer, plate));
        cv::Mat alpha;
        cv::extractChannel(layer, alpha, 3);
        cv::imwrite(MaskFolderMatte::maskFile(dir / "masks", static_cast<std::uint64_t>(i)).string(), alpha);
    }

    LoopbackSink sink;
    const std::string target = "\"127.0.0.1:" + std::to_string(sink.port()) + "\"";
    const std::string showControl = "show_control:\n  osc: {targets: [" + target + "]}\n  tuio: {targets: [" + target +
                                    "], floor: {min: [-6, -9], max: [6, 5]}}\n";
    writeConfig(dir / "people-masks.yaml", "  kind: masks\n  masks: {folder: masks}\n", "", showControl);
    const std::string ownMatte = "  kind: background\n  background: {method: clean_plate, clean_plate: plate.png}\n";
    writeConfig(dir / "people-own-matte.yaml", ownMatte, "", showControl);
    writeConfig(dir / "people-zones.yaml", ownMatte, "", showControl + kZonesAndTriggers);
    const std::vector<fs::path> configs{dir / "people-masks.yaml", dir / "people-own-matte.yaml",
                                        dir / "people-zones.yaml"};
    std::vector<std::unique_ptr<Station>> stations;
    std::vector<Score> scores(configs.size());
    for (const fs::path& config : configs)
        stations.push_back(std::make_unique<Station>(
            loadStationConfig(config), StationInput::fromReplay(std::make_unique<FramesGrabber>(video), kFps)));
    for (Score& s : scores) s.ids.resize(walking.size());
    const double bodyDepth = FloorPeople::Settings{}.bodyDepthMetres;
    std::vector<ZoneCrossing> stationCrossings;
    for (int i = 0; i < o.frames; ++i) {
        for (std::size_t k = 0; k < stations.size(); ++k) {
            if (!stations[k]->frame()) throw std::runtime_error("a station stopped at frame " + std::to_string(i));
            scores[k].peopleMs.push_back(stations[k]->stats().peopleMs);
            scores[k].delayMs.push_back(stations[k]->stats().captureToPeopleSentMs);
            sink.drain();
            scoreFrame(stations[k]->people(), walking, truth, bodyDepth, scores[k]);
        }
        const PeopleFrame& now = stations.back()->people();
        for (const ZoneEvent& e : now.zoneEvents) {
            // Whose crossing: the walker nearest where the person was (a person given up leaves where last seen).
            const Person* p = findPerson(now, e.person);
            const glm::vec2 at = p ? p->position : glm::vec2(1e6f);
            std::size_t nearest = 0;
            for (std::size_t w = 1; w < walking.size(); ++w)
                if (glm::distance(walkerAt(walking[w], now.seconds).position, at) <
                    glm::distance(walkerAt(walking[nearest], now.seconds).position, at))
                    nearest = w;
            stationCrossings.push_back({i, e.zone, e.kind, p && fullView(walking, nearest, i, truth)});
        }
    }
    const std::vector<Zone>& zones = loadStationConfig(configs.back()).zones;
    const ZoneScore zoneScore = scoreZones(trueCrossings(walking, zones, truth, o.frames), stationCrossings);
    std::uint64_t fired = 0;
    for (std::size_t t = 0; t < stations.back()->triggers().triggers().size(); ++t)
        fired += stations.back()->triggers().counts(t).fired;

    for (std::size_t k = 0; k < stations.size(); ++k)
        for (const OutputStatus& out : stations[k]->showControl().outputs()) {
            scores[k].datagramsSent += out.sent;
            if (out.dropped > 0 || out.state != "sending")
                throw std::runtime_error("people bench: " + out.kind + " " + out.state + ", " +
                                         std::to_string(out.dropped) + " dropped (" + out.lastError + ")");
        }
    std::size_t sent = 0;
    for (const Score& s : scores) sent += s.datagramsSent;
    if (sink.received() != sent)
        throw std::runtime_error("people bench: " + std::to_string(sink.received()) + " datagrams arrived of " +
                                 std::to_string(sent) + " sent");
    const double walkerMinutes = static_cast<double>(walking.size()) * o.frames / kFps / 60.0;
    const Score &masks = scores[0], &own = scores[1];
    BenchJson json;
    json.field("bench", "people").field("frames", o.frames).field("walkers", static_cast<int>(walking.size()));
    json.beginArray("size").value(kLens.size.width).value(kLens.size.height).end();
    report(json, "true_masks", masks, walkerMinutes);
    report(json, "own_matte", own, walkerMinutes);
    json.beginObject("zones")
        .field("true_events_in_full_view", zoneScore.trueEvents)
        .field("true_events_hidden", zoneScore.hiddenEvents)
        .field("missed_hidden", zoneScore.hiddenMissed)
        .field("station_events", zoneScore.stationEvents)
        .field("timing_err_frames_median", Fixed{median(zoneScore.errFrames), 1})
        .field("timing_err_frames_p95", Fixed{percentile(zoneScore.errFrames, 95), 1})
        .field("missed", zoneScore.missed)
        .field("spurious", zoneScore.spurious)
        .field("triggers_fired", static_cast<int>(fired))
        .field("people_ms_median", Fixed{median(scores[2].peopleMs), 3})
        .field("zones_and_triggers_ms", Fixed{median(scores[2].peopleMs) - median(own.peopleMs), 3})
        .end();
    json.field("calibration_height_err_pct", Fixed{calibration.heightErrPct, 3})
        .field("calibration_tilt_err_deg", Fixed{calibration.tiltErrDeg, 3});
    json.beginObject("targets")
        .field("position", median(masks.positionErr) <= 0.15 && median(own.positionErr) <= 0.15)
        .field("cost", median(own.peopleMs) <= 1.0)
        .field("zone_timing", median(zoneScore.errFrames) <= 3.0 && zoneScore.missed == 0 && zoneScore.spurious == 0)
        .end();
    json.field("out", dir.string());
    std::cout << json.str() << std::endl;
    return kExitOk;
}

const bool registered = registerCommand(
    {"people", "The people the station publishes against the true walkers: position, velocity, ids, zone events, cost",
     [](CommandLine& line) {
         auto o = std::make_shared<Options>();
         line.option("--frames", o->frames, "frames of the installation (25 a second)").range(50, 100000).showDefault();
         line.option("--out", o->out, "folder for the calibration inputs, the masks and the configs").showDefault();
         return [o] { return run(*o); };
     }});

}  // namespace
}  // namespace arcomp
