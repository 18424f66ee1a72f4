#include "runtime/config/BudgetConfig.hpp"

namespace arcomp {

void readBudgetConfig(YamlMap& root, BudgetConfig& out) {
    if (!root.has("budget")) return;
    YamlMap b = root.map("budget");
    b.boolean("enabled", out.enabled);
    b.number("target_ms", out.targetMs, 1.0, 10000.0);
    if (b.has("change")) {
        const YAML::Node list = b.take("change");
        bool ok = list.IsSequence() && list.size() > 0;
        bool level = false, shading = false;
        for (std::size_t i = 0; ok && i < list.size(); ++i) {
            std::string s;
            ok = YAML::convert<std::string>::decode(list[i], s) && (s == "level" || s == "shading");
            level |= s == "level";
            shading |= s == "shading";
        }
        if (!ok)
            b.report().add(list.Mark(), "budget.change: expected a list of 'level' and/or 'shading'");
        else {
            out.changeLevel = level;
            out.changeShading = shading;
        }
    }
    b.path("calibration", out.calibration, true);
    b.boolean("refit", out.refit);
    b.number("upgrade_margin_pct", out.upgradeMarginPct, 0.0, 50.0);
    b.integer("hold_frames", out.holdFrames, 0, 10000);
    b.number("eccentricity_floor", out.eccentricityFloor, 0.0, 1.0);
    if (out.enabled && out.calibration.empty())
        b.report().add(b.mark(), "budget.calibration: required when enabled; expected the file that "
                                 "`arcomp-bench calibrate --out DIR` writes");
    b.finish();
}

BudgetSettings toBudgetSettings(const BudgetConfig& c) {
    BudgetSettings s;
    s.targetMs = c.targetMs;
    s.changeLevel = c.changeLevel;
    s.changeShading = c.changeShading;
    s.upgradeMargin = c.upgradeMarginPct / 100.0;
    s.holdFrames = c.holdFrames;
    s.eccentricityFloor = c.eccentricityFloor;
    return s;
}

}  // namespace arcomp
