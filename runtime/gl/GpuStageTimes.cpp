#include "runtime/gl/GpuStageTimes.hpp"

#include <algorithm>

namespace arcomp {

using namespace gl;

GpuStageTimes::GpuStageTimes(int stages)
    : cpuMs_(static_cast<std::size_t>(stages), 0.0), ms_(static_cast<std::size_t>(stages), 0.0),
      started_(static_cast<std::size_t>(stages)), finish_(isSoftwareRasterizer()) {
    for (int parity = 0; parity < 2; ++parity) {
        issued_[parity].assign(static_cast<std::size_t>(stages), false);
        if (finish_ || !hasTimerQueries()) continue;
        for (int s = 0; s < stages; ++s) queries_[parity].push_back(GlQuery::generate());
    }
}

void GpuStageTimes::begin(int stage) {
    const auto s = static_cast<std::size_t>(stage);
    if (usesQueries()) {
        glBeginQuery(GL_TIME_ELAPSED, queries_[current_][s].get());
        return;
    }
    if (finish_) glFinish();  // what came before is not this stage's
    started_[s] = Clock::now();
}

void GpuStageTimes::end(int stage) {
    const auto s = static_cast<std::size_t>(stage);
    issued_[current_][s] = true;
    if (usesQueries()) {
        glEndQuery(GL_TIME_ELAPSED);
        return;
    }
    if (finish_) glFinish();
    cpuMs_[s] = std::chrono::duration<double, std::milli>(Clock::now() - started_[s]).count();
}

void GpuStageTimes::endFrame() { current_ ^= 1; }

void GpuStageTimes::collect() {
    const int previous = current_ ^ 1;
    for (std::size_t s = 0; s < ms_.size(); ++s) {
        ms_[s] = 0.0;
        if (!issued_[previous][s]) continue;
        issued_[previous][s] = false;
        if (!usesQueries()) {
            ms_[s] = cpuMs_[s];
            continue;
        }
        GLuint64 ns = 0;
        glGetQueryObjectui64v(queries_[previous][s].get(), GL_QUERY_RESULT, &ns);
        ms_[s] = static_cast<double>(ns) * 1e-6;
    }
}

}  // namespace arcomp
