// arcomp capture-plate <config> --out plate.png [--frames N] [--settle N]:
// records the empty place for `matte.background.clean_plate` from the
// station's own video source, the mean of N frames (sensor noise averages
// out). The first --settle frames are dropped while auto-exposure settles.
// The place must be empty while it runs: a person in view becomes part of
// the plate.

#include "runtime/config/StationConfig.hpp"
#include "tools/cli/Command.hpp"
#include "video/sources/OpenSource.hpp"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <thread>

namespace arcomp {
namespace {

struct Options {
    std::string config;
    std::string out;
    int frames = 30;
    int settle = 15;
    double timeoutSeconds = 10.0;
};

int capturePlate(const Options& o) {
    if (o.frames < 1 || o.settle < 0) throw InputError("--frames must be >= 1 and --settle >= 0");
    const StationConfig cfg = loadStationConfig(o.config);  // ConfigError: exit 2
    if (!cfg.compositing.video)
        throw InputError(o.config + ": no `video` section; capture-plate records from the station's video source");
    SourceSpec spec = *cfg.compositing.video;
    spec.fallback = {};  // a plate of the fallback picture would be no plate at all
    spec.paced = false;  // files: as fast as they decode
    spec.loop = false;
    std::unique_ptr<FrameSource> source = openSource(spec);

    cv::Mat sum;
    int seen = 0, summed = 0;
    using Clock = std::chrono::steady_clock;
    auto lastFrame = Clock::now();
    while (summed < o.frames) {
        if (std::optional<Frame> f = source->newest()) {
            lastFrame = Clock::now();
            if (seen++ < o.settle) continue;
            if (sum.empty()) sum = cv::Mat::zeros(f->image.size(), CV_32FC3);
            if (f->image.size() != sum.size())
                throw InputError(source->name() + ": the frame size changed while capturing");
            cv::accumulate(f->image, sum);
            ++summed;
            continue;
        }
        const SourceState state = source->state();
        const double waited = std::chrono::duration<double>(Clock::now() - lastFrame).count();
        if (isLost(state.status) || waited > o.timeoutSeconds) {
            source->close();
            throw InputError(source->name() + ": got " + std::to_string(summed) + " of " + std::to_string(o.frames) +
                             " frames after " + std::to_string(o.settle) + " to settle (" +
                             std::string(sourceStatusName(state.status)) +
                             (state.reason.empty() ? "" : ": " + state.reason) + ")");
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    source->close();
    cv::Mat plate;
    sum.convertTo(plate, CV_8UC3, 1.0 / summed);
    const std::filesystem::path out(o.out);
    if (out.has_parent_path()) std::filesystem::create_directories(out.parent_path());
    if (!cv::imwrite(o.out, plate)) throw InputError(o.out + ": cannot write the plate (expected a .png or .jpg path)");
    std::printf("plate: %s (%dx%d, mean of %d frames from %s)\n", o.out.c_str(), plate.cols, plate.rows, summed,
                source->name().c_str());
    return kExitOk;
}

const bool registered = registerCommand(
    {"capture-plate", "Record the empty place from the config's video source, for matte.background.clean_plate",
     [](CommandLine& line) {
         auto o = std::make_shared<Options>();
         line.option("config", o->config, "Station config (its `video` section is the source)").required();
         line.option("--out", o->out, "The plate image to write, e.g. plate.png").required();
         line.option("--frames", o->frames, "Frames averaged").showDefault();
         line.option("--settle", o->settle, "Frames dropped first, while exposure settles").showDefault();
         return [o] { return capturePlate(*o); };
     }});

}  // namespace
}  // namespace arcomp
