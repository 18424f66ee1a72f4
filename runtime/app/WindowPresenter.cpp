#include "runtime/app/WindowPresenter.hpp"

#include <algorithm>

namespace arcomp {

using namespace gl;

namespace {

// One quad from gl_VertexID (no buffers), placed by a pixel rectangle;
// texture rows are top to bottom as the overlay image is.
const char* const kOverlayShader = R"(
uniform vec4 uRect;      // x, y, width, height in NDC, y up
#ifdef VERTEX
out vec2 vUv;
void main() {
    vec2 corner = vec2(float(gl_VertexID & 1), float((gl_VertexID >> 1) & 1));
    vUv = vec2(corner.x, 1.0 - corner.y);
    gl_Position = vec4(uRect.xy + corner * uRect.zw, 0.0, 1.0);
}
#endif
#ifdef FRAGMENT
in vec2 vUv;
uniform sampler2D uImage;
out vec4 fragColor;
void main() { fragColor = texture(uImage, vUv); }
#endif
)";

}  // namespace

WindowPresenter::OverlayProgram::OverlayProgram()
    : program(kOverlayShader), image(program.requiredLocation("uImage")), rect(program.requiredLocation("uRect")) {}

WindowPresenter::OverlayTexture::OverlayTexture(GLint filter) : texture(GlTexture::generate()) {
    glBindTexture(GL_TEXTURE_2D, texture.get());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

void WindowPresenter::OverlayTexture::upload(const cv::Mat& rgba) {
    CV_Assert(rgba.type() == CV_8UC4 && rgba.isContinuous());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glBindTexture(GL_TEXTURE_2D, texture.get());
    const glm::ivec2 imageSize(rgba.cols, rgba.rows);
    if (imageSize != size) {
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, imageSize.x, imageSize.y, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data);
        size = imageSize;
    } else {
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, imageSize.x, imageSize.y, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data);
    }
}

// The panel is shown pixel for pixel (nearest); the frame overlay is scaled
// with the frame, where linear filtering keeps its thin lines whole.
WindowPresenter::WindowPresenter() : vao_(GlVertexArray::generate()), overlay_(GL_NEAREST), frameOverlay_(GL_LINEAR) {}

void WindowPresenter::drawOverlay(const OverlayTexture& overlay, glm::vec2 origin, glm::vec2 size,
                                  glm::ivec2 windowSize) {
    glBindTexture(GL_TEXTURE_2D, overlay.texture.get());
    const glm::vec2 ndcOrigin = 2.0f * origin / glm::vec2(windowSize) - 1.0f,
                    ndcSize = 2.0f * size / glm::vec2(windowSize);
    glUniform4f(program_.rect, ndcOrigin.x, ndcOrigin.y, ndcSize.x, ndcSize.y);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
}

void WindowPresenter::present(const RenderTarget& frame, glm::ivec2 windowSize, const cv::Mat* overlay,
                              const cv::Mat* frameOverlay) {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, windowSize.x, windowSize.y);
    glDisable(GL_SCISSOR_TEST);
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);

    // Fit, keeping the aspect: a kiosk screen rarely has the camera's shape.
    const glm::ivec2 size = frame.size();
    const float scale = std::min(static_cast<float>(windowSize.x) / static_cast<float>(size.x),
                                 static_cast<float>(windowSize.y) / static_cast<float>(size.y));
    const glm::ivec2 shown(static_cast<int>(static_cast<float>(size.x) * scale),
                           static_cast<int>(static_cast<float>(size.y) * scale));
    const glm::ivec2 origin = (windowSize - shown) / 2;
    glBindFramebuffer(GL_READ_FRAMEBUFFER, frame.framebuffer());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glBlitFramebuffer(0, 0, size.x, size.y, origin.x, origin.y, origin.x + shown.x, origin.y + shown.y,
                      GL_COLOR_BUFFER_BIT, GL_LINEAR);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);

    const bool withPanel = overlay && !overlay->empty(), withFrameOverlay = frameOverlay && !frameOverlay->empty();
    if (!withPanel && !withFrameOverlay) return;
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);  // premultiplied "over"
    program_.program.use();
    glActiveTexture(GL_TEXTURE0);
    glUniform1i(program_.image, 0);
    glBindVertexArray(vao_.get());
    if (withFrameOverlay) {
        frameOverlay_.upload(*frameOverlay);
        drawOverlay(frameOverlay_, origin, shown, windowSize);
    }
    if (withPanel) {
        overlay_.upload(*overlay);
        const float margin = 8.0f;
        const glm::vec2 panel(overlay_.size);
        drawOverlay(overlay_, {margin, static_cast<float>(windowSize.y) - margin - panel.y}, panel, windowSize);
    }
    glBindVertexArray(0);
    glDisable(GL_BLEND);
}

Image WindowPresenter::screenshot(glm::ivec2 windowSize) const { return readFramebuffer(0, windowSize); }

}  // namespace arcomp
