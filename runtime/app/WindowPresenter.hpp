#pragma once
// Puts a station's composited frame on the kiosk's screen: scaled to fit the
// window with its aspect kept (black bars), the stats overlay laid over it
// when shown, and screenshots of what the screen shows. An image at the
// frame's size (the calibration overlay, runtime/app/CalibrationOverlay.hpp) can
// be laid over the frame itself, scaled with it.
//
//   WindowPresenter presenter;                 // the window's context is current
//   presenter.present(station.compositedFrame(), window.framebufferSize(), overlayOrNull, frameOverlayOrNull);
//   window.swap();
//   writePng("shot.png", presenter.screenshot(window.framebufferSize()));

#include "runtime/gl/GlHandle.hpp"
#include "runtime/gl/RenderTarget.hpp"
#include "runtime/gl/ShaderProgram.hpp"

#include <opencv2/core.hpp>

#include <optional>

namespace arcomp {

class WindowPresenter {
public:
    WindowPresenter();
    WindowPresenter(const WindowPresenter&) = delete;
    WindowPresenter& operator=(const WindowPresenter&) = delete;

    // `overlay`: premultiplied RGBA rows top to bottom, drawn at the top left
    // at its own pixel size; `frameOverlay`: the same at the frame's size,
    // drawn over the frame where it is shown (under `overlay`). Null for none.
    void present(const RenderTarget& frame, glm::ivec2 windowSize, const cv::Mat* overlay,
                 const cv::Mat* frameOverlay = nullptr);
    // The default framebuffer as presented last, rows top to bottom.
    Image screenshot(glm::ivec2 windowSize) const;

private:
    struct OverlayProgram {
        OverlayProgram();
        ShaderProgram program;
        GLint image, rect;  // uniform locations
    };

    // An RGBA image in a texture, reallocated only when its size changes.
    struct OverlayTexture {
        explicit OverlayTexture(GLint filter);
        void upload(const cv::Mat& rgba);
        GlTexture texture;
        glm::ivec2 size{0};
    };
    // Draws `overlay` over a window rectangle in pixels, its origin at the window's bottom left.
    void drawOverlay(const OverlayTexture& overlay, glm::vec2 origin, glm::vec2 size, glm::ivec2 windowSize);

    OverlayProgram program_;
    GlVertexArray vao_;
    OverlayTexture overlay_, frameOverlay_;
};

}  // namespace arcomp
