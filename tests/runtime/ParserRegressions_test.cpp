// Inputs that once broke the config or calibration reader (found by the
// fuzzers in tools/fuzz, kept under tests/fuzz-regressions/<target>/), fed
// to it again: each must load or be refused with ConfigError.

#include "runtime/CalibrationFile.hpp"
#include "runtime/ConfigError.hpp"
#include "runtime/StationConfig.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <typeinfo>
#include <vector>

using namespace arcomp;
namespace fs = std::filesystem;

namespace {

void eachLoadsOrIsRefused(const std::string& target, const std::function<void(const fs::path&)>& parse) {
    const fs::path dir = fs::path(ARCOMP_SOURCE_DIR) / "tests/fuzz-regressions" / target;
    int inputs = 0;
    if (fs::exists(dir))
        for (const auto& e : fs::directory_iterator(dir)) {
            if (!e.is_regular_file()) continue;
            ++inputs;
            try {
                parse(e.path());
            } catch (const ConfigError&) {
            } catch (const std::exception& x) {
                ADD_FAILURE() << e.path() << ": escaped as " << typeid(x).name() << ": " << x.what();
            }
        }
    EXPECT_GT(inputs, 0) << dir << " holds no inputs";
}

} // namespace

TEST(ParserRegressions, configInputsLoadOrAreRefusedWithConfigError) {
    eachLoadsOrIsRefused("config", [](const fs::path& f) { loadStationConfig(f); });
}

TEST(ParserRegressions, calibrationInputsLoadOrAreRefusedWithConfigError) {
    eachLoadsOrIsRefused("calibration", [](const fs::path& f) { readCalibration(f); });
}
