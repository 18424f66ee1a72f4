#include "runtime/gl/FrameTimer.hpp"

#include "graph/core/ElapsedTime.hpp"

namespace arcomp {

using namespace gl;

FrameTimer::FrameTimer(TimerMode mode) : processCpu_(mode == TimerMode::ProcessCpu) {
    if ((mode == TimerMode::Auto || mode == TimerMode::Query) && hasTimerQueries()) query_ = GlQuery::generate();
}

void FrameTimer::begin() {
    if (query_) {
        glBeginQuery(GL_TIME_ELAPSED, query_.get());
        return;
    }
    glFinish();
    start_ = std::chrono::steady_clock::now();
    startCpuMs_ = processCpuMs();
}

double FrameTimer::end() {
    if (query_) {
        glEndQuery(GL_TIME_ELAPSED);
        GLuint64 ns = 0;
        glGetQueryObjectui64v(query_.get(), GL_QUERY_RESULT, &ns);
        return static_cast<double>(ns) * 1e-6;
    }
    glFinish();
    if (processCpu_) return processCpuMs() - startCpuMs_;
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_).count();
}

}  // namespace arcomp
