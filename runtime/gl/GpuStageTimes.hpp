#pragma once
// The GPU milliseconds of a frame's GL stages, read one frame late so that
// timing never stalls the pipeline: each stage is bracketed by a
// GL_TIME_ELAPSED query, and frame N's results are collected during frame
// N+1, when the GPU has long finished them. Two exceptions:
// - a software rasterizer (llvmpipe): its timer queries leave out the
//   rasterization, which runs at flush, so each stage is waited for
//   (glFinish) and timed on the wall clock. Nothing is lost by waiting
//   there: the "GPU" is the machine's own cores.
// - a GPU without timer queries (some ES 3.0 drivers): each stage's CPU
//   submission time stands in.
//
//   GpuStageTimes gpu(kStageCount);   // a context must be current
//   // each frame:
//   gpu.collect();                    // ms(s) now holds the previous frame
//   gpu.time(kRender, [&] { renderer.draw(...); });   // or begin(kRender) ... end(kRender)
//   gpu.endFrame();
//
// Stages must not overlap: GL allows one TIME_ELAPSED query at a time.

#include "runtime/gl/GlApi.hpp"
#include "runtime/gl/GlHandle.hpp"

#include <array>
#include <chrono>
#include <vector>

namespace arcomp {

class GpuStageTimes {
public:
    explicit GpuStageTimes(int stages);
    GpuStageTimes(const GpuStageTimes&) = delete;
    GpuStageTimes& operator=(const GpuStageTimes&) = delete;

    void begin(int stage);
    void end(int stage);
    template <class Stage>
    void time(int stage, Stage&& run) {
        begin(stage);
        run();
        end(stage);
    }
    // Closes this frame's set of queries; the next frame uses the other set.
    void endFrame();
    // Reads the previous frame's results into ms(). Call once a frame,
    // before that frame's first begin().
    void collect();
    // The previous frame's milliseconds for `stage` (0 for a stage it skipped).
    double ms(int stage) const { return ms_[static_cast<std::size_t>(stage)]; }
    bool usesQueries() const { return !queries_[0].empty(); }
    bool waitsForStages() const { return finish_; }

private:
    using Clock = std::chrono::steady_clock;
    std::array<std::vector<GlQuery>, 2> queries_;  // one set per frame parity
    std::array<std::vector<bool>, 2> issued_;
    std::vector<double> cpuMs_;  // without queries: this frame's submission times
    std::vector<double> ms_;
    std::vector<Clock::time_point> started_;
    int current_ = 0;
    bool finish_ = false;
};

}  // namespace arcomp
