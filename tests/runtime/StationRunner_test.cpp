// The station's life around its frames: the operator endpoint during a
// replay, a camera fault showing in /status and /metrics, a status port
// that another program holds, reloading the config at a frame boundary
// (good and bad configs), and cues over OSC.

#include "runtime/app/ShutdownSignals.hpp"
#include "runtime/app/StationRunner.hpp"
#include "runtime/gl/GlContext.hpp"
#include "runtime/operator/StatusServer.hpp"
#include "tests/support/FreePort.hpp"
#include "tests/support/TempDir.hpp"
#include "video/streams/GstRuntime.hpp"

#include <gtest/gtest.h>
#include <httplib.h>
#include <lo/lo.h>

#include <thread>

using namespace arcomp;
namespace fs = std::filesystem;

namespace {

// A camera that delivers `frames` grey frames and then fails the way a USB
// camera pulled from its socket does.
class FailingCamera : public FrameGrabber {
public:
    explicit FailingCamera(int frames) : left_(frames) {}
    GrabResult grab() override {
        if (left_-- > 0)
            return {Frame{cv::Mat(120, 160, CV_8UC3, cv::Scalar(90, 90, 90))}, {SourceStatus::Streaming, ""}};
        return {std::nullopt, {SourceStatus::Error, "/dev/video0: ENODEV while streaming"}};
    }
    std::string name() const override { return "front"; }

private:
    int left_;
};

const char* const kRunnerStation = R"(scene:
  objects:
    - shape: box
      position: [0, 0, -4]
      color: [0.9, 0.1, 0.1, 1]
camera: {eye: [0, 0, 0], target: [0, 0, -1]}
)";

StationConfig withStatus(const fs::path& file) {
    StationConfig cfg = loadStationConfig(file);
    cfg.operation.statusEnabled = true;
    cfg.operation.status.port = 0;  // any free port
    return cfg;
}

}  // namespace

TEST(StationRunner, cameraFaultShowsInStatusAndMetrics) {
    auto ctx = HeadlessContext::create(GlRequest::Auto);
    test::TempDir dir;
    StationRunner runner(withStatus(dir.write("station.yaml", kRunnerStation)), nullptr, [](const StationConfig&) {
        return StationInput::fromReplay(std::make_unique<FailingCamera>(3), 30.0);
    });
    ASSERT_GT(runner.statusPort(), 0);
    httplib::Client client("127.0.0.1", runner.statusPort());

    EXPECT_TRUE(runner.step());
    auto status = client.Get("/status");
    ASSERT_TRUE(status);
    EXPECT_NE(status->body.find("\"state\":\"streaming\""), std::string::npos) << status->body;
    EXPECT_NE(client.Get("/metrics")->body.find("arcomp_camera_up{camera=\"front\"} 1"), std::string::npos);

    while (runner.step()) {}
    EXPECT_EQ(runner.frames(), 3u);
    status = client.Get("/status");
    ASSERT_TRUE(status);
    EXPECT_NE(status->body.find("\"state\":\"error\""), std::string::npos) << status->body;
    EXPECT_NE(status->body.find("ENODEV while streaming"), std::string::npos) << status->body;
    EXPECT_NE(status->body.find("\"frames\":3"), std::string::npos) << status->body;
    const std::string metrics = client.Get("/metrics")->body;
    EXPECT_NE(metrics.find("arcomp_camera_up{camera=\"front\"} 0"), std::string::npos) << metrics;
    EXPECT_NE(metrics.find("arcomp_frame_time_seconds_count 3"), std::string::npos) << metrics;
}

TEST(StationRunner, aStatusPortAlreadyInUseIsReportedAndFramesGoOnWithoutTheEndpoint) {
    auto ctx = HeadlessContext::create(GlRequest::Auto);
    test::TempDir dir;
    StationMetrics otherMetrics;
    StatusServer squatter(otherMetrics, {.bind = "127.0.0.1", .port = 0});
    StationConfig cfg = withStatus(dir.write("station.yaml", kRunnerStation));
    cfg.operation.status.port = squatter.port();
    StationRunner runner(std::move(cfg), nullptr, [](const StationConfig&) {
        return StationInput::fromReplay(std::make_unique<FailingCamera>(4), 30.0);
    });
    EXPECT_EQ(runner.statusPort(), -1);
    while (runner.step()) {}
    EXPECT_EQ(runner.frames(), 4u);
    const std::string status = runner.metrics().statusJson();
    EXPECT_NE(status.find("127.0.0.1:" + std::to_string(squatter.port())), std::string::npos) << status;
}

TEST(StationRunner, reloadSwapsTheSceneAtAFrameBoundaryAndKeepsTheInput) {
    auto ctx = HeadlessContext::create(GlRequest::Auto);
    test::TempDir dir;
    const fs::path file = dir.write("station.yaml", kRunnerStation);
    int opened = 0;
    StationRunner runner(loadStationConfig(file), nullptr, [&opened](const StationConfig&) {
        ++opened;
        return StationInput::fromReplay(std::make_unique<FailingCamera>(100), 30.0);
    });
    ASSERT_TRUE(runner.step());
    const auto centre = [&] {
        const Image image = runner.station().compositedFrame().read();
        const std::size_t i = (static_cast<std::size_t>(image.height / 2) * static_cast<std::size_t>(image.width) +
                               static_cast<std::size_t>(image.width / 2)) *
                              4;
        return glm::ivec3(image.rgba[i], image.rgba[i + 1], image.rgba[i + 2]);
    };
    const glm::ivec3 red = centre();
    EXPECT_GT(red.r, 2 * red.g) << "the box is red before the reload";

    std::string blue = kRunnerStation;
    blue.replace(blue.find("[0.9, 0.1, 0.1, 1]"), 18, "[0.1, 0.1, 0.9, 1]");
    dir.write("station.yaml", blue);
    requestReload();
    ASSERT_TRUE(runner.step());
    const glm::ivec3 now = centre();
    EXPECT_GT(now.b, 2 * now.r) << "the box is blue after the reload";
    EXPECT_EQ(runner.reloads(), 1u);
    EXPECT_EQ(opened, 1) << "an unchanged video section keeps the camera open";

    // A broken config is refused: the station goes on with what it had.
    dir.write("station.yaml", "scene:\n  objects:\n    - shape: cone\n");
    requestReload();
    ASSERT_TRUE(runner.step());
    EXPECT_EQ(runner.reloads(), 1u);
    EXPECT_EQ(centre(), now);
    EXPECT_NE(runner.metrics().statusJson().find("reload refused"), std::string::npos);
}

// Issue #60: a stream's counts reach /status and /metrics, and a reload
// gives the listening port back before the new station takes it again.
TEST(StationRunner, aStreamShowsInStatusAndMetricsAndKeepsItsListeningPortAcrossAReload) {
    if (!hasGstElement("srtsink") || !hasGstElement("x264enc"))
        GTEST_SKIP() << "GStreamer's srtsink or x264enc missing";
    auto ctx = HeadlessContext::create(GlRequest::Auto);
    test::TempDir dir;
    const std::string port = std::to_string(test::freeLoopbackPort(SOCK_DGRAM));
    const fs::path file = dir.write(
        "station.yaml", std::string(kRunnerStation) +
                            "output:\n  streams:\n    - name: lobby\n      url: srt://:" + port + "?mode=listener\n");
    StationRunner runner(withStatus(file), nullptr, [](const StationConfig&) {
        return StationInput::fromReplay(std::make_unique<FailingCamera>(100), 30.0);
    });
    for (int i = 0; i < 5; ++i) ASSERT_TRUE(runner.step());
    httplib::Client client("127.0.0.1", runner.statusPort());
    const std::string metrics = client.Get("/metrics")->body;
    EXPECT_NE(metrics.find("arcomp_stream_up{stream=\"lobby\"} 1"), std::string::npos) << metrics;
    EXPECT_NE(metrics.find("arcomp_stream_frames_total{stream=\"lobby\"} 5"), std::string::npos) << metrics;
    const std::string status = client.Get("/status")->body;
    EXPECT_NE(status.find(R"("streams":[{"name":"lobby","target":"srt listener on 127.0.0.1:)" + port),
              std::string::npos)
        << status;

    requestReload();  // the same config: the new station listens on the same port
    for (int i = 0; i < 3; ++i) ASSERT_TRUE(runner.step());
    EXPECT_EQ(runner.reloads(), 1u) << runner.metrics().statusJson();
    EXPECT_EQ(runner.metrics().statusJson().find("reload failed"), std::string::npos) << runner.metrics().statusJson();
    // (The file has no status section: the reloaded station has no endpoint.)
    const std::string after = runner.metrics().prometheusText();
    EXPECT_NE(after.find("arcomp_stream_up{stream=\"lobby\"} 1"), std::string::npos) << after;
    EXPECT_NE(after.find("arcomp_stream_frames_total{stream=\"lobby\"} 3"), std::string::npos) << after;
}

// A command-line override (arcomp replay --video) holds across reloads: the
// reloaded config gets it again, so the input is kept, not reopened from the file.
TEST(StationRunner, commandLineOverridesSurviveAReload) {
    auto ctx = HeadlessContext::create(GlRequest::Auto);
    test::TempDir dir;
    const fs::path file = dir.write("station.yaml", std::string(kRunnerStation) + "video: {source: pattern}\n");
    int opened = 0;
    std::vector<std::string> openedPaths;
    StationRunner runner(
        loadStationConfig(file),
        [](StationConfig& cfg) {
            SourceSpec recorded;
            recorded.kind = SourceKind::File;
            recorded.path = "recorded.avi";
            cfg.compositing.video = recorded;
        },
        [&](const StationConfig& cfg) {
            ++opened;
            openedPaths.push_back(cfg.compositing.video->path);
            return StationInput::fromReplay(std::make_unique<FailingCamera>(100), 30.0);
        });
    ASSERT_TRUE(runner.step());
    requestReload();
    ASSERT_TRUE(runner.step());
    EXPECT_EQ(runner.reloads(), 1u);
    EXPECT_EQ(opened, 1);
    EXPECT_EQ(openedPaths, std::vector<std::string>{"recorded.avi"});
    EXPECT_EQ(runner.config().compositing.video->path, "recorded.avi");
}

TEST(StationRunner, aModelTurnedToGarbageAtReloadIsSkippedAndReportedAndFramesGoOn) {
    auto ctx = HeadlessContext::create(GlRequest::Auto);
    test::TempDir dir;
    dir.write("tri.obj", "v -1 -1 -4\nv 1 -1 -4\nv 0 1 -4\nf 1 2 3\n");
    const fs::path file = dir.write("station.yaml", R"(scene:
  objects:
    - model: tri.obj
      color: [0.9, 0.1, 0.1, 1]
camera: {eye: [0, 0, 0], target: [0, 0, -1]}
)");
    StationRunner runner(loadStationConfig(file), nullptr, [](const StationConfig&) {
        return StationInput::fromReplay(std::make_unique<FailingCamera>(100), 30.0);
    });
    ASSERT_TRUE(runner.step());
    EXPECT_GT(runner.station().stats().cgTriangles, 0u);

    dir.write("tri.obj", std::string("\x89PNG\r\n\x1a\n\0\0\0garbage", 18));
    requestReload();
    ASSERT_TRUE(runner.step());
    ASSERT_TRUE(runner.step());
    EXPECT_EQ(runner.reloads(), 1u);
    EXPECT_EQ(runner.station().stats().cgTriangles, 0u) << "the broken model is skipped";
    EXPECT_NE(runner.metrics().statusJson().find("tri.obj"), std::string::npos) << runner.metrics().statusJson();
}

TEST(StationRunner, anOutputThatCannotBeWrittenIsCountedAndReportedWhileFramesGoOn) {
    auto ctx = HeadlessContext::create(GlRequest::Auto);
    test::TempDir dir;
    StationConfig cfg = loadStationConfig(dir.write("station.yaml", kRunnerStation));
    cfg.compositing.output.pngDir = dir.write("blocked", "a file where the output folder should be");
    StationRunner runner(cfg, nullptr, [](const StationConfig&) {
        return StationInput::fromReplay(std::make_unique<FailingCamera>(5), 30.0);
    });
    while (runner.step()) {}
    EXPECT_EQ(runner.frames(), 5u);
    EXPECT_EQ(runner.outputFailures(), 5u);
    EXPECT_NE(runner.station().lastOutputError().find("blocked"), std::string::npos)
        << runner.station().lastOutputError();
    EXPECT_NE(runner.metrics().statusJson().find("output: cannot write"), std::string::npos)
        << runner.metrics().statusJson();
}

// Cues from a real liblo sender reach the station before the next frame: a
// hidden box is shown, a cue for an object the scene does not have is
// refused and counted, and a reload cue reloads.
TEST(StationRunner, oscCuesShowAnObjectRefuseAnUnknownOneAndReload) {
    auto ctx = HeadlessContext::create(GlRequest::Auto);
    test::TempDir dir;
    std::string station = kRunnerStation;
    station.replace(station.find("    - shape: box"), 16, "    - name: sign\n      visible: false\n      shape: box");
    StationConfig cfg = loadStationConfig(dir.write("station.yaml", station + R"(show_control:
  cues: {osc: {listen: 9100}}
)"));
    // Any free port, on start and on the reload alike.
    const auto anyPort = [](StationConfig& c) { c.showControl.cues.listen.port = 0; };
    StationRunner runner(std::move(cfg), anyPort, [](const StationConfig&) {
        return StationInput::fromReplay(std::make_unique<FailingCamera>(100), 30.0);
    });
    ASSERT_GT(runner.cuePort(), 0);
    ASSERT_TRUE(runner.step());
    EXPECT_TRUE(runner.station().drawList().items.empty()) << "hidden";
    lo_address to = lo_address_new("127.0.0.1", std::to_string(runner.cuePort()).c_str());
    lo_send(to, "/arcomp/cue/show", "s", "sign");
    lo_send(to, "/arcomp/cue/show", "s", "ghost");
    // Sent on loopback; the next step reads what has arrived by then.
    for (int i = 0; i < 50 && runner.cueCounts().received < 2; ++i) {
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
        ASSERT_TRUE(runner.step());
    }
    EXPECT_EQ(runner.station().drawList().items.size(), 1u) << "shown by the cue";
    const std::string metrics = runner.metrics().prometheusText();
    EXPECT_NE(metrics.find("arcomp_cues_total{result=\"accepted\"} 1"), std::string::npos) << metrics;
    EXPECT_NE(metrics.find("arcomp_cues_total{result=\"refused\"} 1"), std::string::npos) << metrics;
    lo_send(to, "/arcomp/cue/reload", "");
    for (int i = 0; i < 50 && runner.reloads() == 0; ++i) {
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
        ASSERT_TRUE(runner.step());
    }
    lo_address_free(to);
    EXPECT_EQ(runner.reloads(), 1u);
    EXPECT_TRUE(runner.station().drawList().items.empty()) << "the reloaded config hides it again";
}
