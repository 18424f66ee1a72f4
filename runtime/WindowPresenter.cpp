#include "runtime/WindowPresenter.hpp"

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

} // namespace

WindowPresenter::OverlayProgram::OverlayProgram()
    : program(kOverlayShader), image(program.requiredLocation("uImage")), rect(program.requiredLocation("uRect")) {}

WindowPresenter::WindowPresenter() : vao_(GlVertexArray::generate()), overlayTexture_(GlTexture::generate()) {
    glBindTexture(GL_TEXTURE_2D, overlayTexture_.get());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

void WindowPresenter::present(const RenderTarget& frame, glm::ivec2 windowSize, const cv::Mat* overlay) {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, windowSize.x, windowSize.y);
    glDisable(GL_SCISSOR_TEST);
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);

    // Fit, keeping the aspect: a kiosk screen rarely has the camera's shape.
    const glm::ivec2 size = frame.size();
    const float scale = std::min(static_cast<float>(windowSize.x) / static_cast<float>(size.x),
                                 static_cast<float>(windowSize.y) / static_cast<float>(size.y));
    const glm::ivec2 shown(static_cast<int>(static_cast<float>(size.x) * scale), static_cast<int>(static_cast<float>(size.y) * scale));
    const glm::ivec2 origin = (windowSize - shown) / 2;
    glBindFramebuffer(GL_READ_FRAMEBUFFER, frame.framebuffer());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glBlitFramebuffer(0, 0, size.x, size.y, origin.x, origin.y, origin.x + shown.x, origin.y + shown.y, GL_COLOR_BUFFER_BIT, GL_LINEAR);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);

    if (!overlay || overlay->empty()) return;
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glBindTexture(GL_TEXTURE_2D, overlayTexture_.get());
    const glm::ivec2 overlaySize(overlay->cols, overlay->rows);
    if (overlaySize != overlaySize_) {
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, overlaySize.x, overlaySize.y, 0, GL_RGBA, GL_UNSIGNED_BYTE, overlay->data);
        overlaySize_ = overlaySize;
    } else {
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, overlaySize.x, overlaySize.y, GL_RGBA, GL_UNSIGNED_BYTE, overlay->data);
    }
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);  // premultiplied "over"
    program_.program.use();
    glActiveTexture(GL_TEXTURE0);
    glUniform1i(program_.image, 0);
    const glm::vec2 ndc = 2.0f * glm::vec2(overlaySize) / glm::vec2(windowSize);
    const float margin = 2.0f * 8.0f / static_cast<float>(windowSize.y);
    glUniform4f(program_.rect, -1.0f + margin, 1.0f - margin - ndc.y, ndc.x, ndc.y);
    glBindVertexArray(vao_.get());
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    glBindVertexArray(0);
    glDisable(GL_BLEND);
}

Image WindowPresenter::screenshot(glm::ivec2 windowSize) const { return readFramebuffer(0, windowSize); }

} // namespace arcomp
