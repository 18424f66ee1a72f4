#include "runtime/config/CalibrationFile.hpp"

#include "runtime/config/YamlMap.hpp"

#include <algorithm>
#include <fstream>
#include <iomanip>
#include <stdexcept>

namespace arcomp {

namespace {

const char* const kShadingKeys[kShadingCount] = {"unlit", "flat", "gouraud", "phong"};

// [A, B]: two numbers, neither negative.
void readPair(YamlMap& m, const char* key, CostCoefficients& out) {
    const std::string where = m.where() + "." + key;
    if (!m.has(key)) {
        m.report().add(m.mark(), where + ": missing; expected [A ms/pixel, B ms]");
        return;
    }
    const YAML::Node n = m.take(key);
    double a = 0, b = 0;
    if (!n.IsSequence() || n.size() != 2 || !YAML::convert<double>::decode(n[0], a) ||
        !YAML::convert<double>::decode(n[1], b) || !(a >= 0.0) || !(b >= 0.0)) {
        m.report().add(n.Mark(), where + ": expected [A ms/pixel, B ms], two numbers >= 0");
        return;
    }
    out = {a, b};
}

}  // namespace

void writeCalibration(const std::filesystem::path& file, const CostModel& model, const CalibrationInfo& info) {
    if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
    std::ofstream out(file);
    if (!out) throw std::runtime_error(file.string() + ": cannot be written");
    out << "# arcomp cost calibration (paper: uniform-frame-time): per LOD level and\n"
           "# shading, [A, B] of t = A * pixels + B, in ms per pixel and ms; pixels is\n"
           "# the projected disc of the object's bounding sphere.\n";
    out << "device: \"" << info.device << "\"\n";
    out << "viewport: [" << info.viewport.x << ", " << info.viewport.y << "]\n";
    out << std::setprecision(6) << "overhead_ms: " << model.overheadMs << "\nlevels:\n";
    for (std::size_t l = 0; l < model.levels(); ++l) {
        out << "  - {";
        for (int s = 0; s < kShadingCount; ++s) {
            const CostCoefficients& c = model.at(l, static_cast<Shading>(s));
            out << (s ? ", " : "") << kShadingKeys[s] << ": [" << c.msPerPixel << ", " << c.ms << "]";
        }
        out << "}\n";
    }
    if (!out) throw std::runtime_error(file.string() + ": write failed");
}

CostModel readCalibration(const std::filesystem::path& file, CalibrationInfo* info) {
    ConfigReport report(file);
    YAML::Node rootNode = loadYamlFile(report);
    if (!rootNode) report.throwIfAny();
    YamlMap root(rootNode, "", report);
    CalibrationInfo read;
    root.text("device", read.device);
    root.vec2i("viewport", read.viewport, 1, 16384);
    double overhead = 0.0;
    root.number("overhead_ms", overhead, 0.0, 1e4, Required::Yes);
    std::vector<YamlMap> levels = root.list("levels", Required::Yes);
    if (levels.size() > 8) report.add(root.mark(), "levels: at most 8 LOD levels");
    CostModel model(std::max<std::size_t>(levels.size(), 1));
    for (std::size_t l = 0; l < levels.size() && l < 8; ++l) {
        for (int s = 0; s < kShadingCount; ++s) {
            CostCoefficients c;
            readPair(levels[l], kShadingKeys[s], c);
            model.set(l, static_cast<Shading>(s), c);
        }
        levels[l].finish();
    }
    root.finish();
    report.throwIfAny();
    model.overheadMs = overhead;
    if (info) *info = read;
    return model;
}

}  // namespace arcomp
