#pragma once
// An offscreen framebuffer: RGBA8 colour in a texture (so later passes can
// sample it) and a depth-stencil buffer. Headless rendering and every image
// test draw into one of these and read it back.
//
//   RenderTarget target({640, 480});
//   target.bind();  ... draw ...
//   Image img = target.read();   // rows top to bottom, premultiplied RGBA

#include "graph/core/Material.hpp"
#include "runtime/gl/GlApi.hpp"
#include "runtime/gl/GlHandle.hpp"

#include <glm/glm.hpp>

namespace arcomp {

class RenderTarget {
public:
    explicit RenderTarget(glm::ivec2 size);
    RenderTarget(const RenderTarget&) = delete;
    RenderTarget& operator=(const RenderTarget&) = delete;

    void bind() const;  // also sets the viewport to the whole target
    Image read() const;
    // Into an image kept between frames: a 1080p frame is 8 MB, and a fresh
    // buffer each frame pays for its zero fill and page faults again.
    void read(Image& into) const;
    glm::ivec2 size() const { return size_; }
    GLuint colorTexture() const { return color_.get(); }
    GLuint framebuffer() const { return framebuffer_.get(); }

private:
    glm::ivec2 size_;
    GlTexture color_;
    GlRenderbuffer depthStencil_;
    GlFramebuffer framebuffer_;
};

// Reads a framebuffer's colour (0: the window's) as an image, rows top to bottom.
Image readFramebuffer(GLuint framebuffer, glm::ivec2 size);
void readFramebuffer(GLuint framebuffer, glm::ivec2 size, Image& into);

}  // namespace arcomp
