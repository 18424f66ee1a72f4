#pragma once
// Puts a station's composited frame on the kiosk's screen: scaled to fit the
// window with its aspect kept (black bars), the stats overlay laid over it
// when shown, and screenshots of what the screen shows.
//
//   WindowPresenter presenter;                 // the window's context is current
//   presenter.present(station.compositedFrame(), window.framebufferSize(), overlayOrNull);
//   window.swap();
//   writePng("shot.png", presenter.screenshot(window.framebufferSize()));

#include "runtime/GlHandle.hpp"
#include "runtime/RenderTarget.hpp"
#include "runtime/ShaderProgram.hpp"

#include <opencv2/core.hpp>

#include <optional>

namespace arcomp {

class WindowPresenter {
public:
    WindowPresenter();
    WindowPresenter(const WindowPresenter&) = delete;
    WindowPresenter& operator=(const WindowPresenter&) = delete;

    // `overlay`: premultiplied RGBA rows top to bottom, drawn at the top left; null for none.
    void present(const RenderTarget& frame, glm::ivec2 windowSize, const cv::Mat* overlay);
    // The default framebuffer as presented last, rows top to bottom.
    Image screenshot(glm::ivec2 windowSize) const;

private:
    struct OverlayProgram {
        OverlayProgram();
        ShaderProgram program;
        GLint image, rect;  // uniform locations
    };

    OverlayProgram program_;
    GlVertexArray vao_;
    GlTexture overlayTexture_;
    glm::ivec2 overlaySize_{0};
};

} // namespace arcomp
