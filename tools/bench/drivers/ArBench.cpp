// arcomp-bench ar [--frames 300] [--out DIR]: registered AR against a
// ground truth the bench makes itself.
//  - The installation: a camera 3.2 m up, tilted 17 degrees, with a lens
//    that bends (k1 -0.12); a textured floor; three walkers (boxes 1.7 m
//    tall) on known paths: one behind a CG box, one in front of it, one
//    walking towards the camera past it; a CG sphere further back.
//  - The calibration: `arcomp calibrate intrinsics` on 14 photographs of a
//    chessboard through the lens, then `arcomp calibrate floor --marker` on
//    a photograph of an ArUco marker on the floor. Their errors against the
//    true camera are reported.
//  - The ground truth: the walkers and the CG drawn together in 3D through
//    the true camera; where a walker's pixel shows the CG is the layering.
//  - Three station runs on the same video, with that calibration: per-person
//    depth with the ground-truth masks (`matte: masks`), per-person depth
//    with the station's own matte (a clean plate), and everyone on one
//    plane (`person_depth: plane`, the old behaviour) with the masks.
//    Wrong layering: walker pixels where the station shows CG and the
//    truth does not, or the other way round, as a share of walker pixels.
//  - Cost: the per-frame median of the per-person run (tracking and contact
//    shadows on) less that of the plane run (both off), same masks. The
//    three stations run side by side, a frame of each in turn.
// --out gets strip.png (ground truth | single plane | per-person depth, a
// few frames), the calibration inputs and the station configs.
//
//   arcomp-bench ar --out build/bench-ar

#include "graph/core/SelectPass.hpp"
#include "runtime/config/CameraFile.hpp"
#include "runtime/gl/GlContext.hpp"
#include "runtime/station/ReplayInput.hpp"
#include "runtime/station/SceneFile.hpp"
#include "runtime/station/Station.hpp"
#include "tools/bench/probes/ShellCommand.hpp"
#include "tools/bench/report/BenchJson.hpp"
#include "tools/bench/report/Stats.hpp"
#include "tools/bench/scenes/SyntheticCamera.hpp"
#include "tools/cli/Command.hpp"
#include "video/matte/MaskFolderMatte.hpp"

#include <opencv2/imgcodecs.hpp>

#include <cstdio>
#include <fstream>
#include <iostream>

namespace arcomp {
namespace {

namespace fs = std::filesystem;

struct Options {
    int frames = 300;
    std::string out = "build/bench-ar";
};

constexpr double kFps = 25.0;
const SyntheticLens kLens{.size = {768, 576}, .fx = 690, .fy = 686, .cx = 388, .cy = 284, .distortion = {-0.12, 0.02}};
constexpr double kCameraHeight = 3.2, kCameraZ = 9.5, kTiltDegrees = 17.0;

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

ObjectConfig box(const std::string& name, glm::vec3 size, glm::vec3 position, glm::vec4 colour) {
    ObjectConfig o;
    o.name = name;
    o.shape = "box";
    o.size = size;
    o.position = position;
    o.color = colour;
    return o;
}

// The CG: blue, so that a pixel showing it is told from a walker (red).
std::vector<ObjectConfig> cgObjects() {
    ObjectConfig sphere;
    sphere.name = "sphere";
    sphere.shape = "sphere";
    sphere.radius = 0.5f;
    sphere.position = {-2.4f, 0.5f, -4.5f};
    sphere.color = {0.1f, 0.3f, 0.95f, 1.0f};
    return {box("box", {1.2f, 1.4f, 0.6f}, {0.0f, 0.7f, 0.0f}, {0.1f, 0.15f, 0.9f, 1.0f}), sphere};
}

// Walkers on known paths, back and forth (graph/core/ObjectMotion.hpp).
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

cv::Mat bgraOf(const Image& img) {
    cv::Mat rgba(img.height, img.width, CV_8UC4, const_cast<std::uint8_t*>(img.rgba.data())), bgra;
    cv::cvtColor(rgba, bgra, cv::COLOR_RGBA2BGRA);
    return bgra;
}

// Premultiplied BGRA over BGR.
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

// Where a picture shows the CG: blue well above red.
cv::Mat showsCg(const cv::Mat& bgr) {
    std::vector<cv::Mat> ch;
    cv::split(bgr, ch);
    cv::Mat redPlus;
    cv::add(ch[2], cv::Scalar(60), redPlus);
    return (ch[0] > 120) & (ch[0] > redPlus);
}

// Draws a list of objects at video time `seconds` through `view`.
class ObjectPainter {
public:
    ObjectPainter(std::vector<ObjectConfig> objects, const View& view) : view_(view), target_(view.viewport) {
        StationConfig cfg;
        cfg.file = "bench-ar";
        cfg.objects = std::move(objects);
        std::vector<std::string> warnings;
        buildScene(cfg, world_, warnings);
    }
    // Premultiplied BGRA, rows top first.
    cv::Mat paint(double seconds, Shading shading) {
        moveObjects(world_, seconds);
        world_.scene.update();
        DrawList list;
        select(world_, view_, {.shading = shading, .lod = false, .grouping = false}, list);
        target_.bind();
        renderer_.draw(world_.scene, list, view_, {.clearColor = glm::vec4(0.0f)});
        return bgraOf(target_.read());
    }

private:
    World world_;
    View view_;
    RenderTarget target_;
    Renderer renderer_;
};

struct Calibration {
    CalibratedCamera camera;
    double focalErrPct = 0, principalErrPx = 0, rmsPx = 0, heightErrPct = 0, tiltErrDeg = 0;
};

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

// The video the station sees, frame after frame, from memory.
class FramesGrabber : public FrameGrabber {
public:
    explicit FramesGrabber(const std::vector<cv::Mat>& frames) : frames_(frames) {}
    GrabResult grab() override {
        if (next_ >= frames_.size()) return {std::nullopt, {SourceStatus::Ended, "end of the synthetic video"}};
        Frame f{frames_[next_].clone()};
        f.timestamp = std::chrono::nanoseconds(static_cast<std::int64_t>(1e9 * static_cast<double>(next_) / kFps));
        f.sequence = next_++;
        return {f, {SourceStatus::Streaming, ""}};
    }
    std::string name() const override { return "synthetic installation"; }

private:
    const std::vector<cv::Mat>& frames_;
    std::size_t next_ = 0;
};

struct StationRun {
    double wrongPct = 0;
    double medianMs = 0;
    FrameStats stages;           // each stage's median
    std::vector<cv::Mat> shown;  // the frames kept for the strip
    cv::Mat worst;               // the frame with the most wrong pixels, those in magenta
    int worstFrame = -1;
};

// The stations run side by side, a frame of each in turn (the order
// rotating), so that their frame times share the machine's moment.
std::vector<StationRun> runStations(const std::vector<fs::path>& configs, const std::vector<cv::Mat>& video,
                                    const std::vector<cv::Mat>& walkerMasks, const std::vector<cv::Mat>& truthCg,
                                    const std::vector<int>& stripFrames) {
    struct Running {
        std::unique_ptr<Station> station;
        StationRun result;
        std::vector<double> totals, track, shadow, holdout, composite, matte, render;
        std::size_t wrong = 0, walkerPixels = 0;
        int worstCount = 0;
    };
    std::vector<Running> runs(configs.size());
    for (std::size_t k = 0; k < configs.size(); ++k)
        runs[k].station = std::make_unique<Station>(
            loadStationConfig(configs[k]), StationInput::fromReplay(std::make_unique<FramesGrabber>(video), kFps));
    for (std::size_t i = 0; i < video.size(); ++i)
        for (std::size_t turn = 0; turn < runs.size(); ++turn) {
            Running& r = runs[(i + turn) % runs.size()];
            if (!r.station->frame()) throw std::runtime_error("a station stopped at frame " + std::to_string(i));
            const FrameStats& s = r.station->stats();
            r.totals.push_back(s.totalMs);
            r.track.push_back(s.trackMs);
            r.shadow.push_back(s.shadowMs);
            r.holdout.push_back(s.holdoutMs);
            r.composite.push_back(s.compositeMs);
            r.matte.push_back(s.matteMs);
            r.render.push_back(s.renderMs);
            cv::Mat bgr;
            cv::cvtColor(bgraOf(r.station->compositedFrame().read()), bgr, cv::COLOR_BGRA2BGR);
            cv::Mat disagree;
            cv::bitwise_xor(showsCg(bgr), truthCg[i], disagree);
            const cv::Mat wrongHere = disagree & walkerMasks[i];
            const int count = cv::countNonZero(wrongHere);
            r.wrong += static_cast<std::size_t>(count);
            r.walkerPixels += static_cast<std::size_t>(cv::countNonZero(walkerMasks[i]));
            if (count > r.worstCount) {
                r.worstCount = count;
                r.result.worstFrame = static_cast<int>(i);
                r.result.worst = bgr.clone();
                r.result.worst.setTo(cv::Scalar(255, 0, 255), wrongHere);
            }
            if (std::find(stripFrames.begin(), stripFrames.end(), static_cast<int>(i)) != stripFrames.end())
                r.result.shown.push_back(bgr);
        }
    std::vector<StationRun> results;
    for (Running& r : runs) {
        StationRun& out = r.result;
        out.wrongPct =
            r.walkerPixels ? 100.0 * static_cast<double>(r.wrong) / static_cast<double>(r.walkerPixels) : 0.0;
        out.medianMs = median(r.totals);
        out.stages.trackMs = median(r.track);
        out.stages.shadowMs = median(r.shadow);
        out.stages.holdoutMs = median(r.holdout);
        out.stages.compositeMs = median(r.composite);
        out.stages.matteMs = median(r.matte);
        out.stages.renderMs = median(r.render);
        results.push_back(std::move(out));
    }
    return results;
}

void writeConfig(const fs::path& file, const std::string& matte, const std::string& compositor) {
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
}

int run(const Options& o) {
    const fs::path dir = o.out;
    fs::create_directories(dir / "masks");
    auto context = HeadlessContext::create(GlRequest::Auto);
    const SyntheticCamera lens(kLens);
    const Calibration calibration = calibrate(lens, dir);

    // The installation through the true lens, and the truth through the true pinhole.
    const CalibratedCamera truth = trueCamera();
    const View view = truth.view({kLens.size.width, kLens.size.height}, 0.1f, 100.0f);
    const double texelsPerMetre = 40.0;
    const cv::Mat floor = floorTexture(texelsPerMetre);
    const cv::Matx33d floorPose = floorToCamera(0.0, kCameraHeight, kCameraZ, kTiltDegrees);
    const cv::Mat plate = lens.photograph(floor, 1.0 / texelsPerMetre, {-15.0, -15.0}, floorPose);
    const SyntheticCamera pinhole(
        {.size = kLens.size, .fx = kLens.fx, .fy = kLens.fy, .cx = kLens.cx, .cy = kLens.cy, .distortion = {}});
    const cv::Mat truthPlate = pinhole.photograph(floor, 1.0 / texelsPerMetre, {-15.0, -15.0}, floorPose);
    cv::imwrite((dir / "plate.png").string(), plate);

    std::vector<ObjectConfig> everything = walkers();
    for (const ObjectConfig& c : cgObjects()) everything.push_back(c);
    ObjectPainter people(walkers(), view), scene(everything, view);
    std::vector<cv::Mat> video, masks, truthCg, truthShown;
    const std::vector<int> stripFrames{o.frames / 6, o.frames / 3, o.frames / 2, 2 * o.frames / 3, 5 * o.frames / 6};
    const cv::Mat erode = cv::getStructuringElement(cv::MORPH_RECT, {3, 3});
    for (int i = 0; i < o.frames; ++i) {
        const double t = i / kFps;
        const cv::Mat walkersLayer = people.paint(t, Shading::Phong);
        video.push_back(over(lens.throughLens(walkersLayer), plate));
        cv::Mat alpha, mask;
        cv::extractChannel(walkersLayer, alpha, 3);
        cv::imwrite(MaskFolderMatte::maskFile(dir / "masks", static_cast<std::uint64_t>(i)).string(), alpha);
        // Scored away from the walkers' outlines, where a matte's edge may fall either way.
        cv::erode(alpha > 0, mask, erode);
        masks.push_back(mask);
        const cv::Mat whole = over(scene.paint(t, Shading::Unlit), truthPlate);
        truthCg.push_back(showsCg(whole));
        if (std::find(stripFrames.begin(), stripFrames.end(), i) != stripFrames.end()) truthShown.push_back(whole);
    }

    const std::string gtMasks = "  kind: masks\n  masks: {folder: masks}\n";
    const std::string ownMatte = "  kind: background\n  background: {method: clean_plate, clean_plate: plate.png}\n";
    writeConfig(dir / "feet-masks.yaml", gtMasks, "");
    writeConfig(dir / "feet-own-matte.yaml", ownMatte, "");
    writeConfig(dir / "plane-masks.yaml", gtMasks, "  person_depth: plane\n  shadow: {enabled: false}\n");
    const std::vector<StationRun> runs =
        runStations({dir / "feet-masks.yaml", dir / "plane-masks.yaml", dir / "feet-own-matte.yaml"}, video, masks,
                    truthCg, stripFrames);
    const StationRun &feet = runs[0], &plane = runs[1], &own = runs[2];

    // The strip: a row a frame, ground truth | single plane | per-person depth, at half size.
    std::vector<cv::Mat> rows;
    for (std::size_t i = 0; i < truthShown.size(); ++i) {
        cv::Mat row;
        cv::hconcat(std::vector<cv::Mat>{truthShown[i], plane.shown[i], feet.shown[i]}, row);
        cv::resize(row, row, {}, 0.5, 0.5, cv::INTER_AREA);
        rows.push_back(row);
    }
    cv::Mat strip;
    cv::vconcat(rows, strip);
    cv::imwrite((dir / "strip.png").string(), strip);
    for (const auto& [name, r] : {std::pair{"worst-per-person.png", &feet}, std::pair{"worst-own-matte.png", &own},
                                  std::pair{"worst-single-plane.png", &plane}})
        if (r->worstFrame >= 0) cv::imwrite((dir / name).string(), r->worst);

    BenchJson json;
    json.field("bench", "ar").field("frames", o.frames);
    json.beginArray("size").value(kLens.size.width).value(kLens.size.height).end();
    json.field("wrong_layering_pct", Fixed{feet.wrongPct, 3})
        .field("wrong_layering_pct_own_matte", Fixed{own.wrongPct, 3})
        .field("wrong_layering_pct_single_plane", Fixed{plane.wrongPct, 3});
    json.beginObject("calibration")
        .field("focal_err_pct", Fixed{calibration.focalErrPct, 3})
        .field("principal_err_px", Fixed{calibration.principalErrPx, 2})
        .field("rms_px", Fixed{calibration.rmsPx, 3})
        .field("height_err_pct", Fixed{calibration.heightErrPct, 3})
        .field("tilt_err_deg", Fixed{calibration.tiltErrDeg, 3})
        .end();
    json.field("frame_ms_median_per_person", Fixed{feet.medianMs, 2})
        .field("frame_ms_median_single_plane", Fixed{plane.medianMs, 2})
        .field("added_ms_768x576", Fixed{feet.medianMs - plane.medianMs, 2});
    for (const auto& [name, r] : {std::pair{"stage_ms_per_person", &feet}, std::pair{"stage_ms_single_plane", &plane}})
        json.beginObject(name)
            .field("matte", Fixed{r->stages.matteMs, 2})
            .field("track", Fixed{r->stages.trackMs, 2})
            .field("shadow", Fixed{r->stages.shadowMs, 2})
            .field("render", Fixed{r->stages.renderMs, 2})
            .field("holdout", Fixed{r->stages.holdoutMs, 2})
            .field("composite", Fixed{r->stages.compositeMs, 2})
            .end();
    json.beginObject("targets")
        .field("layering", feet.wrongPct <= 0.5 && own.wrongPct <= 0.5)
        .field("single_plane_fails", plane.wrongPct > 0.5)
        .field("calibration", calibration.focalErrPct <= 1.0 && calibration.principalErrPx <= 2.0 &&
                                  calibration.rmsPx < 0.5 && calibration.heightErrPct <= 2.0 &&
                                  calibration.tiltErrDeg <= 0.5)
        .field("cost", feet.medianMs - plane.medianMs <= 2.0)
        .end();
    json.field("out", dir.string());
    std::cout << json.str() << std::endl;
    return kExitOk;
}

const bool registered = registerCommand(
    {"ar", "Registered AR against a synthetic ground truth: layering per person vs one plane, calibration error, cost",
     [](CommandLine& line) {
         auto o = std::make_shared<Options>();
         line.option("--frames", o->frames, "frames of the installation (the walkers reach the box after about 100)")
             .range(12, 100000)
             .showDefault();
         line.option("--out", o->out, "folder for the strip, the calibration inputs and configs").showDefault();
         return [o] { return run(*o); };
     }});

}  // namespace
}  // namespace arcomp
