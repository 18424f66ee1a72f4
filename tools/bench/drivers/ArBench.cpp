// arcomp-bench ar [--frames 300] [--out DIR]: registered AR against a
// ground truth the bench makes itself.
//  - The installation: tools/bench/drivers/ArInstallation.hpp.
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
#include "runtime/gl/GlContext.hpp"
#include "runtime/station/ReplayInput.hpp"
#include "runtime/station/SceneFile.hpp"
#include "runtime/station/Station.hpp"
#include "tools/bench/drivers/ArInstallation.hpp"
#include "tools/bench/report/BenchJson.hpp"
#include "tools/bench/report/Stats.hpp"
#include "tools/cli/Command.hpp"
#include "video/matte/MaskFolderMatte.hpp"

#include <opencv2/imgcodecs.hpp>

#include <cstdio>
#include <fstream>
#include <iostream>

namespace arcomp {
namespace {

namespace fs = std::filesystem;
using namespace ar;

struct Options {
    int frames = 300;
    std::string out = "build/bench-ar";
};

// Where a picture shows the CG: blue well above red.
cv::Mat showsCg(const cv::Mat& bgr) {
    std::vector<cv::Mat> ch;
    cv::split(bgr, ch);
    cv::Mat redPlus;
    cv::add(ch[2], cv::Scalar(60), redPlus);
    return (ch[0] > 120) & (ch[0] > redPlus);
}

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

int run(const Options& o) {
    const fs::path dir = o.out;
    fs::create_directories(dir / "masks");
    auto context = HeadlessContext::create(GlRequest::Auto);
    const SyntheticCamera lens(kLens);
    const Calibration calibration = calibrate(lens, dir);

    // The installation through the true lens, and the truth through the true pinhole.
    const CalibratedCamera truth = trueCamera();
    const View view = truth.view({kLens.size.width, kLens.size.height}, 0.1f, 100.0f);
    const cv::Mat plate = floorPlate(lens);
    const cv::Mat truthPlate = floorPlate(SyntheticCamera(
        {.size = kLens.size, .fx = kLens.fx, .fy = kLens.fy, .cx = kLens.cx, .cy = kLens.cy, .distortion = {}}));
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
