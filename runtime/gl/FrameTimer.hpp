#pragma once
// Times the GPU work between begin() and end(), for the frame-time cost
// model: GL_TIME_ELAPSED timer queries where the driver has them, else the
// wall clock around glFinish (which also waits for queued work first, so
// that the interval holds only what was issued inside it).
//
//   FrameTimer timer;                 // a context must be current
//   timer.begin();  renderer.draw(...);  double ms = timer.end();
//
// On Mesa's llvmpipe the "GPU" is the CPU: vertex work runs inside the draw
// calls on the calling thread and only rasterization is deferred, so a
// timer query there can leave out part of what the frame costs. Finish mode
// measures what a viewer waits for. ProcessCpu mode counts the CPU time
// this process (all its threads, the rasterizer's included) spent between
// the two glFinish calls: on a software rasterizer that is the device's busy
// time, as a timer query gives it on a GPU, and time other programs took
// from the machine's cores is left out of it, as it is on a GPU.

#include "runtime/gl/GlApi.hpp"
#include "runtime/gl/GlHandle.hpp"

#include <chrono>
#include <string_view>

namespace arcomp {

enum class TimerMode { Auto, Query, Finish, ProcessCpu };

class FrameTimer {
public:
    // Auto: queries where hasTimerQueries(), else Finish; Query where there
    // are none falls back to Finish too.
    explicit FrameTimer(TimerMode mode = TimerMode::Auto);
    FrameTimer(const FrameTimer&) = delete;
    FrameTimer& operator=(const FrameTimer&) = delete;

    void begin();
    // Waits for the work issued since begin() and gives its milliseconds.
    double end();
    bool usesQueries() const { return static_cast<bool>(query_); }
    std::string_view method() const {
        return usesQueries() ? "gl_time_elapsed" : processCpu_ ? "process_cpu_glfinish" : "wall_glfinish";
    }

private:
    GlQuery query_;  // none: timed with glFinish
    bool processCpu_ = false;
    double startCpuMs_ = 0.0;
    std::chrono::steady_clock::time_point start_{};
};

}  // namespace arcomp
