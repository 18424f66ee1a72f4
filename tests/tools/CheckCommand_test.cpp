// arcomp check: every class of config error is reported with its place and
// exits 2; a good config with loadable assets exits 0.

#include "../support/TempDir.hpp"

#include <gtest/gtest.h>

#include "tests/support/FreePort.hpp"
#include "tests/support/Shell.hpp"
#include <arpa/inet.h>
#include <array>
#include <cstdio>
#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

using arcomp::test::TempDir;

namespace {

arcomp::test::ShellResult check(const std::filesystem::path& config) {
    return arcomp::test::arcompCommand("check " + config.string());
}

}  // namespace

TEST(CheckCommand, acceptsEveryShippedConfig) {
    std::size_t configs = 0;
    for (const auto& entry :
         std::filesystem::directory_iterator(std::filesystem::path(ARCOMP_SOURCE_DIR) / "configs")) {
        if (entry.path().extension() != ".yaml") continue;
        ++configs;
        const auto r = check(entry.path());
        EXPECT_EQ(r.code, 0) << r.out;
        EXPECT_NE(r.out.find(": ok ("), std::string::npos) << r.out;
    }
    EXPECT_GE(configs, 4u);
}

// Each class of error: the config, and the message expected with its place.
struct ConfigErrorCase {
    const char* name;
    const char* yaml;
    const char* expected;
};

class CheckCommandRejects : public ::testing::TestWithParam<ConfigErrorCase> {};

TEST_P(CheckCommandRejects, withTheMessageAtItsLineAndColumn) {
    TempDir dir;
    const auto r = check(dir.write("station.yaml", GetParam().yaml));
    EXPECT_EQ(r.code, 2) << r.out;
    EXPECT_NE(r.out.find(GetParam().expected), std::string::npos) << r.out;
}

INSTANTIATE_TEST_SUITE_P(
    ErrorClasses, CheckCommandRejects,
    ::testing::Values(
        ConfigErrorCase{"unknownKey", "scene:\n  objects:\n    - shape: box\n      colour: [1, 0, 0, 1]\n",
                        "station.yaml:4:7: scene.objects[0].colour: unknown key; expected one of color,"},
        ConfigErrorCase{"wrongType", "scene:\n  objects:\n    - shape: box\n      position: forward\n",
                        "station.yaml:4:17: scene.objects[0].position"},
        ConfigErrorCase{"missingFile", "scene:\n  objects:\n    - model: statue.glb\n", "statue.glb' does not exist"},
        ConfigErrorCase{"missingEnvironment",
                        "scene:\n  objects:\n    - shape: box\nrender:\n  environment: studio.hdr\n",
                        "studio.hdr: environment file does not exist"},
        ConfigErrorCase{"missingFilePlace", "scene:\n  objects:\n    - model: statue.glb\n",
                        "station.yaml:3:14: scene.objects[0].model: file '"},
        ConfigErrorCase{"numberOutOfRange", "scene:\n  objects:\n    - shape: box\nstatus:\n  port: 99999\n",
                        "station.yaml:5:9: status.port: 99999 is out of range; expected 1 to 65535"},
        ConfigErrorCase{
            "statusBeyondLoopbackWithoutAToken", "status:\n  port: 9464\n  bind: 0.0.0.0\n",
            "station.yaml:2:3: status.bind: 0.0.0.0 is beyond loopback, so the endpoint needs status.token_file"},
        ConfigErrorCase{"cameraCalibrationMissing",
                        "scene:\n  objects:\n    - shape: box\ncamera:\n  calibration: cam.yaml\n",
                        "camera.calibration: file '"},
        ConfigErrorCase{
            "cameraCalibrationAndEye",
            "scene:\n  objects:\n    - shape: box\ncamera:\n  calibration: station.yaml\n  eye: [0, 1, 5]\n",
            "camera.eye: not used with camera.calibration"},
        ConfigErrorCase{"encodingOddSize", "output:\n  video_file: show.mp4\n  encoding:\n    size: [641, 480]\n",
                        "station.yaml:4:5: output.encoding.size: expected even width and height"},
        ConfigErrorCase{"encodingBitrate", "output:\n  video_file: show.mp4\n  encoding: {bitrate_kbps: 5}\n",
                        "output.encoding.bitrate_kbps: 5 is out of range"},
        ConfigErrorCase{"streamUrl", "output:\n  streams:\n    - name: obs\n      url: udp://10.0.0.2:9000\n",
                        "station.yaml:4:12: output.streams[0].url: udp://10.0.0.2:9000: expected srt://host:port or "
                        "rtsp://host:port/name"},
        ConfigErrorCase{"streamPort", "output:\n  streams:\n    - name: obs\n      url: srt://10.0.0.2:99999\n",
                        "output.streams[0].url: srt://10.0.0.2:99999: expected a port from 1 to 65535"},
        ConfigErrorCase{"streamListenerBeyondLoopback",
                        "output:\n  streams:\n    - name: lobby\n      url: srt://0.0.0.0:9000?mode=listener\n",
                        "station.yaml:3:7: output.streams[0].url: a listener on 0.0.0.0 is beyond loopback, so it "
                        "needs passphrase_file"},
        ConfigErrorCase{"rtspBeyondLoopbackWithoutCredentials",
                        "output:\n  streams:\n    - name: hall\n      url: rtsp://0.0.0.0:8554/hall\n",
                        "station.yaml:3:7: output.streams[0].url: an RTSP server on 0.0.0.0 is beyond loopback, so "
                        "it needs credentials_file"},
        ConfigErrorCase{"rtspCredentialsForSrt",
                        "output:\n  streams:\n    - name: obs\n      url: srt://10.0.0.2:9000\n"
                        "      credentials_file: station.yaml\n",
                        "output.streams[0].credentials_file: only for rtsp://"},
        ConfigErrorCase{"streamNamesTwice",
                        "output:\n  streams:\n    - {name: a, url: 'srt://h:1'}\n    - {name: a, url: 'srt://h:2'}\n",
                        "output.streams[1].name: a is used by another stream"},
        ConfigErrorCase{"statusTokenFileMissing", "status:\n  port: 9464\n  bind: 0.0.0.0\n  token_file: token.txt\n",
                        "status.token_file: file '"}),
    [](const auto& info) { return std::string(info.param.name); });

TEST(CheckCommand, aStatusEndpointBeyondLoopbackNeedsAUsableTokenFile) {
    TempDir dir;
    const auto config = dir.write(
        "station.yaml",
        "scene:\n  objects:\n    - shape: box\nstatus:\n  port: 9464\n  bind: 0.0.0.0\n  token_file: token.txt\n");
    dir.write("token.txt", "hunter2\n");
    auto r = check(config);
    EXPECT_EQ(r.code, 2) << r.out;
    EXPECT_NE(r.out.find("status.token_file: " + (dir.path() / "token.txt").string() +
                         ": line 1: the status token is 7 characters"),
              std::string::npos)
        << r.out;
    dir.write("token.txt", "9f86d081884c7d659a2feaa0c55ad015\n");
    r = check(config);
    EXPECT_EQ(r.code, 0) << r.out;
    // The token never appears in what check prints.
    EXPECT_EQ(r.out.find("9f86d081884c7d659a2feaa0c55ad015"), std::string::npos) << r.out;
}

TEST(CheckCommand, anRtspServerBeyondLoopbackNeedsUsableCredentials) {
    TempDir dir;
    const auto config = dir.write("station.yaml", "scene:\n  objects:\n    - shape: box\noutput:\n  streams:\n"
                                                  "    - name: hall\n      url: rtsp://0.0.0.0:" +
                                                      std::to_string(arcomp::test::freeLoopbackPort(SOCK_STREAM)) +
                                                      "/hall\n      credentials_file: viewer.txt\n");
    const std::string file = (dir.path() / "viewer.txt").string();
    dir.write("viewer.txt", "screen-password-only\n");
    auto r = check(config);
    EXPECT_EQ(r.code, 2) << r.out;
    EXPECT_NE(r.out.find("output.streams[0].credentials_file: " + file + ": line 1: expected user:password"),
              std::string::npos)
        << r.out;
    dir.write("viewer.txt", "screen:short\n");
    r = check(config);
    EXPECT_NE(r.out.find(file + ": line 1: the password is 5 characters; expected at least 10"), std::string::npos)
        << r.out;
    dir.write("viewer.txt", "screen:a-long-enough-secret\n");
    r = check(config);
    EXPECT_EQ(r.code, 0) << r.out;
    EXPECT_EQ(r.out.find("a-long-enough-secret"), std::string::npos) << "the password is never printed: " << r.out;
}

TEST(CheckCommand, everyErrorIsListedAtOnce) {
    TempDir dir;
    const auto file = dir.write(
        "station.yaml", "scene:\n  objects:\n    - shape: cone\nrender:\n  shading: glossy\nlog:\n  level: loud\n");
    const auto r = check(file);
    EXPECT_EQ(r.code, 2) << r.out;
    EXPECT_NE(r.out.find("3 errors"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find(":3:14: scene.objects[0].shape"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find(":5:12: render.shading"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find(":7:10: log.level"), std::string::npos) << r.out;
}

// The environment `arcomp environment` writes is one check accepts; a file
// that is not an image is refused, named.
TEST(CheckCommand, readsTheEnvironmentFileItNames) {
    TempDir dir;
    const auto written = arcomp::test::arcompCommand("environment --out " + (dir.path() / "neutral.hdr").string());
    ASSERT_EQ(written.code, 0) << written.out;
    const auto good =
        check(dir.write("good.yaml", "scene:\n  objects:\n    - shape: box\nrender:\n  environment: neutral.hdr\n"));
    EXPECT_EQ(good.code, 0) << good.out;
    dir.write("notes.hdr", "these are notes, not light");
    const auto bad =
        check(dir.write("bad.yaml", "scene:\n  objects:\n    - shape: box\nrender:\n  environment: notes.hdr\n"));
    EXPECT_EQ(bad.code, 2) << bad.out;
    EXPECT_NE(bad.out.find("notes.hdr: cannot decode the environment"), std::string::npos) << bad.out;
}

// Issue #60: GStreamer with no plugins at all (an empty plugin path and a
// registry of its own) stands for a machine without x264: an H.264
// recording is refused at its line, naming the package to install.
TEST(CheckCommand, anH264RecordingWithoutAnEncoderIsRefusedNamingThePackage) {
    TempDir dir;
    const auto config =
        dir.write("station.yaml", "scene:\n  objects:\n    - shape: box\noutput:\n  video_file: show.mp4\n");
    const std::string bare = "GST_PLUGIN_SYSTEM_PATH_1_0=" + dir.path().string() +
                             " GST_PLUGIN_PATH_1_0= " + "GST_REGISTRY_1_0=" + (dir.path() / "registry.bin").string() +
                             " ";
    const auto r = arcomp::test::shell(bare + ARCOMP_BINARY + " check " + config.string());
    EXPECT_EQ(r.code, 2) << r.out;
    EXPECT_NE(r.out.find("station.yaml:5:15: output.video_file: no H.264 encoder: GStreamer element x264enc "
                         "missing (install gstreamer1.0-plugins-ugly)"),
              std::string::npos)
        << r.out;
    const auto stream = dir.write(
        "stream.yaml",
        "scene:\n  objects:\n    - shape: box\noutput:\n  streams:\n    - {name: obs, url: 'srt://10.0.0.2:9000'}\n");
    const auto s = arcomp::test::shell(bare + ARCOMP_BINARY + " check " + stream.string());
    EXPECT_EQ(s.code, 2) << s.out;
    EXPECT_NE(s.out.find("stream.yaml:6:24: output.streams obs: no H.264 encoder"), std::string::npos) << s.out;
    const auto avi = dir.write("avi.yaml", "scene:\n  objects:\n    - shape: box\noutput:\n  video_file: show.avi\n");
    EXPECT_EQ(arcomp::test::shell(bare + ARCOMP_BINARY + " check " + avi.string()).code, 0)
        << "OpenCV's writer needs no GStreamer plugin";
}

// A listening stream (an SRT listener on UDP, an RTSP server on TCP) whose
// port another program holds: refused at its URL.
TEST(CheckCommand, aStreamListeningOnAPortTakenIsRefusedAtItsUrl) {
    for (const bool rtsp : {false, true}) {
        TempDir dir;
        const int taken = socket(AF_INET, rtsp ? SOCK_STREAM : SOCK_DGRAM, 0);
        sockaddr_in address{};
        address.sin_family = AF_INET;
        address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
        ASSERT_EQ(bind(taken, reinterpret_cast<sockaddr*>(&address), sizeof address), 0);
        if (rtsp) {
            ASSERT_EQ(listen(taken, 1), 0);
        }
        socklen_t length = sizeof address;
        getsockname(taken, reinterpret_cast<sockaddr*>(&address), &length);
        const std::string port = std::to_string(ntohs(address.sin_port));
        const std::string url = rtsp ? "rtsp://:" + port + "/lobby" : "srt://:" + port + "?mode=listener";
        const auto config = dir.write("station.yaml", "scene:\n  objects:\n    - shape: box\noutput:\n  streams:\n"
                                                      "    - name: lobby\n      url: " +
                                                          url + "\n");
        const auto r = check(config);
        EXPECT_EQ(r.code, 2) << r.out;
        EXPECT_NE(r.out.find("station.yaml:7:12: output.streams lobby.url: port " + port + " on 127.0.0.1 is taken"),
                  std::string::npos)
            << r.out;
        close(taken);
        EXPECT_EQ(check(config).code, 0) << url << " free again";
    }
}
