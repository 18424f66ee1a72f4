// The station config's budget section: absent means off; on with a target
// and a calibration; every mistake reported with its place.
#include "runtime/config/ConfigError.hpp"
#include "runtime/config/StationConfig.hpp"

#include "../support/TempDir.hpp"

#include <gtest/gtest.h>

using namespace arcomp;
using arcomp::test::TempDir;

namespace {
const char* const kUnplacedBox = "scene:\n  objects:\n    - shape: box\n";

std::string describe(const ConfigError& e) {
    std::string s;
    for (const ConfigIssue& i : e.issues) s += i.format() + "\n";
    return s;
}
}  // namespace

TEST(BudgetConfig, absentSectionLeavesTheControllerOff) {
    TempDir dir;
    const StationConfig cfg = loadStationConfig(dir.write("s.yaml", kUnplacedBox));
    EXPECT_FALSE(cfg.budget.enabled);
}

TEST(BudgetConfig, turnsTheControllerOnWithATargetAndACalibration) {
    TempDir dir;
    dir.write("calib.yaml",
              "overhead_ms: 1\nlevels:\n  - {unlit: [0, 1], flat: [0, 1], gouraud: [0, 1], phong: [0, 1]}\n");
    const StationConfig cfg = loadStationConfig(dir.write("s.yaml", std::string(kUnplacedBox) + R"(budget:
  enabled: true
  target_ms: 16.7
  change: [shading]
  calibration: calib.yaml
  hold_frames: 30
  upgrade_margin_pct: 8
)"));
    EXPECT_TRUE(cfg.budget.enabled);
    EXPECT_DOUBLE_EQ(cfg.budget.targetMs, 16.7);
    EXPECT_FALSE(cfg.budget.changeLevel);
    EXPECT_TRUE(cfg.budget.changeShading);
    EXPECT_EQ(cfg.budget.calibration, (dir.path() / "calib.yaml").lexically_normal());
    const BudgetSettings s = toBudgetSettings(cfg.budget);
    EXPECT_EQ(s.holdFrames, 30);
    EXPECT_DOUBLE_EQ(s.upgradeMargin, 0.08);
    EXPECT_DOUBLE_EQ(s.targetMs, 16.7);
}

TEST(BudgetConfig, reportsEveryMistakeWithItsPlace) {
    TempDir dir;
    const auto file = dir.write("s.yaml", std::string(kUnplacedBox) + R"(budget:
  enabled: true
  target_ms: -3
  change: [level, colour]
  refresh: 2
)");
    try {
        loadStationConfig(file);
        FAIL() << "expected a ConfigError";
    } catch (const ConfigError& e) {
        const std::string all = describe(e);
        EXPECT_NE(all.find("s.yaml:6:14"), std::string::npos) << all;  // target_ms out of range
        EXPECT_NE(all.find("budget.change: expected a list"), std::string::npos) << all;
        EXPECT_NE(all.find("s.yaml:8:3"), std::string::npos) << all;  // unknown key
        EXPECT_NE(all.find("budget.calibration: required when enabled"), std::string::npos) << all;
    }
}
