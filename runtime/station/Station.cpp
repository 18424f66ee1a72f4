#include "runtime/station/Station.hpp"

#include "graph/core/ElapsedTime.hpp"
#include "graph/core/JoinText.hpp"
#include "graph/core/SelectPass.hpp"
#include "runtime/composite/ShadowCatcher.hpp"
#include "runtime/config/CalibrationFile.hpp"
#include "runtime/render/Environment.hpp"
#include "runtime/render/ImpostorBaker.hpp"
#include "runtime/render/PointCloudLayer.hpp"
#include "runtime/station/SceneFile.hpp"

#include <spdlog/spdlog.h>

namespace arcomp {

namespace {

// The frame's GL stages, timed on the GPU (runtime/gl/GpuStageTimes.hpp).
enum GpuStage { kGpuBackdrop, kGpuShadow, kGpuRender, kGpuHoldout, kGpuPerson, kGpuStageCount };

// Milliseconds of each CPU stage, one lap after another.
class StageClock {
public:
    double lap() {
        const auto now = std::chrono::steady_clock::now();
        const double ms = std::chrono::duration<double, std::milli>(now - last_).count();
        last_ = now;
        return ms;
    }
    double total() const { return msSince(start_); }

private:
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now(), last_ = start_;
};

// Waits for the worker's job on the way out of a scope, exceptions included.
class WaitOnExit {
public:
    explicit WaitOnExit(WorkerThread& worker) : worker_(worker) {}
    WaitOnExit(const WaitOnExit&) = delete;
    WaitOnExit& operator=(const WaitOnExit&) = delete;
    ~WaitOnExit() { worker_.wait(); }

private:
    WorkerThread& worker_;
};

}  // namespace

void Station::preflight(const StationConfig& cfg) {
    if (cfg.budget.enabled) (void)readCalibration(cfg.budget.calibration);
    (void)makeGazeSource(cfg.gaze, View{});
    (void)makeMatte(cfg.compositing.matte);
    if (!cfg.render.environment.empty()) (void)loadEnvironment(cfg.render.environment);  // BadInput naming the file
    OutputStage::preflight(cfg.compositing.output);
}

Station::Station(const StationConfig& cfg, StationInput input)
    : cfg_(cfg), capture_(std::move(input)), matte_(cfg_.compositing.matte),
      personDepths_(cfg_.compositing.compositor.personDepthFromFeet ? cfg_.camera.calibrated : std::nullopt,
                    cfg_.compositing.compositor.personPlaneMetres, capture_.size()),
      people_(cfg_.camera.calibrated, capture_.size()), zones_(cfg_.zones), triggers_(cfg_.triggers),
      showControl_(cfg_.showControl),
      outputs_(cfg_.compositing.output, capture_.fps(), capture_.size(), FrameReadback::Mode::Auto,
               capture_.isReplay() ? WhenFull::Wait : WhenFull::Drop) {
    const std::filesystem::path cache = bakeCacheFolder(cfg_.compositing.compositor);
    lodBake_ = buildScene(cfg_, world_, warnings_, cache);
    warnings_.insert(warnings_.end(), showControl_.problems().begin(), showControl_.problems().end());
    if (!cfg_.compositing.output.events.empty()) {
        try {
            events_.emplace(cfg_.compositing.output.events);
        } catch (const std::exception& e) {
            warnings_.push_back(std::string(e.what()) + "; the station runs without its event log");
        }
    }
    world_.scene.update();
    // The CG camera is the video camera: its pose and field of view from the
    // config or its calibration file, its image size the video's.
    CameraConfig camera = cfg_.camera;
    camera.size = capture_.size();
    if (camera.calibrated && camera.calibrated->intrinsics.distorted()) {
        const CameraIntrinsics k = camera.calibrated->intrinsics.scaledTo(camera.size);
        const auto& d = k.distortion;
        capture_.undistortWith(LensUndistortion(cv::Matx33d(k.fx, 0, k.cx, 0, k.fy, k.cy, 0, 0, 1),
                                                cv::Vec<double, 5>(d[0], d[1], d[2], d[3], d[4]),
                                                {camera.size.x, camera.size.y}));
    }
    view_ = cfg_.camera.given
                ? cameraView(camera)
                : View::framing(world_.scene.bound().empty() ? Sphere{glm::vec3(0.0f), 1.0f} : world_.scene.bound(),
                                camera.fovyDegrees, camera.size);
    gaze_ = makeGazeSource(cfg_.gaze, view_);
    holdoutBake_ = bakeHoldouts(world_, view_, cfg_.compositing.compositor, cache, cfg_.file);
    bakeImpostors(world_.scene, world_.grouping, view_.eye);
    if (cfg_.budget.enabled) budget_.emplace(cfg_.budget);

    renderer_ = std::make_unique<Renderer>();
    if (!cfg_.render.environment.empty()) {
        // A station that cannot read its environment still runs, lit by the
        // built-in one: the operator sees the warning, visitors see a model.
        try {
            renderer_->setEnvironment(prefilterEnvironment(loadEnvironment(cfg_.render.environment)));
        } catch (const std::exception& e) {
            warnings_.push_back(std::string("render.environment: ") + e.what() +
                                "; lighting with the neutral environment");
        }
    }
    gpuTimes_ = std::make_unique<GpuStageTimes>(kGpuStageCount);
    if (world_.pointClouds.size()) cloudLayer_ = std::make_unique<PointCloudLayer>();
    compositor_ = std::make_unique<Compositor>(camera.size);
    // The floor is only known for a calibrated camera: shadows are on there unless the config says otherwise.
    if (cfg_.compositing.compositor.shadow.enabled.value_or(cfg_.camera.calibrated.has_value()))
        shadows_ = std::make_unique<ShadowCatcher>(camera.size);
}

Station::~Station() { finish(); }

void Station::captureAndMatte(CapturedFrame& f, const CapturedFrame& shown) {
    StageClock clock;
    f.ok = false;  // and so it stays when the capture throws
    // The frame before the shown one lets its image go before the decoder
    // asks for a new one, which can then take the same memory.
    f.image.release();
    if (!capture_.next()) return;
    f.ok = true;
    f.capturedAt = std::chrono::steady_clock::now();
    f.image = capture_.image();
    f.newFrame = capture_.newFrame();
    f.seconds = capture_.seconds();
    f.frameSeconds = capture_.frameSeconds();
    // A live frame that did not change keeps the shown frame's plate and
    // tiles: copied into this frame's own buffers, never shared, so that
    // neither frame writes what the other one reads.
    const bool same = !f.newFrame && shown.ok;
    if (cfg_.compositing.compositor.backdropVideo) {
        if (same && !shown.plate.empty())
            shown.plate.copyTo(f.plate);
        else
            Compositor::makePlate(f.image, f.plate);
    }
    f.captureMs = clock.lap();
    matte_.run(f.image, f.newFrame);
    f.person = matte_.person();
    if (same)
        f.tiles = shown.tiles;
    else
        Compositor::findTiles(f.person, f.tiles);
    f.matteMs = clock.lap();
}

bool Station::frame() {
    StageClock clock;
    // The first frame (and any after the input ended) is captured here;
    // every other was captured while the previous frame rendered. finish()
    // rethrows what the front threw (a damaged file), at the frame it
    // belongs to.
    const unsigned next = shownFront_ ^ 1U;
    if (front_.busy())
        front_.finish();
    else
        captureAndMatte(fronts_[next], shown());
    if (!fronts_[next].ok) return false;
    shownFront_ = next;
    const CapturedFrame& now = shown();
    // The front writes the other frame and the other person layer
    // (MatteStage), so this frame's stay as they are while it runs.
    front_.start([this] { captureAndMatte(fronts_[shownFront_ ^ 1U], shown()); });
    // Whatever a stage below throws, the front is done before frame() ends.
    const WaitOnExit join(front_);
    stats_.newVideoFrame = now.newFrame;
    stats_.captureMs = now.captureMs;
    stats_.matteMs = now.matteMs;
    clock.lap();
    personDepths_.run(now.person, now.newFrame);
    stats_.people = static_cast<std::size_t>(personDepths_.depths().people);
    stats_.trackMs = clock.lap();
    const PeopleFrame& visitors = zones_.update(
        people_.update(personDepths_.people(), personDepths_.scale(), stats_.frame, now.seconds, now.newFrame));
    if (now.newFrame) runTriggers(visitors);
    if (events_ && now.newFrame) {
        try {
            events_->write(visitors, &triggers_);
        } catch (const std::exception& e) {
            spdlog::error(joinText(e.what(), "; the event log stops here, the station goes on"));
            events_.reset();
        }
    }
    if (now.newFrame && !showControl_.empty()) {
        const auto sent = showControl_.publish(visitors);
        stats_.captureToPeopleSentMs = std::chrono::duration<double, std::milli>(sent - now.capturedAt).count();
    }
    stats_.peopleMs = clock.lap();

    const double seconds = now.seconds;
    moveObjects(world_, seconds);
    animateObjects(world_, now.frameSeconds);
    world_.scene.update();
    stats_.updateMs = clock.lap();

    const glm::vec3 gaze = gazeAt(seconds);
    select(world_, view_, {.shading = cfg_.render.shading, .gaze = gaze, .timeSeconds = seconds}, drawList_);
    stats_.selectMs = clock.lap();

    collectGpuTimes();
    if (budget_) {
        stats_.budget = budget_->plan(world_.scene, drawList_, view_, gaze, stats_);
        stats_.budgetMs = clock.lap();
    }

    const CompositorConfig& comp = cfg_.compositing.compositor;
    gpuTimes_->time(kGpuBackdrop, [&] {
        compositor_->beginWithPlate(now.plate,
                                    {.backdropVideo = comp.backdropVideo, .backdropColor = comp.backdropColor});
    });
    if (shadows_)
        gpuTimes_->time(kGpuShadow, [&] {
            shadows_->cast(world_.scene, drawList_, view_, comp.shadow, *renderer_, compositor_->output());
        });
    gpuTimes_->time(kGpuRender, [&] {
        renderer_->draw(world_.scene, drawList_, view_,
                        {.clearColor = std::nullopt,
                         .lightDirection = comp.shadow.light,
                         .environmentIntensity = cfg_.render.environmentIntensity});
    });
    stats_.cgTriangles = renderer_->trianglesDrawn();
    clock.lap();
    if (cloudLayer_) cloudLayer_->draw(world_.scene, world_.pointClouds, drawList_.pointClouds, view_);
    stats_.pointCloudMs = clock.lap();
    const PersonDepths& people = personDepths_.depths();
    gpuTimes_->time(kGpuHoldout, [&] {
        holdout_.cut(world_, drawList_, view_, people.farthest(), *renderer_, *compositor_, stats_);
    });
    gpuTimes_->time(kGpuPerson, [&] { compositor_->person(now.person, now.tiles, people, view_.projection); });
    gpuTimes_->endFrame();
    stats_.personTiles = compositor_->personTiles();
    ++stats_.frame;
    clock.lap();

    outputs_.write(compositor_->output(), now.person);
    stats_.outputMs = clock.lap();
    front_.wait();
    stats_.totalMs = clock.total();
    return true;
}

void Station::runTriggers(const PeopleFrame& visitors) {
    const TriggerFrame& fired = triggers_.update(visitors, world_);
    for (const std::string& problem : fired.problems) spdlog::warn(problem);
    for (const StationAction& a : fired.forStation) {
        switch (a.action->kind) {
        case ActionKind::Snapshot: outputs_.snapshot(a.action->folder); break;
        case ActionKind::Clip: outputs_.clip(a.action->folder, a.action->seconds); break;
        default: showControl_.send(*a.action); break;
        }
    }
}

std::string Station::cue(const Cue& cue) {
    if (cue.kind == Cue::Kind::Reload) return "a reload is the station runner's to do";
    if (cue.action.kind == ActionKind::Snapshot) {
        outputs_.snapshot(cfg_.showControl.cues.snapshotFolder);
        return {};
    }
    return triggers_.objects().perform(world_, cue.action, shown().seconds);
}

void Station::collectGpuTimes() {
    gpuTimes_->collect();  // the previous frame's GL stages, so the budget sees its CG draw
    stats_.renderMs = gpuTimes_->ms(kGpuRender);
    stats_.holdoutMs = gpuTimes_->ms(kGpuHoldout);
    stats_.compositeMs = gpuTimes_->ms(kGpuBackdrop) + gpuTimes_->ms(kGpuPerson);
    stats_.shadowMs = gpuTimes_->ms(kGpuShadow);
}

glm::vec3 Station::gazeAt(double seconds) {
    if (gaze_)
        if (const std::optional<GazeSample> g = gaze_->sample(seconds)) return g->direction;
    return glm::vec3(0.0f);  // the screen centre
}

Image Station::readHoldout() {
    if (!holdoutMask_) holdoutMask_ = std::make_unique<RenderTarget>(compositor_->size());
    holdoutMask_->bind();
    renderer_->draw(world_.scene, holdout_.drawn(), view_, {.clearColor = glm::vec4(0.0f)});
    return holdoutMask_->read();
}

void Station::setCamera(const glm::vec3& eye, const glm::vec3& target) {
    CameraConfig camera = cfg_.camera;
    camera.eye = eye;
    camera.target = target;
    camera.size = compositor_->size();
    view_ = cameraView(camera);
}

void Station::finish() { outputs_.finish(); }

StationInput Station::releaseInput() {
    finish();
    // The frame read ahead was never shown: the next station starts with it.
    bool readAhead = false;
    if (front_.busy()) {
        front_.finish();
        readAhead = fronts_[shownFront_ ^ 1U].ok;
    }
    return capture_.release(readAhead);
}

}  // namespace arcomp
