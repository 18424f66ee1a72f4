#include "runtime/gl/RenderTarget.hpp"

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace arcomp {

using namespace gl;

RenderTarget::RenderTarget(glm::ivec2 size) : size_(size) {
    GLint maxSize = 0;
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &maxSize);
    if (size.x <= 0 || size.y <= 0 || size.x > maxSize || size.y > maxSize)
        throw std::invalid_argument("render target size " + std::to_string(size.x) + "x" + std::to_string(size.y) +
                                    " is outside 1.." + std::to_string(maxSize));
    color_ = GlTexture::generate();
    glBindTexture(GL_TEXTURE_2D, color_.get());
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, size.x, size.y, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    depthStencil_ = GlRenderbuffer::generate();
    glBindRenderbuffer(GL_RENDERBUFFER, depthStencil_.get());
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, size.x, size.y);
    framebuffer_ = GlFramebuffer::generate();
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.get());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color_.get(), 0);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, depthStencil_.get());
    const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error("framebuffer incomplete: status 0x" + std::to_string(status));
}

void RenderTarget::bind() const {
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.get());
    glViewport(0, 0, size_.x, size_.y);
}

Image readFramebuffer(GLuint framebuffer, glm::ivec2 size) {
    Image img;
    readFramebuffer(framebuffer, size, img);
    return img;
}

void readFramebuffer(GLuint framebuffer, glm::ivec2 size, Image& img) {
    img.width = size.x;
    img.height = size.y;
    img.rgba.resize(static_cast<std::size_t>(size.x) * static_cast<std::size_t>(size.y) * 4);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    // RGBA + UNSIGNED_BYTE is the one read format every GL and GLES accepts.
    glReadPixels(0, 0, size.x, size.y, GL_RGBA, GL_UNSIGNED_BYTE, img.rgba.data());
    // GL's rows run bottom to top; images run top to bottom. Whole rows
    // through memcpy: a byte-wise swap costs a 1080p frame over a millisecond.
    const std::size_t row = static_cast<std::size_t>(size.x) * 4;
    std::vector<std::uint8_t> spare(row);
    for (int y = 0; y < size.y / 2; ++y) {
        std::uint8_t* top = img.rgba.data() + static_cast<std::size_t>(y) * row;
        std::uint8_t* bottom = img.rgba.data() + static_cast<std::size_t>(size.y - 1 - y) * row;
        std::memcpy(spare.data(), top, row);
        std::memcpy(top, bottom, row);
        std::memcpy(bottom, spare.data(), row);
    }
}

Image RenderTarget::read() const { return readFramebuffer(framebuffer_.get(), size_); }

void RenderTarget::read(Image& into) const { readFramebuffer(framebuffer_.get(), size_, into); }

}  // namespace arcomp
