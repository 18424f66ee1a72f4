// arcomp-bench matte --sequence DIR [--out DIR]: how well and how fast each
// person matte cuts people out of a real sequence with ground truth, in the
// CDnet 2014 layout (tools/bench/scenes/CdnetSequence.hpp), against OpenCV's own
// background subtractors run in the same process on the same frames.
//  - Methods: every `matte.background.method` of the station with its
//    defaults (alpha > 127 is the person), and the peers with OpenCV's
//    defaults and no clean-up: MOG2, KNN and bgsegm's GSOC (their shadow
//    label 127 counts as background).
//  - Quality: precision, recall, F, IoU and percentage wrong over the scored
//    frames, counted the CDnet way (tools/bench/report/MatteScore.hpp).
//  - Speed: ms per frame on the sequence, and on --speed-clip (vtest.avi,
//    768x576, and the same scaled to 1920x1080): frames are decoded outside
//    the clock, the first --speed-skip frames (start-up) are not timed, and
//    768x576 is timed --speed-runs times (the median is reported, the runs
//    too, as the machine may be shared).
//  - --out: strip-<method>.png (frame | ground truth | alpha for a few
//    frames) and f_per_frame.png (F of each scored frame with people in it).
//
//   arcomp-bench matte --sequence ../shared/data/video/busStation --out build/bench-matte

#include "graph/core/ElapsedTime.hpp"
#include "tools/bench/report/BenchJson.hpp"
#include "tools/bench/report/LinePlot.hpp"
#include "tools/bench/report/MatteScore.hpp"
#include "tools/bench/report/Stats.hpp"
#include "tools/bench/scenes/CdnetSequence.hpp"
#include "tools/cli/Command.hpp"
#include "video/matte/MatteSpec.hpp"

#include <opencv2/bgsegm.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/video/background_segm.hpp>
#include <opencv2/videoio.hpp>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <functional>

namespace arcomp {
namespace {

using Clock = std::chrono::steady_clock;
namespace fs = std::filesystem;

struct Options {
    std::string sequence;
    std::string out;
    std::string speedClip = "/usr/share/doc/opencv-doc/examples/data/vtest.avi";
    double fps = 25.0;  // CDnet gives no rate; its sequences were filmed at 25-30 fps
    int speedFrames = 90;
    int speedSkip = 60;
    int speedRuns = 3;
};

// One way of turning a frame into a person mask (0 or 255), fresh for each
// run: `apply` is what is timed, `mask` reads its result out.
struct Running {
    std::function<void(const cv::Mat&)> apply;
    std::function<void(cv::Mat&)> mask;
};

struct Method {
    std::string name;
    bool peer = false;
    std::function<Running()> start;
};

std::vector<Method> methods(double fps) {
    std::vector<Method> all;
    const std::pair<const char*, BackgroundMethod> station[] = {{"consensus", BackgroundMethod::Consensus},
                                                                {"mog2", BackgroundMethod::Mog2},
                                                                {"knn", BackgroundMethod::Knn},
                                                                {"cnt", BackgroundMethod::Cnt},
                                                                {"clean_plate", BackgroundMethod::CleanPlate}};
    for (const auto& [name, method] : station)
        all.push_back({name, false, [method, fps] {
                           MatteSpec spec;
                           spec.kind = MatteKind::Background;
                           spec.background.method = method;
                           spec.background.consensus.fps = fps;
                           std::shared_ptr<PersonMatte> matte = makeMatte(spec);
                           auto person = std::make_shared<cv::Mat>();
                           return Running{[matte, person](const cv::Mat& frame) { matte->apply(frame, *person); },
                                          [person](cv::Mat& mask) {
                                              cv::extractChannel(*person, mask, 3);
                                              cv::threshold(mask, mask, 127, 255, cv::THRESH_BINARY);
                                          }};
                       }});
    const auto peer = [](std::function<cv::Ptr<cv::BackgroundSubtractor>()> make) {
        return [make] {
            cv::Ptr<cv::BackgroundSubtractor> model = make();
            auto raw = std::make_shared<cv::Mat>();
            return Running{[model, raw](const cv::Mat& frame) { model->apply(frame, *raw); },
                           [raw](cv::Mat& mask) {
                               cv::threshold(*raw, mask, 200, 255,
                                             cv::THRESH_BINARY);  // shadows (127) are not the person
                           }};
        };
    };
    all.push_back({"opencv_mog2", true, peer([] { return cv::createBackgroundSubtractorMOG2(); })});
    all.push_back({"opencv_knn", true, peer([] { return cv::createBackgroundSubtractorKNN(); })});
    all.push_back({"bgsegm_gsoc", true, peer([] { return cv::bgsegm::createBackgroundSubtractorGSOC(); })});
    return all;
}

const char* methodName(BackgroundMethod m) {
    switch (m) {
    case BackgroundMethod::Consensus: return "consensus";
    case BackgroundMethod::Mog2: return "mog2";
    case BackgroundMethod::Knn: return "knn";
    case BackgroundMethod::Cnt: return "cnt";
    case BackgroundMethod::CleanPlate: return "clean_plate";
    }
    return "?";
}

struct Result {
    MatteScore score;
    double msPerFrame = 0;
    std::vector<double> frameIndex, frameF;  // scored frames with people or false alarms
    std::vector<cv::Mat> stripMasks;         // at the strip frames
    std::vector<double> ms768Runs;
    double ms768 = 0, ms1080 = 0;
};

std::vector<int> stripFrames(const CdnetSequence& seq) {
    // Four frames spread over the scored range, away from its ends.
    std::vector<int> frames;
    const int span = seq.lastScored - seq.firstScored;
    for (int k = 1; k <= 4; ++k) frames.push_back(seq.firstScored + span * k / 5);
    return frames;
}

void scoreSequence(const CdnetSequence& seq, const Method& method, const std::vector<int>& strips, Result& r) {
    Running run = method.start();
    cv::Mat mask;
    double ms = 0;
    for (int i = 1; i <= seq.frameCount; ++i) {
        const cv::Mat frame = seq.frame(i);
        const auto t0 = Clock::now();
        run.apply(frame);
        ms += msSince(t0);
        if (!seq.scored(i)) continue;
        run.mask(mask);
        MatteScore one;
        one.add(mask, seq.labels(i), seq.roi);
        r.score += one;
        if (one.truePositives + one.falsePositives + one.falseNegatives > 0) {
            r.frameIndex.push_back(i);
            r.frameF.push_back(one.fMeasure());
        }
        if (std::find(strips.begin(), strips.end(), i) != strips.end()) r.stripMasks.push_back(mask.clone());
    }
    r.msPerFrame = ms / seq.frameCount;
}

// Mean ms per frame over `frames` frames of the clip at `size`, after `skip` untimed ones.
double timeAtSize(const Method& method, const std::string& clip, cv::Size size, int skip, int frames) {
    cv::VideoCapture cap(clip);
    Running run = method.start();
    cv::Mat decoded, frame;
    double ms = 0;
    int timed = 0;
    for (int i = 0; i < skip + frames; ++i) {
        if (!cap.read(decoded)) {
            cap.set(cv::CAP_PROP_POS_FRAMES, 0);
            if (!cap.read(decoded)) throw InputError(clip + ": cannot read frames for the speed runs");
        }
        if (decoded.size() != size)
            cv::resize(decoded, frame, size, 0, 0, cv::INTER_LINEAR);
        else
            frame = decoded;
        const auto t0 = Clock::now();
        run.apply(frame);
        if (i >= skip) ms += msSince(t0), ++timed;
    }
    return ms / std::max(1, timed);
}

void writeStrip(const fs::path& file, const CdnetSequence& seq, const std::vector<int>& frames, const Result& r) {
    std::vector<cv::Mat> rows;
    for (std::size_t k = 0; k < frames.size() && k < r.stripMasks.size(); ++k) {
        cv::Mat labels, matte, row;
        cv::cvtColor(seq.labels(frames[k]), labels, cv::COLOR_GRAY2BGR);
        cv::cvtColor(r.stripMasks[k], matte, cv::COLOR_GRAY2BGR);
        cv::hconcat(std::vector<cv::Mat>{seq.frame(frames[k]), labels, matte}, row);
        cv::putText(row, "frame " + std::to_string(frames[k]), {6, 18}, cv::FONT_HERSHEY_SIMPLEX, 0.5, {0, 0, 255}, 1,
                    cv::LINE_AA);
        rows.push_back(row);
    }
    cv::Mat strip;
    cv::vconcat(rows, strip);
    if (!cv::imwrite(file.string(), strip)) throw std::runtime_error(file.string() + ": cannot write");
}

int matteBench(const Options& o) {
    if (o.speedFrames < 1 || o.speedSkip < 0 || o.speedRuns < 1)
        throw InputError("--speed-frames and --speed-runs must be >= 1");
    const CdnetSequence seq = openCdnetSequence(o.sequence);  // VideoError: exit 2
    const bool haveClip = fs::exists(o.speedClip);
    if (!haveClip)
        std::fprintf(stderr, "bench matte: %s absent; no timing at 768x576 and 1920x1080\n", o.speedClip.c_str());
    const std::vector<int> strips = stripFrames(seq);
    const std::vector<Method> all = methods(o.fps);
    std::vector<Result> results(all.size());
    for (std::size_t m = 0; m < all.size(); ++m) {
        std::fprintf(stderr, "bench matte: %s on %s (%d frames)\n", all[m].name.c_str(), seq.dir.c_str(),
                     seq.frameCount);
        scoreSequence(seq, all[m], strips, results[m]);
        if (!haveClip) continue;
        // Runs interleaved with the other methods would spread a busy spell of
        // the machine over all of them; here each method's runs are back to back,
        // so the spread of its runs shows such a spell.
        for (int run = 0; run < o.speedRuns; ++run)
            results[m].ms768Runs.push_back(timeAtSize(all[m], o.speedClip, {768, 576}, o.speedSkip, o.speedFrames));
        results[m].ms768 = median(results[m].ms768Runs);
        results[m].ms1080 = timeAtSize(all[m], o.speedClip, {1920, 1080}, o.speedSkip, std::max(1, o.speedFrames / 3));
    }

    if (!o.out.empty()) {
        fs::create_directories(o.out);
        LinePlot plot("F per scored frame: " + seq.dir.filename().string(), "frame", "F");
        for (std::size_t m = 0; m < all.size(); ++m) {
            writeStrip(fs::path(o.out) / ("strip-" + all[m].name + ".png"), seq, strips, results[m]);
            if (all[m].name == "consensus" || all[m].name == "mog2" || all[m].peer)
                plot.addSeries(all[m].name, results[m].frameIndex, results[m].frameF);
        }
        plot.addLevel("target 0.86", 0.86);
        plot.writePng(fs::path(o.out) / "f_per_frame.png");
        std::fprintf(stderr, "bench matte: wrote strip-<method>.png and f_per_frame.png to %s\n", o.out.c_str());
    }

    const std::string defaultName = methodName(BackgroundSpec{}.method);
    double bestPeerF = 0, defaultF = 0, default768 = 0;
    for (std::size_t m = 0; m < all.size(); ++m) {
        if (all[m].peer) bestPeerF = std::max(bestPeerF, results[m].score.fMeasure());
        if (all[m].name == defaultName) defaultF = results[m].score.fMeasure(), default768 = results[m].ms768;
    }
    // Scores to four places and milliseconds to three, as this bench has always reported them.
    BenchJson j;
    j.field("bench", "matte").field("sequence", seq.dir.filename().string()).field("frames", seq.frameCount);
    j.beginArray("scored").value(seq.firstScored).value(seq.lastScored).end();
    j.field("fps", o.fps).field("default", defaultName);
    j.beginArray("methods");
    for (std::size_t m = 0; m < all.size(); ++m) {
        const Result& r = results[m];
        j.beginObject()
            .field("name", all[m].name)
            .field("peer", all[m].peer)
            .field("precision", Fixed{r.score.precision(), 4})
            .field("recall", Fixed{r.score.recall(), 4})
            .field("f_measure", Fixed{r.score.fMeasure(), 4})
            .field("iou", Fixed{r.score.iou(), 4})
            .field("pwc", Fixed{r.score.percentWrong(), 4})
            .field("ms_per_frame", Fixed{r.msPerFrame, 3});
        if (haveClip) {
            j.field("ms_per_frame_768x576", Fixed{r.ms768, 3});
            j.beginArray("ms_768x576_runs");
            for (const double ms : r.ms768Runs) j.value(Fixed{ms, 3});
            j.end().field("ms_per_frame_1920x1080", Fixed{r.ms1080, 3});
        } else {
            j.null("ms_per_frame_768x576").null("ms_per_frame_1920x1080");
        }
        j.end();
    }
    j.end();
    j.beginObject("targets")
        .field("f_measure_min", 0.86)
        .field("f_met", defaultF >= 0.86)
        .field("ahead_of_peers", defaultF > bestPeerF)
        .field("ms_768x576_max", 8)
        .field("speed_met", haveClip && default768 <= 8.0)
        .end();
    std::printf("%s\n", j.str().c_str());
    return kExitOk;
}

const bool registered = registerCommand(
    {"matte", "Person mattes on a CDnet sequence: P, R, F, IoU and ms/frame against OpenCV's subtractors",
     [](CommandLine& line) {
         auto o = std::make_shared<Options>();
         line.option("--sequence", o->sequence, "CDnet sequence folder (input/, groundtruth/, temporalROI.txt)")
             .required();
         line.option("--out", o->out, "folder for the strips and the per-frame F plot");
         line.option("--fps", o->fps, "the sequence's frame rate, for the settings given in seconds").showDefault();
         line.option("--speed-clip", o->speedClip, "clip timed at 768x576 and 1920x1080").showDefault();
         line.option("--speed-frames", o->speedFrames, "timed frames per run").showDefault();
         line.option("--speed-skip", o->speedSkip, "untimed start-up frames before each run").showDefault();
         line.option("--speed-runs", o->speedRuns, "runs at 768x576 (median reported)").showDefault();
         return [o] { return matteBench(*o); };
     }});

}  // namespace
}  // namespace arcomp
