#include "runtime/gl/FrameReadback.hpp"

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>

namespace arcomp {

using namespace gl;

bool FrameReadback::read(const RenderTarget& frame, Image& into) {
    if (mode_ == Mode::Auto) mode_ = isSoftwareRasterizer() ? Mode::Synchronous : Mode::Asynchronous;
    if (mode_ == Mode::Synchronous) {
        frame.read(into);
        return true;
    }
    Slot& slot = slots_[next_];
    const glm::ivec2 size = frame.size();
    const std::size_t bytes = static_cast<std::size_t>(size.x) * static_cast<std::size_t>(size.y) * 4;
    if (!slot.buffer) slot.buffer = GlBuffer::generate();
    glBindBuffer(GL_PIXEL_PACK_BUFFER, slot.buffer.get());
    if (slot.capacity != bytes) {
        glBufferData(GL_PIXEL_PACK_BUFFER, static_cast<GLsizeiptr>(bytes), nullptr, GL_STREAM_READ);
        slot.capacity = bytes;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, frame.framebuffer());
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, size.x, size.y, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);  // into the buffer, at offset 0
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    slot.size = size;
    slot.pending = true;
    next_ = 1 - next_;
    // The other slot holds the frame before, if there was one.
    Slot& previous = slots_[next_];
    if (!previous.pending) return false;
    collect(previous, into);
    return true;
}

bool FrameReadback::drain(Image& into) {
    // The frame in flight is the one read() started last: the slot before next_.
    Slot& last = slots_[1 - next_];
    if (!last.pending) return false;
    collect(last, into);
    return true;
}

void FrameReadback::collect(Slot& slot, Image& into) {
    slot.pending = false;
    into.width = slot.size.x;
    into.height = slot.size.y;
    into.rgba.resize(slot.capacity);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, slot.buffer.get());
    const void* mapped =
        glMapBufferRange(GL_PIXEL_PACK_BUFFER, 0, static_cast<GLsizeiptr>(slot.capacity), GL_MAP_READ_BIT);
    if (!mapped) {
        // The frames in the two buffers are lost; later ones are read the plain way.
        const GLenum error = glGetError();
        glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
        mode_ = Mode::Synchronous;
        for (Slot& s : slots_) s.pending = false;
        char hex[16];
        std::snprintf(hex, sizeof hex, "0x%04x", error);
        throw std::runtime_error(std::string("reading a frame back: the GL cannot map its pixel buffer (GL error ") +
                                 hex + "); the frames in flight are lost, later frames are read synchronously");
    }
    // GL's rows run bottom to top: copied into place, the flip costs nothing extra.
    const std::size_t row = static_cast<std::size_t>(slot.size.x) * 4;
    const auto* source = static_cast<const std::uint8_t*>(mapped);
    for (int y = 0; y < slot.size.y; ++y)
        std::memcpy(into.rgba.data() + static_cast<std::size_t>(slot.size.y - 1 - y) * row,
                    source + static_cast<std::size_t>(y) * row, row);
    glUnmapBuffer(GL_PIXEL_PACK_BUFFER);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
}

}  // namespace arcomp
