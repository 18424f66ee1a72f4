#include "runtime/Station.hpp"

#include "graph/core/SelectPass.hpp"
#include "graph/io/SilhouetteFile.hpp"
#include "graph/silhouette/SilhouetteMesh.hpp"
#include "runtime/CalibrationFile.hpp"
#include "runtime/ImageFile.hpp"
#include "runtime/ImpostorBaker.hpp"
#include "runtime/PointCloudLayer.hpp"
#include "runtime/SceneFile.hpp"
#include "video/MatteSpec.hpp"
#include "video/VideoError.hpp"

#include <spdlog/spdlog.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <cctype>
#include <chrono>
#include <cstdlib>
#include <map>
#include <set>
#include <cstdio>
#include <thread>

namespace arcomp {

using namespace gl;

namespace {

using Clock = std::chrono::steady_clock;

// The frame's GL stages, timed on the GPU (runtime/GpuStageTimes.hpp).
enum GpuStage { kGpuBackdrop, kGpuRender, kGpuHoldout, kGpuPerson, kGpuStageCount };

double msSince(Clock::time_point& t) {
    const Clock::time_point now = Clock::now();
    const double ms = std::chrono::duration<double, std::milli>(now - t).count();
    t = now;
    return ms;
}

// Where baked silhouettes wait for the next start: the config's folder,
// systemd's CacheDirectory for a service, else the user's cache folder;
// empty: nowhere (bake at every start).
std::filesystem::path holdoutCacheFolder(const CompositorConfig& c) {
    if (c.holdoutCache == "none") return {};
    if (!c.holdoutCache.empty()) return c.holdoutCache;
    if (const char* d = std::getenv("CACHE_DIRECTORY"); d && *d) return std::string(d).substr(0, std::string(d).find(':'));
    if (const char* d = std::getenv("XDG_CACHE_HOME"); d && *d) return std::filesystem::path(d) / "arcomp";
    if (const char* d = std::getenv("HOME"); d && *d) return std::filesystem::path(d) / ".cache" / "arcomp";
    return {};
}

// A file name for one mesh node's holdout: the config, the node's name and
// id, in characters any file system takes. The file itself says which mesh
// and region it was baked for; a stale one is baked again.
std::string holdoutFileName(const std::filesystem::path& config, const std::string& node, NodeId id) {
    std::string name = config.stem().string() + "-" + node;
    for (char& ch : name)
        if (!std::isalnum(static_cast<unsigned char>(ch)) && ch != '-' && ch != '_') ch = '_';
    return name + "-" + std::to_string(id) + ".sil";
}

std::string numbered(const char* stem, std::uint64_t index) {
    char name[64];
    std::snprintf(name, sizeof name, "%s-%06llu.png", stem, static_cast<unsigned long long>(index));
    return name;
}

} // namespace

StationInput StationInput::fromReplay(std::unique_ptr<FrameGrabber> g, double fps) {
    StationInput in;
    in.replay = std::move(g);
    in.fps = fps;
    return in;
}

StationInput StationInput::fromLive(std::unique_ptr<FrameSource> s, double fps) {
    StationInput in;
    in.live = std::move(s);
    in.fps = fps;
    return in;
}

void Station::preflight(const StationConfig& cfg) {
    if (cfg.budget.enabled) (void)readCalibration(cfg.budget.calibration);
    (void)makeGazeSource(cfg.gaze, View{});
    (void)makeMatte(cfg.compositing.matte);
}

Station::Station(const StationConfig& cfg, StationInput input) : cfg_(cfg), input_(std::move(input)) {
    matte_ = makeMatte(cfg_.compositing.matte);
    firstPending_ = grabNext();
    if (!firstPending_) throw VideoError(input_.replay ? input_.replay->name() : input_.live->name(), "first frame",
                                     "no frame to start from");
    const glm::ivec2 size(frame_.cols, frame_.rows);

    buildScene(cfg_, scene_, warnings_, &grouping_, &lods_, &motions_, &pointClouds_);
    scene_.update();
    // The CG camera is the video camera: its pose and field of view from the
    // config, its image size the video's.
    CameraConfig camera = cfg_.camera;
    camera.size = size;
    if (!cfg_.camera.given) {
        view_ = View::framing(scene_.bound().empty() ? Sphere{glm::vec3(0.0f), 1.0f} : scene_.bound(),
                              camera.fovyDegrees, size);
    } else {
        view_ = cameraView(camera);
    }
    gaze_ = makeGazeSource(cfg_.gaze, view_);
    buildHoldouts();
    bakeImpostors(scene_, grouping_, view_.eye);

    if (cfg_.budget.enabled) {
        budget_.emplace(readCalibration(cfg_.budget.calibration), toBudgetSettings(cfg_.budget));
        budget_->model().enableRefit(cfg_.budget.refit);
    }

    renderer_ = std::make_unique<Renderer>();
    gpuTimes_ = std::make_unique<GpuStageTimes>(kGpuStageCount);
    if (pointClouds_.size()) cloudLayer_ = std::make_unique<PointCloudLayer>();
    compositor_ = std::make_unique<Compositor>(size);

    const OutputConfig& out = cfg_.compositing.output;
    if (!out.videoFile.empty())
        video_ = std::make_unique<VideoFileWriter>(out.videoFile.string(), out.videoFourcc, input_.fps,
                                                   cv::Size(size.x, size.y));
}

Station::~Station() { finish(); }

void Station::buildHoldouts() {
    // Every CG mesh, each LOD level included, gets a holdout: its silhouette
    // mesh baked for the box of eyes around the camera (in the mesh's own
    // space), drawn unlit into the mask with the CG node's own matrix.
    Material white;
    white.name = "holdout";
    white.baseColor = glm::vec4(1.0f);
    white.unlit = true;
    white.doubleSided = true;
    const std::uint32_t material = scene_.addMaterial(white);
    const float r = cfg_.compositing.compositor.holdoutRegionMetres;
    const bool full = cfg_.compositing.compositor.holdout == HoldoutMesh::Full;
    auto moves = [&](NodeId n) {
        for (; n != kNoNode; n = scene_.parent(n))
            for (const ObjectMotion& m : motions_)
                if (m.node == n) return true;
        return false;
    };
    const std::filesystem::path cache = holdoutCacheFolder(cfg_.compositing.compositor);
    holdoutBake_ = {.folder = cache};
    if (!cache.empty()) {
        std::error_code ec;
        std::filesystem::create_directories(cache, ec);  // a folder that cannot be made: every write says so
    }
    const std::vector<NodeId> meshes = [&] {
        std::vector<NodeId> m;
        for (const NodeId n : scene_.order())
            if (scene_.kind(n) == NodeKind::Mesh) m.push_back(n);
        return m;
    }();
    for (const NodeId n : meshes) {
        const glm::mat4 toLocal = glm::inverse(scene_.world(n));
        std::vector<glm::vec3> corners;
        for (int i = 0; i < 8; ++i) {
            const glm::vec3 offset((i & 1) ? r : -r, (i & 2) ? r : -r, (i & 4) ? r : -r);
            corners.push_back(glm::vec3(toLocal * glm::vec4(view_.eye + offset, 1.0f)));
        }
        const Geometry& g = scene_.geometry(scene_.meshPart(n).geometry);
        std::vector<ViewRegion> regions;
        // A mover leaves the region it was baked for: its full mesh is the holdout.
        if (!full && !moves(n)) regions.push_back(ViewRegion::fromVertices(corners));
        if (cache.empty()) {
            holdouts_.add(scene_, n, bakeSilhouetteMesh(g.positions, g.indices, regions), material);
            ++holdoutBake_.baked;
            continue;
        }
        std::string note;
        const std::filesystem::path file = cache / holdoutFileName(cfg_.file, scene_.name(n), n);
        holdouts_.add(scene_, n, loadOrBakeSilhouetteMesh(file, g.positions, g.indices, regions, note), material);
        if (note.ends_with(": loaded")) {
            ++holdoutBake_.loaded;
        } else {
            ++holdoutBake_.baked;
            spdlog::info("holdout of '{}': {}", scene_.name(n), note);
        }
    }
}

void Station::moveObjects(double seconds) {
    for (const ObjectMotion& m : motions_)
        scene_.setLocal(m.node, glm::translate(glm::mat4(1.0f), motionOffset(m, seconds)) * m.rest);
    scene_.update();
    // Only the branches of the grouping tree that hold movers are rebuilt.
    std::map<NodeId, std::vector<MovedObject>> moved;
    for (const ObjectMotion& m : motions_)
        if (m.groupingNode != kNoNode) moved[m.groupingNode].push_back({m.groupingObject, motionVelocity(m, seconds)});
    for (const auto& [node, objects] : moved) regroupMoved(scene_, node, grouping_, objects);
}

Image Station::readHoldout() {
    if (!holdoutMask_) holdoutMask_ = std::make_unique<RenderTarget>(compositor_->size());
    holdoutMask_->bind();
    renderer_->draw(scene_, holdoutList_, view_, {.clearColor = glm::vec4(0.0f)});
    return holdoutMask_->read();
}

std::size_t Station::silhouetteTrianglesTotal() const { return holdouts_.triangles(); }

void Station::setCamera(const glm::vec3& eye, const glm::vec3& target) {
    CameraConfig camera = cfg_.camera;
    camera.eye = eye;
    camera.target = target;
    camera.size = compositor_->size();
    view_ = cameraView(camera);
}

bool Station::capture() {
    if (firstPending_) {
        firstPending_ = false;  // the constructor read it to learn the size
        stats_.newVideoFrame = true;
        return true;
    }
    return grabNext();
}

bool Station::grabNext() {
    std::optional<Frame> f;
    if (input_.replay) {
        GrabResult r = input_.replay->grab();
        replayState_ = r.state;
        if (!r.frame) {
            inputEnd_ = r.state.reason;
            return false;
        }
        replayState_.status = SourceStatus::Streaming;
        f = std::move(r.frame);
        videoSeconds_ = std::chrono::duration<double>(f->timestamp).count();
    } else {
        f = input_.live->newest();
        // A camera takes a moment to deliver its first frame; the station
        // needs one to know its size.
        for (int wait = 0; !f && frame_.empty() && wait < 600; ++wait) {
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
            f = input_.live->newest();
        }
    }
    stats_.newVideoFrame = f.has_value();
    if (f) {
        if (!frame_.empty() && f->image.size() != frame_.size())
            cv::resize(f->image, frame_, frame_.size(), 0, 0, cv::INTER_AREA);  // a fallback of another size
        else frame_ = f->image;
        if (!frame_.isContinuous()) frame_ = frame_.clone();
    }
    return !frame_.empty();
}

bool Station::frame() {
    Clock::time_point t = Clock::now();
    const Clock::time_point start = t;

    if (!capture()) return false;
    stats_.captureMs = msSince(t);
    if (stats_.newVideoFrame || person_.empty()) matte_->apply(frame_, person_);
    stats_.matteMs = msSince(t);

    const double seconds = input_.replay ? videoSeconds_ : std::chrono::duration<double>(Clock::now() - clockStart_).count();
    if (!motions_.empty()) moveObjects(seconds);
    scene_.update();
    stats_.updateMs = msSince(t);

    glm::vec3 gaze(0.0f);  // zero: the screen centre
    if (gaze_)
        if (const std::optional<GazeSample> g = gaze_->sample(seconds)) gaze = g->direction;
    select(scene_, view_,
           {.shading = cfg_.render.shading, .lod = lods_.size() ? &lods_ : nullptr, .gaze = gaze, .timeSeconds = seconds,
            .grouping = &grouping_, .holdouts = &holdouts_},
           cgList_);
    stats_.selectMs = msSince(t);

    gpuTimes_->collect();  // the previous frame's GL stages
    stats_.renderMs = gpuTimes_->ms(kGpuRender);
    stats_.holdoutMs = gpuTimes_->ms(kGpuHoldout);
    stats_.compositeMs = gpuTimes_->ms(kGpuBackdrop) + gpuTimes_->ms(kGpuPerson);
    if (budget_) {
        // The controller steers the CG draw only. It learns from the
        // previous frame's draw before it plans this one; its share of the
        // target is what the rest of the previous frame left.
        if (stats_.frame > 0) budget_->observe(stats_.renderMs);
        const double others = stats_.totalMs - stats_.renderMs - stats_.budgetMs;
        budget_->setTarget(std::max(1.0, cfg_.budget.targetMs - (stats_.frame > 0 ? std::max(0.0, others) : 0.0)));
        stats_.budget = budget_->apply(scene_, cgList_, view_, gaze);
        stats_.budgetMs = msSince(t);
    }

    const CompositorConfig& comp = cfg_.compositing.compositor;
    gpuTimes_->begin(kGpuBackdrop);
    compositor_->begin(frame_, {.backdropVideo = comp.backdropVideo, .backdropColor = comp.backdropColor});
    gpuTimes_->end(kGpuBackdrop);

    gpuTimes_->begin(kGpuRender);
    renderer_->draw(scene_, cgList_, view_, {.clearColor = std::nullopt});
    gpuTimes_->end(kGpuRender);
    stats_.cgTriangles = renderer_->trianglesDrawn();
    msSince(t);
    if (cloudLayer_) cloudLayer_->draw(scene_, pointClouds_, cgList_.pointClouds, view_);
    stats_.pointCloudMs = msSince(t);

    chooseHoldouts();
    gpuTimes_->begin(kGpuHoldout);
    compositor_->beginHoldout();
    renderer_->draw(scene_, holdoutList_, view_, {.clearColor = std::nullopt});
    compositor_->endHoldout();
    gpuTimes_->end(kGpuHoldout);
    stats_.holdoutTriangles = renderer_->trianglesDrawn();

    gpuTimes_->begin(kGpuPerson);
    compositor_->person(person_);
    gpuTimes_->end(kGpuPerson);
    gpuTimes_->endFrame();
    stats_.personTiles = compositor_->personTiles();

    ++frames_;
    stats_.frame = frames_;
    msSince(t);
    try {
        writeOutputs();
    } catch (const std::exception& e) {
        // A kiosk keeps showing its frames when the disk fills; the runner
        // reports the failure to the operator.
        ++outputFailures_;
        lastOutputError_ = e.what();
    }
    stats_.outputMs = msSince(t);
    stats_.totalMs = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    return true;
}

void Station::chooseHoldouts() {
    // In front of the person: the object's centre is nearer than the person
    // plane along the view axis. The CG item is read after the controller,
    // so the holdout is the silhouette of the level actually drawn.
    holdoutList_.clear();
    const float plane = cfg_.compositing.compositor.personPlaneMetres;
    stats_.objectsInFront = stats_.objectsBehind = 0;
    for (const HoldoutItem& h : cgList_.holdouts) {
        if (h.depth >= plane) {
            ++stats_.objectsBehind;
            continue;
        }
        ++stats_.objectsInFront;
        if (const std::optional<DrawItem> item = holdouts_.itemFor(scene_, cgList_.items[h.cgItem], view_))
            holdoutList_.items.push_back(*item);
    }
}

void Station::writeOutputs() {
    const OutputConfig& out = cfg_.compositing.output;
    const std::uint64_t index = firstOutputIndex_ + frames_ - 1;
    if (!out.matteDir.empty()) {
        std::filesystem::create_directories(out.matteDir);
        const std::filesystem::path file = out.matteDir / numbered("matte", index);
        if (!cv::imwrite(file.string(), alphaOf(person_))) throw VideoError(file.string(), "matte", "cannot write");
    }
    if (out.pngDir.empty() && !video_) return;
    const Image image = compositor_->output().read();
    if (!out.pngDir.empty()) writePng(out.pngDir / numbered("frame", index), image);
    if (video_) {
        const cv::Mat rgba(image.height, image.width, CV_8UC4, const_cast<std::uint8_t*>(image.rgba.data()));
        cv::cvtColor(rgba, bgr_, cv::COLOR_RGBA2BGR);
        video_->write(bgr_);
    }
}

void Station::finish() {
    if (video_) video_->close();
}

StationInput Station::releaseInput() {
    finish();
    return std::move(input_);
}

std::string Station::inputName() const {
    if (input_.replay) return input_.replay->name();
    return input_.live ? input_.live->name() : std::string();
}

SourceState Station::inputState() const {
    if (input_.live) return input_.live->state();
    return replayState_;
}

std::uint64_t Station::inputDrops() const { return input_.live ? input_.live->drops() : 0; }

} // namespace arcomp
