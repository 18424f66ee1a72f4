#pragma once
// Brings a rendered frame back to the CPU, for files and streams.
//
// Synchronous: glReadPixels waits until the GPU has finished the frame, then
// copies it. Asynchronous: the copy goes into one of two pixel-buffer
// objects and the call returns at once; the next call maps the buffer of the
// frame before, long finished by then, so the CPU never waits on the GPU's
// current frame. That costs one frame of latency, and the last frame comes
// out through drain().
//
// Auto reads asynchronously on a GPU and synchronously on a software
// rasterizer (llvmpipe): there the frame is finished when drawn, and
// glReadPixels is a copy on the calling thread either way.
//
//   FrameReadback readback(FrameReadback::Mode::Auto);
//   if (readback.read(target, image)) write(image);   // each frame: this one, or the one before
//   if (readback.drain(image)) write(image);          // at the end: the one still in flight

#include "graph/core/Material.hpp"
#include "runtime/gl/GlHandle.hpp"
#include "runtime/gl/RenderTarget.hpp"

#include <array>

namespace arcomp {

class FrameReadback {
public:
    enum class Mode { Auto, Synchronous, Asynchronous };

    explicit FrameReadback(Mode mode = Mode::Auto) : mode_(mode) {}

    // Starts reading `frame`. True when `into` now holds a frame: this one
    // (synchronous), or the one passed to the call before (asynchronous).
    bool read(const RenderTarget& frame, Image& into);
    // The frame still in flight, if any. Call with the context current.
    bool drain(Image& into);
    // Frames between the one passed to read() and the one it returns; the
    // mode is settled on the first read(), with a context to ask.
    int latencyFrames() const { return mode_ == Mode::Asynchronous ? 1 : 0; }

private:
    struct Slot {
        GlBuffer buffer;
        glm::ivec2 size{0};
        std::size_t capacity = 0;
        bool pending = false;
    };
    void collect(Slot& slot, Image& into);

    Mode mode_;
    std::array<Slot, 2> slots_;
    std::size_t next_ = 0;
};

}  // namespace arcomp
