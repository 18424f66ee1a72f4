// Inputs kept from fuzzing the config, calibration, camera-file and
// gaze-track readers and the status endpoint's request parser
// (tests/support/ParserRegressions.hpp), fed to them again.

#include "runtime/config/CalibrationFile.hpp"
#include "runtime/config/CameraFile.hpp"
#include "runtime/config/ConfigError.hpp"
#include "runtime/config/StationConfig.hpp"
#include "runtime/operator/HttpRequest.hpp"
#include "runtime/station/GazeSource.hpp"
#include "tests/support/ParserRegressions.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <iterator>
#include <typeinfo>
#include <vector>

using namespace arcomp;
using arcomp::test::eachLoadsOrIsRefused;
using arcomp::test::eachRegressionInput;
namespace fs = std::filesystem;

TEST(ParserRegressions, configInputsLoadOrAreRefusedWithConfigError) {
    eachLoadsOrIsRefused<ConfigError>("config", [](const fs::path& f) { loadStationConfig(f); });
}

TEST(ParserRegressions, calibrationInputsLoadOrAreRefusedWithConfigError) {
    eachLoadsOrIsRefused<ConfigError>("calibration", [](const fs::path& f) { readCalibration(f); });
}

TEST(ParserRegressions, gazeTrackInputsLoadOrAreRefusedWithGazeTrackError) {
    eachLoadsOrIsRefused<GazeTrackError>("gaze", [](const fs::path& f) { readGazeTrackCsv(f); });
}

TEST(ParserRegressions, cameraFileInputsLoadOrAreRefusedWithConfigError) {
    eachLoadsOrIsRefused<ConfigError>("camera", [](const fs::path& f) { readCameraFile(f); });
}

// The request parser returns a state rather than throwing: each input ends
// in one, with what the server relies on (as tools/fuzz/fuzz_http.cpp checks).
TEST(ParserRegressions, httpRequestHeadsEndInAStateTheServerCanActOn) {
    eachRegressionInput("http", [](const fs::path& f) {
        std::ifstream in(f, std::ios::binary);
        const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
        const HttpRequestHead head = parseHttpRequestHead(bytes);
        if (head.state == HttpRequestHead::Complete) {
            EXPECT_FALSE(head.method.empty()) << f;
            EXPECT_TRUE(head.path.starts_with('/')) << f << ": " << head.path;
        }
        if (head.state == HttpRequestHead::Bad) {
            EXPECT_FALSE(head.error.empty()) << f;
        }
    });
}
