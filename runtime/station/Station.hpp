#pragma once
// One compositing station's frame, in one place. Station::frame() is the
// pipeline, each stage a class of its own:
//   capture -> matte -> people (depths, floor, zones, triggers, show control) -> update -> select -> budget
//   -> backdrop -> contact shadows -> render -> holdout -> composite -> output
// (CaptureStage, MatteStage, PersonDepthStage, FloorPeople, ZoneOccupancy, Triggers and ShowControl, moveObjects and
// animateObjects, select, BudgetStage, Compositor, ShadowCatcher, Renderer and PointCloudLayer, HoldoutStage,
// Compositor, OutputStage), and it records each stage's milliseconds in stats() (runtime/station/FrameStats.hpp).
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
// Replay pulls frames in order with no drops, so the same input gives
// bit-identical output images on the same machine.
//
// Pipelined: the CPU front of frame N+1 (capture with its decode and the
// video plate the compositor uploads, then the matte and the tiles its
// person layer covers) runs on a thread of its own (WorkerThread, one for
// the station's life) while frame N's GL stages run here, and frame()
// returns once both are done, so no thread runs between calls. Each frame
// is still composited with its own video image and its own matte, in
// order, so replay stays deterministic; the last frame of a file is
// composited as before. The cost is one frame of latency: a live frame is
// taken from the camera one frame() earlier than it is shown (one frame
// period, 33 ms at 30 fps). In stats(), captureMs and matteMs are that
// thread's times (during the previous frame); totalMs is this thread's wall
// time, the wait for the front included, so 1000 / totalMs is the rate.
//
// Threads: none is started per frame, per request or per reconnect. Each
// thread a station uses (this front, a camera's CaptureThread, the status
// server's, OpenCV's and llvmpipe's pools) starts once and lives as long as
// its owner: libraries keep per-thread data that outlives a thread, so a
// thread a frame piles it up (runtime/station/WorkerThread.hpp).
//
// Memory: every per-frame buffer is allocated once, at its steady size, and
// written in place from then on. The front fills two frames in turn (the
// shown one stays whole while the next is made), each keeping its plate
// and its tiles; MatteStage keeps its two person layers the same way. A
// station's memory is flat after its first frames (bench soak, and the
// SoakGuard test in CI).

#include "graph/core/DrawList.hpp"
#include "graph/core/View.hpp"
#include "graph/core/World.hpp"
#include "runtime/composite/Compositor.hpp"
#include "runtime/config/StationConfig.hpp"
#include "runtime/gl/GpuStageTimes.hpp"
#include "runtime/people/FloorPeople.hpp"
#include "runtime/render/Renderer.hpp"
#include "runtime/showcontrol/ShowControl.hpp"
#include "runtime/station/BudgetStage.hpp"
#include "runtime/station/CaptureStage.hpp"
#include "runtime/station/EventLog.hpp"
#include "runtime/station/FrameStats.hpp"
#include "runtime/station/GazeSource.hpp"
#include "runtime/station/HoldoutBake.hpp"
#include "runtime/station/HoldoutStage.hpp"
#include "runtime/station/MatteStage.hpp"
#include "runtime/station/OutputStage.hpp"
#include "runtime/station/PersonDepthStage.hpp"
#include "runtime/station/WorkerThread.hpp"
#include "runtime/triggers/Cue.hpp"
#include "runtime/triggers/Triggers.hpp"
#include "runtime/zones/ZoneOccupancy.hpp"

#include <array>
#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace arcomp {

class PointCloudLayer;
class ShadowCatcher;

class Station {
public:
    // A GL context must be current. The output size is the video's size (the
    // first frame is read here; a live source gets up to 3 s to deliver it).
    // Outputs come from cfg.compositing.output.
    // Throws VideoError when there is no first frame or an output cannot be
    // opened, and what preflight() throws.
    Station(const StationConfig& cfg, StationInput input);

    // Everything config-dependent that can fail before a station starts (the
    // calibration file, the gaze track, the matte settings), checked without
    // GL or video, so that a reload can be refused while the old station runs.
    static void preflight(const StationConfig& cfg);

    // Movers and the gaze track run on this clock: the video's own
    // timestamps in replay (deterministic), wall time since `start` live;
    // model animations on the shown frame's capture time since `start`
    // (CaptureStage::frameSeconds). A reloaded live station keeps the
    // previous one's start.
    void setClockStart(std::chrono::steady_clock::time_point start) { capture_.setClockStart(start); }
    std::chrono::steady_clock::time_point clockStart() const { return capture_.clockStart(); }
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
    void setFirstOutputIndex(std::uint64_t index) { outputs_.setFirstIndex(index); }

    // The input as an operator sees it: its name, state and dropped frames.
    std::string inputName() const { return capture_.name(); }
    SourceState inputState() const { return capture_.state(); }
    std::uint64_t inputDrops() const { return capture_.drops(); }

    const FrameStats& stats() const { return stats_; }
    // Each output stream's state and counts (output.streams).
    std::vector<StreamStatus> streamStatus() const { return outputs_.streamStatus(); }
    const RenderTarget& compositedFrame() const { return compositor_->output(); }
    const View& view() const { return view_; }
    // What the last frame's select (and budget) chose to draw.
    const DrawList& drawList() const { return drawList_; }
    glm::ivec2 size() const { return compositor_->size(); }
    const std::vector<std::string>& warnings() const { return warnings_; }
    // The last frame's holdout mask, drawn again (same meshes, same view)
    // into a colour target and read back: 255 where a holdout mesh covers,
    // which cuts each person who stands behind it there. The frame itself
    // keeps the holdout only as depth.
    Image readHoldout();
    // The last matte output (premultiplied BGRA, video size).
    const cv::Mat& personLayer() const { return shown().person; }
    // The last frame's video as uploaded (RGBA, rows bottom first); empty
    // without a video backdrop.
    const cv::Mat& videoPlate() const { return shown().plate; }
    // Where the last frame's people stood (all on the person plane without a calibrated camera).
    const PersonDepths& personDepths() const { return personDepths_.depths(); }
    const std::vector<StandingPerson>& standingPeople() const { return personDepths_.standing(); }
    // The last frame's visitors as the outputs publish them: on the floor in
    // metres with a calibrated camera, else in the picture.
    const PeopleFrame& people() const { return zones_.people(); }
    // Where the people go: each OSC, TUIO and MQTT output's state and counts.
    const ShowControl& showControl() const { return showControl_; }
    // A cue from show control (runtime/triggers/Cue.hpp), done at once on
    // the last frame's video time: an object action, or a snapshot of the
    // next frame into show_control.cues.snapshot_folder. Empty when done,
    // else why not (an object the scene does not have). A reload is the
    // runner's: refused here.
    std::string cue(const Cue& cue);
    // The MQTT cue topic's payloads since the last call.
    std::vector<std::string> takeMqttCues() { return showControl_.takeMqttCues(); }
    // The config's triggers with their counts, and what the last frame fired.
    const Triggers& triggers() const { return triggers_; }
    // Snapshots and clips the triggers asked for that were written.
    std::uint64_t snapshotsWritten() const { return outputs_.snapshotsWritten(); }
    std::uint64_t clipsWritten() const { return outputs_.clipsWritten(); }
    // Overrides the camera (tests move it along a path); keeps the intrinsics.
    void setCamera(const glm::vec3& eye, const glm::vec3& target);
    std::size_t silhouetteTrianglesTotal() const { return world_.holdouts.triangles(); }
    // How this start came by its holdout meshes: loaded from the cache
    // folder (runtime/station/BakeCache.hpp) or baked (and saved there).
    const HoldoutBake& holdoutBake() const { return holdoutBake_; }
    // The same for the objects' generated LOD levels.
    const BakeTally& lodBake() const { return lodBake_; }
    // Why a replay input ended ("end after 795 frames", a decoder error); empty while it runs.
    const std::string& inputEnd() const { return capture_.end(); }
    // File outputs that failed (a full disk, a folder gone read-only): the
    // frame is still composited and shown, only its file is missing.
    // Frames written before stay whole (PNGs are written beside and renamed).
    std::uint64_t outputFailures() const { return outputs_.failures(); }
    const std::string& lastOutputError() const { return outputs_.lastError(); }

private:
    // One frame's CPU front: its video image and person layer, and the
    // times the stage clock and the movers run on for it. Filled in place:
    // its plate and tiles keep their buffers from one use to the next.
    struct CapturedFrame {
        bool ok = false;    // false: a replay input has ended
        cv::Mat image;      // BGR, video size; never written after capture
        cv::Mat plate;      // the image as the compositor uploads it (Compositor::makePlate)
        cv::Mat person;     // premultiplied BGRA, video size
        PersonTiles tiles;  // where the person layer has alpha (Compositor::findTiles)
        bool newFrame = false;
        double seconds = 0, frameSeconds = 0;
        double captureMs = 0, matteMs = 0;
        std::chrono::steady_clock::time_point capturedAt;  // when the input handed the frame over
    };
    // Fills `next` from the input; `shown` is the frame on screen, whose
    // plate and tiles a live frame that did not change takes over.
    void captureAndMatte(CapturedFrame& next, const CapturedFrame& shown);
    const CapturedFrame& shown() const { return fronts_[shownFront_]; }

    glm::vec3 gazeAt(double seconds);
    // The frame's triggers: their object actions on the world, and the
    // snapshots, clips and messages they hand to the outputs.
    void runTriggers(const PeopleFrame& visitors);
    void collectGpuTimes();

    StationConfig cfg_;
    CaptureStage capture_;
    MatteStage matte_;
    PersonDepthStage personDepths_;
    FloorPeople people_;
    ZoneOccupancy zones_;  // the people with their zones: what is published
    Triggers triggers_;
    std::optional<EventLog> events_;
    ShowControl showControl_;
    World world_;
    View view_;
    std::unique_ptr<GazeSource> gaze_;
    HoldoutBake holdoutBake_;
    BakeTally lodBake_;
    DrawList drawList_;
    std::optional<BudgetStage> budget_;
    std::unique_ptr<Renderer> renderer_;           // CG and holdouts: one scene, one set of GPU buffers
    std::unique_ptr<PointCloudLayer> cloudLayer_;  // only with point clouds
    std::unique_ptr<ShadowCatcher> shadows_;       // only with contact shadows on
    HoldoutStage holdout_;
    std::unique_ptr<Compositor> compositor_;
    std::unique_ptr<RenderTarget> holdoutMask_;  // only for readHoldout()
    OutputStage outputs_;
    std::unique_ptr<GpuStageTimes> gpuTimes_;
    std::vector<std::string> warnings_;
    FrameStats stats_;
    // The frame last composited and the one the front fills next, in turn.
    std::array<CapturedFrame, 2> fronts_;
    unsigned shownFront_ = 1;  // the first frame goes into fronts_[0]
    // Runs the next frame's front during this one; it is done when frame()
    // returns. Last, so that it is joined before the stages it uses go.
    WorkerThread front_;
};

}  // namespace arcomp
