#pragma once
// One compositing station's frame, in one place: it owns the video input,
// the person matte, the CG scene and its holdout meshes, the renderers, the
// compositor and the file outputs. frame() runs
//   capture -> update -> select -> budget -> render -> composite -> output
// (composite being: backdrop, CG, holdout into the stencil, person layer;
// see runtime/Compositor.hpp)
// and records each stage's milliseconds in stats().
//
//   auto ctx = HeadlessContext::create(GlRequest::Auto);   // or a window's context
//   Station station(cfg, StationInput::fromReplay(std::move(grabber), fps));
//   while (station.frame()) {}                              // false at the end of the input
//   station.finish();                                       // closes the video file
//
// With `budget` on, the controller (graph/budget/FrameBudget.hpp) edits the CG draw
// list between select and render so that the whole frame meets the target.
// The composited frame stays in compositedFrame() after frame(): an RGBA8
// colour texture (colorTexture(), rows bottom-up as GL keeps them) in an FBO
// (framebuffer()); a windowed driver draws it with a textured quad or blits
// the FBO to the default framebuffer to present it.
// Replay pulls frames in order with no thread and no drops, so the same
// input gives bit-identical output images on the same machine.

#include "graph/core/DrawList.hpp"
#include "graph/budget/FrameBudget.hpp"
#include "graph/grouping/GroupingNodes.hpp"
#include "graph/lod/Lod.hpp"
#include "graph/core/ObjectMotion.hpp"
#include "graph/points/PointCloudNodes.hpp"
#include "graph/core/Scene.hpp"
#include "graph/silhouette/HoldoutMeshes.hpp"
#include "runtime/Compositor.hpp"
#include "runtime/GazeConfig.hpp"
#include "runtime/GpuStageTimes.hpp"
#include "runtime/Renderer.hpp"
#include "runtime/StationConfig.hpp"
#include "video/FrameGrabber.hpp"
#include "video/FrameSource.hpp"
#include "video/PersonMatte.hpp"
#include "video/VideoFileWriter.hpp"

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace arcomp {

class PointCloudLayer;

// Where frames come from: a grabber pulled frame by frame (replay: every
// frame, in order) or a live source whose newest frame is taken.
struct StationInput {
    std::unique_ptr<FrameGrabber> replay;
    std::unique_ptr<FrameSource> live;
    double fps = 25.0;  // for the video file output

    static StationInput fromReplay(std::unique_ptr<FrameGrabber> g, double fps);
    static StationInput fromLive(std::unique_ptr<FrameSource> s, double fps);
};

// Per frame: stage times (ms) and counters. CPU stages are wall time of
// this frame. GL stages are the previous frame's, from GpuStageTimes: the
// GPU's time from timer queries read one frame late, so that timing never
// stalls a GPU (on a software rasterizer, the stage's wall time, waited for).
struct FrameStats {
    std::uint64_t frame = 0;   // frames composited so far, this one included
    double captureMs = 0;      // CPU: wait for / decode the frame
    double matteMs = 0;        // CPU: person layer
    double updateMs = 0;       // CPU: transforms and bounds
    double selectMs = 0;       // CPU: culling, LOD, grouping cut, silhouette region, bins
    double budgetMs = 0;       // CPU: the frame-time controller (0 when it is off)
    double renderMs = 0;       // GL: CG, all objects, shaded (what the controller observes)
    double pointCloudMs = 0;   // CPU: point clouds splatted and laid over the CG (0 without)
    double holdoutMs = 0;      // GL: holdout mask from the front objects' silhouette meshes
    double compositeMs = 0;    // GL: backdrop upload, person upload and tiles
    double outputMs = 0;       // CPU: read back and write files (0 without file outputs)
    double totalMs = 0;        // wall time of the whole frame on the CPU
    std::size_t cgTriangles = 0;
    std::size_t holdoutTriangles = 0;
    std::size_t objectsInFront = 0;
    std::size_t objectsBehind = 0;
    std::size_t personTiles = 0;  // 32x32 tiles where the matte had any alpha
    // The controller's view of the CG render stage, when it is on: its target
    // (the frame target less what the other stages took last frame), its
    // prediction, and the area-weighted quality it kept (1 = finest).
    std::optional<BudgetStats> budget;
    bool newVideoFrame = false;  // live: false when the camera had nothing new
};

class Station {
public:
    // A GL context must be current. The output size is the video's size (the
    // first frame is read here; a live source gets up to 3 s to deliver it). Outputs come from cfg.compositing.output.
    // Throws VideoError when there is no first frame or an output cannot be
    // opened, and what preflight() throws.
    Station(const StationConfig& cfg, StationInput input);

    // Everything config-dependent that can fail before a station starts (the
    // calibration file, the gaze track, the matte settings), checked without
    // GL or video, so that a reload can be refused while the old station runs.
    static void preflight(const StationConfig& cfg);

    // Movers and the gaze track run on this clock: the video's own
    // timestamps in replay (deterministic), wall time since `start` live. A
    // reloaded live station keeps the previous one's start.
    void setClockStart(std::chrono::steady_clock::time_point start) { clockStart_ = start; }
    std::chrono::steady_clock::time_point clockStart() const { return clockStart_; }
    ~Station();

    // One frame; false when a replay input has ended (nothing was drawn).
    bool frame();
    // Finishes outputs (closes the video file). Safe to call twice.
    void finish();
    // After finish(): the input, still open, for the next Station when the
    // config is reloaded with the same video source.
    StationInput releaseInput();
    // Output files are numbered from here (a reloaded station continues
    // where the previous one stopped instead of overwriting its frames).
    void setFirstOutputIndex(std::uint64_t index) { firstOutputIndex_ = index; }

    // The input as an operator sees it: its name, state and dropped frames.
    std::string inputName() const;
    SourceState inputState() const;
    std::uint64_t inputDrops() const;

    const FrameStats& stats() const { return stats_; }
    const RenderTarget& compositedFrame() const { return compositor_->output(); }
    const View& view() const { return view_; }
    // What the last frame's select (and budget) chose to draw.
    const DrawList& drawList() const { return cgList_; }
    glm::ivec2 size() const { return compositor_->size(); }
    const std::vector<std::string>& warnings() const { return warnings_; }
    // The last frame's holdout mask, drawn again (same meshes, same view)
    // into a colour target and read back: 255 where the person is cut. The
    // frame itself keeps the mask only in the stencil.
    Image readHoldout();
    // The last matte output (premultiplied BGRA, video size).
    const cv::Mat& personLayer() const { return person_; }
    // Overrides the camera (tests move it along a path); keeps the intrinsics.
    void setCamera(const glm::vec3& eye, const glm::vec3& target);
    std::size_t silhouetteTrianglesTotal() const;
    // How this start came by its holdout meshes: loaded from the cache
    // folder (CompositorConfig::holdoutCache) or baked (and saved there).
    struct HoldoutBake {
        std::filesystem::path folder;  // empty: no cache
        std::size_t loaded = 0, baked = 0;
    };
    const HoldoutBake& holdoutBake() const { return holdoutBake_; }
    // Why a replay input ended ("end after 795 frames", a decoder error); empty while it runs.
    const std::string& inputEnd() const { return inputEnd_; }
    // File outputs that failed (a full disk, a folder gone read-only): the
    // frame is still composited and shown, only its file is missing.
    // Frames written before stay whole (PNGs are written beside and renamed).
    std::uint64_t outputFailures() const { return outputFailures_; }
    const std::string& lastOutputError() const { return lastOutputError_; }

private:
    bool capture();
    bool grabNext();
    void buildHoldouts();
    void chooseHoldouts();
    void moveObjects(double timeSeconds);
    void writeOutputs();

    StationConfig cfg_;
    StationInput input_;
    std::unique_ptr<PersonMatte> matte_;
    Scene scene_;
    GroupingNodes grouping_;
    LodTable lods_;
    std::vector<ObjectMotion> motions_;
    std::unique_ptr<GazeSource> gaze_;
    PointCloudNodes pointClouds_;
    HoldoutMeshes holdouts_;
    HoldoutBake holdoutBake_;
    View view_;
    DrawList cgList_, holdoutList_;
    std::unique_ptr<Renderer> renderer_;  // CG and holdouts: one scene, one set of GPU buffers
    std::unique_ptr<GpuStageTimes> gpuTimes_;
    std::unique_ptr<PointCloudLayer> cloudLayer_;  // only with point clouds
    std::unique_ptr<Compositor> compositor_;
    std::unique_ptr<RenderTarget> holdoutMask_;  // only for readHoldout()
    std::unique_ptr<VideoFileWriter> video_;
    std::optional<FrameBudget> budget_;
    std::vector<std::string> warnings_;
    cv::Mat frame_, person_, bgr_;
    bool firstPending_ = false;
    std::string inputEnd_;
    SourceState replayState_{SourceStatus::Opening, ""};
    std::uint64_t firstOutputIndex_ = 0;
    std::chrono::steady_clock::time_point clockStart_ = std::chrono::steady_clock::now();
    double videoSeconds_ = 0.0;  // the current frame's timestamp (replay)
    std::uint64_t outputFailures_ = 0;
    std::string lastOutputError_;
    FrameStats stats_;
    std::uint64_t frames_ = 0;
};

} // namespace arcomp
