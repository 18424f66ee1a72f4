// Inputs that once broke the config, calibration or gaze-track reader
// (tests/support/ParserRegressions.hpp), fed to it again.

#include "runtime/CalibrationFile.hpp"
#include "runtime/ConfigError.hpp"
#include "runtime/GazeSource.hpp"
#include "runtime/StationConfig.hpp"
#include "tests/support/ParserRegressions.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <typeinfo>
#include <vector>

using namespace arcomp;
using arcomp::test::eachLoadsOrIsRefused;
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
