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
//
//   arcomp-bench people --out build/bench-people

#include "runtime/gl/GlContext.hpp"
#include "runtime/station/ReplayInput.hpp"
#include "runtime/station/Station.hpp"
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
    writeConfig(dir / "people-own-matte.yaml",
                "  kind: background\n  background: {method: clean_plate, clean_plate: plate.png}\n", "", showControl);
    const std::vector<fs::path> configs{dir / "people-masks.yaml", dir / "people-own-matte.yaml"};
    std::vector<std::unique_ptr<Station>> stations;
    std::vector<Score> scores(configs.size());
    for (const fs::path& config : configs)
        stations.push_back(std::make_unique<Station>(
            loadStationConfig(config), StationInput::fromReplay(std::make_unique<FramesGrabber>(video), kFps)));
    for (Score& s : scores) s.ids.resize(walking.size());
    const double bodyDepth = FloorPeople::Settings{}.bodyDepthMetres;
    for (int i = 0; i < o.frames; ++i)
        for (std::size_t k = 0; k < stations.size(); ++k) {
            if (!stations[k]->frame()) throw std::runtime_error("a station stopped at frame " + std::to_string(i));
            scores[k].peopleMs.push_back(stations[k]->stats().peopleMs);
            scores[k].delayMs.push_back(stations[k]->stats().captureToPeopleSentMs);
            sink.drain();
            scoreFrame(stations[k]->people(), walking, truth, bodyDepth, scores[k]);
        }

    for (std::size_t k = 0; k < stations.size(); ++k)
        for (const OutputStatus& out : stations[k]->showControl().outputs()) {
            scores[k].datagramsSent += out.sent;
            if (out.dropped > 0 || out.state != "sending")
                throw std::runtime_error("people bench: " + out.kind + " " + out.state + ", " +
                                         std::to_string(out.dropped) + " dropped (" + out.lastError + ")");
        }
    if (sink.received() != scores[0].datagramsSent + scores[1].datagramsSent)
        throw std::runtime_error("people bench: " + std::to_string(sink.received()) + " datagrams arrived of " +
                                 std::to_string(scores[0].datagramsSent + scores[1].datagramsSent) + " sent");
    const double walkerMinutes = static_cast<double>(walking.size()) * o.frames / kFps / 60.0;
    const Score &masks = scores[0], &own = scores[1];
    BenchJson json;
    json.field("bench", "people").field("frames", o.frames).field("walkers", static_cast<int>(walking.size()));
    json.beginArray("size").value(kLens.size.width).value(kLens.size.height).end();
    report(json, "true_masks", masks, walkerMinutes);
    report(json, "own_matte", own, walkerMinutes);
    json.field("calibration_height_err_pct", Fixed{calibration.heightErrPct, 3})
        .field("calibration_tilt_err_deg", Fixed{calibration.tiltErrDeg, 3});
    json.beginObject("targets")
        .field("position", median(masks.positionErr) <= 0.15 && median(own.positionErr) <= 0.15)
        .field("cost", median(own.peopleMs) <= 1.0)
        .end();
    json.field("out", dir.string());
    std::cout << json.str() << std::endl;
    return kExitOk;
}

const bool registered = registerCommand(
    {"people", "The people the station publishes against the true walkers: position, velocity, ids, cost",
     [](CommandLine& line) {
         auto o = std::make_shared<Options>();
         line.option("--frames", o->frames, "frames of the installation (25 a second)").range(50, 100000).showDefault();
         line.option("--out", o->out, "folder for the calibration inputs, the masks and the configs").showDefault();
         return [o] { return run(*o); };
     }});

}  // namespace
}  // namespace arcomp
