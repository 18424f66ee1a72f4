#include "tools/bench/drivers/ArInstallation.hpp"

#include "graph/core/ObjectMotion.hpp"
#include "runtime/config/CameraFile.hpp"
#include "runtime/station/SceneFile.hpp"
#include "tools/bench/probes/ShellCommand.hpp"

#include <opencv2/imgcodecs.hpp>

#include <cstdio>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>

namespace arcomp::ar {
namespace {

namespace fs = std::filesystem;

ObjectConfig box(const std::string& name, glm::vec3 size, glm::vec3 position, glm::vec4 colour) {
    ObjectConfig o;
    o.name = name;
    o.shape = "box";
    o.size = size;
    o.position = position;
    o.color = colour;
    return o;
}

// A grey checkerboard floor with paler lines every metre, 30 m square.
cv::Mat floorTexture(double texelsPerMetre) {
    const int side = static_cast<int>(30.0 * texelsPerMetre);
    cv::Mat floor(side, side, CV_8UC3);
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x) {
            const int cell = (x / static_cast<int>(texelsPerMetre / 2) + y / static_cast<int>(texelsPerMetre / 2)) % 2;
            const bool line = x % static_cast<int>(texelsPerMetre) < 2 || y % static_cast<int>(texelsPerMetre) < 2;
            floor.at<cv::Vec3b>(y, x) = line   ? cv::Vec3b(190, 190, 185)
                                        : cell ? cv::Vec3b(120, 125, 120)
                                               : cv::Vec3b(95, 100, 98);
        }
    return floor;
}

// Runs `arcomp <args>` (the station binary) and gives its standard output; throws when it fails.
std::string arcomp(const std::string& args) {
    const std::string command = shellQuote(stationBinary()) + " " + args + " 2>&1";
    std::FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) throw std::runtime_error("cannot run " + command);
    std::string out;
    char buffer[512];
    while (std::fgets(buffer, sizeof buffer, pipe)) out += buffer;
    if (pclose(pipe) != 0) throw std::runtime_error("`arcomp " + args + "` failed:\n" + out);
    return out;
}

}  // namespace

CalibratedCamera trueCamera() {
    CalibratedCamera c;
    c.intrinsics = {.imageSize = {kLens.size.width, kLens.size.height},
                    .fx = kLens.fx,
                    .fy = kLens.fy,
                    .cx = kLens.cx,
                    .cy = kLens.cy,
                    .distortion = {kLens.distortion[0], kLens.distortion[1], 0, 0, 0}};
    const double tilt = glm::radians(kTiltDegrees);
    const glm::dvec3 forward(0.0, -std::sin(tilt), -std::cos(tilt)), right(1.0, 0.0, 0.0);
    c.rotation = glm::transpose(glm::dmat3(right, glm::cross(forward, right), forward));
    c.translation = -c.rotation * glm::dvec3(0.0, kCameraHeight, kCameraZ);
    return c;
}

std::vector<ObjectConfig> cgObjects() {
    ObjectConfig sphere;
    sphere.name = "sphere";
    sphere.shape = "sphere";
    sphere.radius = 0.5f;
    sphere.position = {-2.4f, 0.5f, -4.5f};
    sphere.color = {0.1f, 0.3f, 0.95f, 1.0f};
    return {box("box", {1.2f, 1.4f, 0.6f}, {0.0f, 0.7f, 0.0f}, {0.1f, 0.15f, 0.9f, 1.0f}), sphere};
}

std::vector<ObjectConfig> walkers() {
    auto walker = [](const std::string& name, glm::vec3 start, glm::vec3 velocity, float range, glm::vec4 colour) {
        ObjectConfig o = box(name, {0.5f, 1.7f, 0.3f}, start, colour);
        o.velocity = velocity;
        o.rangeMetres = range;
        return o;
    };
    return {walker("behind", {-4.0f, 0.85f, -2.0f}, {0.8f, 0.0f, 0.0f}, 8.0f, {0.85f, 0.12f, 0.08f, 1.0f}),
            walker("in front", {4.0f, 0.85f, 2.2f}, {-0.7f, 0.0f, 0.0f}, 8.0f, {0.9f, 0.45f, 0.1f, 1.0f}),
            walker("towards", {0.95f, 0.85f, -8.0f}, {0.0f, 0.0f, 1.0f}, 12.0f, {0.8f, 0.2f, 0.3f, 1.0f})};
}

FloorTruth walkerAt(const ObjectConfig& walker, double seconds) {
    const ObjectMotion motion{.velocity = walker.velocity, .range = walker.rangeMetres};
    const glm::vec3 at = walker.position + motionOffset(motion, seconds);
    const glm::vec3 velocity = motionVelocity(motion, seconds);
    return {{at.x, at.z}, {velocity.x, velocity.z}};
}

cv::Mat floorPlate(const SyntheticCamera& lens) {
    const double texelsPerMetre = 40.0;
    return lens.photograph(floorTexture(texelsPerMetre), 1.0 / texelsPerMetre, {-15.0, -15.0},
                           floorToCamera(0.0, kCameraHeight, kCameraZ, kTiltDegrees));
}

cv::Mat bgraOf(const Image& img) {
    cv::Mat rgba(img.height, img.width, CV_8UC4, const_cast<std::uint8_t*>(img.rgba.data())), bgra;
    cv::cvtColor(rgba, bgra, cv::COLOR_RGBA2BGRA);
    return bgra;
}

cv::Mat over(const cv::Mat& layer, const cv::Mat& under) {
    cv::Mat out(under.size(), CV_8UC3);
    for (int y = 0; y < out.rows; ++y)
        for (int x = 0; x < out.cols; ++x) {
            const cv::Vec4b l = layer.at<cv::Vec4b>(y, x);
            const cv::Vec3b u = under.at<cv::Vec3b>(y, x);
            for (int c = 0; c < 3; ++c)
                out.at<cv::Vec3b>(y, x)[c] = cv::saturate_cast<std::uint8_t>(l[c] + u[c] * (255 - l[3]) / 255.0);
        }
    return out;
}

ObjectPainter::ObjectPainter(std::vector<ObjectConfig> objects, const View& view)
    : view_(view), target_(view.viewport) {
    StationConfig cfg;
    cfg.file = "bench-ar";
    cfg.objects = std::move(objects);
    std::vector<std::string> warnings;
    buildScene(cfg, world_, warnings);
}

cv::Mat ObjectPainter::paint(double seconds, Shading shading) {
    moveObjects(world_, seconds);
    world_.scene.update();
    DrawList list;
    select(world_, view_, {.shading = shading, .lod = false, .grouping = false}, list);
    target_.bind();
    renderer_.draw(world_.scene, list, view_, {.clearColor = glm::vec4(0.0f)});
    return bgraOf(target_.read());
}

Calibration calibrate(const SyntheticCamera& lens, const fs::path& dir) {
    // 14 views of a 9 x 6 chessboard of 4 cm squares, 0.6-1 m away, tilted each way.
    fs::create_directories(dir / "board");
    const int texels = 40;
    const cv::Mat board = chessboardTexture(9, 6, texels);
    for (int i = 0; i < 14; ++i) {
        const double a = 0.45 * std::sin(i * 1.3), b = 0.4 * std::cos(i * 0.9), c = 0.15 * std::sin(i * 2.1);
        const cv::Vec3d rvec(a, b, c),
            tvec(-0.22 + 0.12 * std::sin(i * 0.7), -0.15 + 0.1 * std::cos(i * 1.1), 0.6 + 0.03 * i);
        char name[32];
        std::snprintf(name, sizeof name, "view-%02d.png", i);
        cv::imwrite((dir / "board" / name).string(),
                    lens.photograph(board, 0.04 / texels, {-0.04, -0.04}, boardToCamera(rvec, tvec)));
    }
    const std::string intrinsics =
        arcomp("calibrate intrinsics " + (dir / "board").string() +
               " --board chessboard --cols 9 --rows 6 --square 0.04 --out " + (dir / "lens.yaml").string());
    // An ArUco marker of 1.5 m (a floor decal) at the floor's origin, 10 m from the lens.
    const cv::Mat floor =
        floorWithMarkers(cv::aruco::getPredefinedDictionary(cv::aruco::DICT_4X4_50), {{7, 0.0, 0.0}}, 1.5, 3.0, 200);
    cv::imwrite(
        (dir / "floor-marker.png").string(),
        lens.photograph(floor, 1.0 / 200, {-1.5, -1.5}, floorToCamera(0.0, kCameraHeight, kCameraZ, kTiltDegrees)));
    (void)arcomp("calibrate floor " + (dir / "floor-marker.png").string() + " --intrinsics " +
                 (dir / "lens.yaml").string() + " --marker 7 --marker-size 1.5 --out " +
                 (dir / "camera.yaml").string());

    Calibration c;
    c.camera = readCameraFile(dir / "camera.yaml");
    const CalibratedCamera truth = trueCamera();
    const CameraIntrinsics &k = c.camera.intrinsics, &t = truth.intrinsics;
    c.focalErrPct = 100.0 * std::max(std::abs(k.fx - t.fx) / t.fx, std::abs(k.fy - t.fy) / t.fy);
    c.principalErrPx = std::max(std::abs(k.cx - t.cx), std::abs(k.cy - t.cy));
    if (const auto at = intrinsics.find("reprojection "); at != std::string::npos)
        c.rmsPx = std::stod(intrinsics.substr(at + 13));
    c.heightErrPct = 100.0 * std::abs(c.camera.heightMetres() - truth.heightMetres()) / truth.heightMetres();
    c.tiltErrDeg = std::abs(c.camera.tiltDegrees() - truth.tiltDegrees());
    return c;
}

void writeConfig(const fs::path& file, const std::string& matte, const std::string& compositor,
                 const std::string& sections) {
    std::ofstream out(file);
    out << "matte:\n"
        << matte << "compositor:\n  person_plane_m: 12\n"
        << compositor << "render:\n  shading: unlit\n"
        << "camera:\n  calibration: camera.yaml\nscene:\n  objects:\n";
    for (const ObjectConfig& o : cgObjects()) {
        out << "    - {name: " << o.name << ", shape: " << o.shape << ", position: [" << o.position.x << ", "
            << o.position.y << ", " << o.position.z << "], color: [" << o.color.r << ", " << o.color.g << ", "
            << o.color.b << ", 1]";
        if (o.shape == "box")
            out << ", size: [" << o.size.x << ", " << o.size.y << ", " << o.size.z << "]";
        else
            out << ", radius: " << o.radius;
        out << "}\n";
    }
    out << sections;
}

GrabResult FramesGrabber::grab() {
    if (next_ >= frames_.size()) return {std::nullopt, {SourceStatus::Ended, "end of the synthetic video"}};
    Frame f{frames_[next_].clone()};
    f.timestamp = std::chrono::nanoseconds(static_cast<std::int64_t>(1e9 * static_cast<double>(next_) / kFps));
    f.sequence = next_++;
    return {f, {SourceStatus::Streaming, ""}};
}

}  // namespace arcomp::ar
