#include "runtime/config/ZoneConfig.hpp"

#include "graph/camera/CalibratedCamera.hpp"
#include "runtime/config/YamlMap.hpp"

#include <cmath>
#include <set>

namespace arcomp {
namespace {

// [x, y] pairs; a problem is reported at the node and gives nothing.
std::optional<std::vector<glm::vec2>> points(const YAML::Node& node, const std::string& where, ConfigReport& report) {
    if (!node.IsSequence()) {
        report.add(node.Mark(), where + ": expected a list of [x, z] corners, e.g. [[-1, 1], [1, 1], [0, 2]]");
        return std::nullopt;
    }
    std::vector<glm::vec2> out;
    for (std::size_t i = 0; i < node.size(); ++i) {
        const YAML::Node p = node[i];
        glm::vec2 v;
        try {
            if (!p.IsSequence() || p.size() != 2) throw YAML::Exception(p.Mark(), "");
            v = {p[0].as<float>(), p[1].as<float>()};
        } catch (const YAML::Exception&) {
            report.add(p.Mark(), where + "[" + std::to_string(i) + "]: expected a corner [x, z] of two numbers");
            return std::nullopt;
        }
        if (!std::isfinite(v.x) || !std::isfinite(v.y)) {
            report.add(p.Mark(), where + "[" + std::to_string(i) + "]: not a finite number");
            return std::nullopt;
        }
        out.push_back(v);
    }
    return out;
}

// Whether the calibrated camera sees any of the floor zone.
bool seen(const Zone& zone, const CalibratedCamera& camera) {
    const glm::dvec2 size(camera.intrinsics.imageSize);
    for (const glm::vec2& p : samplePoints(zone)) {
        const glm::dvec3 floor(p.x, 0.0, p.y);
        if (camera.depthOf(floor) <= 0.0) continue;
        const glm::dvec2 pixel = camera.project(floor);
        if (pixel.x >= 0.0 && pixel.y >= 0.0 && pixel.x < size.x && pixel.y < size.y) return true;
    }
    return false;
}

}  // namespace

void readZoneConfig(YamlMap& root, const std::optional<CalibratedCamera>& camera, std::vector<Zone>& out) {
    std::set<std::string> names;
    auto zones = root.list("zones");
    for (std::size_t i = 0; i < zones.size(); ++i) {
        YamlMap& z = zones[i];
        ConfigReport& report = z.report();
        Zone zone;
        z.text("name", zone.name, Required::Yes);
        if (z.has("name") && zone.name.empty())
            report.add(z.mark(), z.where() + ".name: empty; a zone needs a name for its events and messages");
        const std::string label =
            "zones[" + std::to_string(i) + "]" + (zone.name.empty() ? "" : " '" + zone.name + "'");
        if (!zone.name.empty() && !names.insert(zone.name).second)
            report.add(z.mark(), label + ": the name is used by an earlier zone; each zone needs its own");
        const int shapes = int(z.has("polygon")) + int(z.has("circle")) + int(z.has("image_rect"));
        if (shapes != 1) {
            report.add(z.mark(), label +
                                     ": give one shape: polygon (floor metres), circle (floor metres) or "
                                     "image_rect (picture 0..1); it has " +
                                     std::to_string(shapes));
            z.take("polygon");
            z.take("circle");
            z.take("image_rect");
            z.finish();
            continue;
        }
        bool ok = true;
        if (z.has("polygon")) {
            const YAML::Node node = z.take("polygon");
            if (auto corners = points(node, label + ".polygon", report)) {
                zone.polygon = *corners;
                if (const std::string problem = polygonProblem(zone.polygon); !problem.empty()) {
                    report.add(node.Mark(), label + ".polygon: " + problem);
                    ok = false;
                }
            } else {
                ok = false;
            }
        } else if (z.has("circle")) {
            YamlMap circle = z.map("circle");
            std::vector<float> center;
            circle.numbers("center", center, -1e6, 1e6, Required::Yes);
            circle.number("radius", zone.radius, 1e-3, 1e6, Required::Yes);
            circle.finish();
            if (center.size() == 2)
                zone.center = {center[0], center[1]};
            else {
                if (circle.has("center")) report.add(circle.mark(), label + ".circle.center: expected [x, z]");
                ok = false;
            }
        } else {
            zone.space = ZoneSpace::Image;
            YamlMap rect = z.map("image_rect");
            std::vector<float> lo, hi;
            rect.numbers("min", lo, 0.0, 1.0, Required::Yes);
            rect.numbers("max", hi, 0.0, 1.0, Required::Yes);
            rect.finish();
            if (lo.size() == 2 && hi.size() == 2 && lo[0] < hi[0] && lo[1] < hi[1])
                zone.polygon = {{lo[0], lo[1]}, {hi[0], lo[1]}, {hi[0], hi[1]}, {lo[0], hi[1]}};
            else {
                report.add(rect.mark(), label + ".image_rect: expected min: [u, v] below and left of max: [u, v], "
                                                "each 0..1");
                ok = false;
            }
        }
        zone.enterMargin = zone.leaveMargin = defaultMargin(zone.space);
        z.number("enter_margin", zone.enterMargin, 0.0, 100.0);
        z.number("leave_margin", zone.leaveMargin, 0.0, 100.0);
        z.finish();
        if (!ok) continue;
        if (zone.space == ZoneSpace::Floor && !camera) {
            report.add(z.mark(), label + ": a floor zone is in metres, which needs camera.calibration; without "
                                         "one, give image_rect in the picture's 0..1");
            continue;
        }
        if (zone.space == ZoneSpace::Floor && !seen(zone, *camera)) {
            report.add(z.mark(), label + ": lies wholly outside the calibrated camera's view of the floor");
            continue;
        }
        out.push_back(std::move(zone));
    }
}

}  // namespace arcomp
