#pragma once
// Joins the video and the CG into one frame, on the GPU, in one full-screen
// pass. Its inputs, each in its own texture at the output size:
//   - the backdrop: the video frame (or a colour);
//   - the CG: every object, shaded, with depth (Renderer into cgTarget());
//   - the person layer: video x matte, premultiplied, at full resolution;
//   - the holdout mask: the objects in front of the person plane drawn with
//     their silhouette meshes (cheap, coverage only) into holdoutTarget().
// Per pixel: person' = person * (1 - holdout);
//            out = person' over (CG over backdrop).
// So the person covers CG behind it, and CG in front shows through the hole
// the holdout cut; CG in front was already on top of CG behind by depth.
//
//   Compositor c({768, 576});
//   c.uploadVideo(frame, person);                 // BGR and premultiplied BGRA
//   c.cgTarget().bind();      renderer.draw(...);  // all CG
//   c.holdoutTarget().bind(); holdoutRenderer.draw(...);  // front objects, white
//   c.composite();                                // into output()
//   Image img = c.output().read();
//
// Colour: everything is blended as premultiplied RGBA in the sRGB-encoded
// (gamma) space the video arrives in and the renderer writes (it lights in
// linear and encodes once). Blending encoded values is what broadcast keyers
// do; it keeps the matte's edge exactly as the matte computed it and costs
// no decode/encode per pixel, at the price of slightly dark soft edges
// against very different colours.

#include "runtime/RenderTarget.hpp"
#include "runtime/ShaderProgram.hpp"

#include <opencv2/core/mat.hpp>

#include <optional>

namespace arcomp {

struct CompositeSettings {
    bool backdropVideo = true;
    glm::vec4 backdropColor{0.0f, 0.0f, 0.0f, 1.0f};  // linear-valued like config colours; used as given
};

class Compositor {
public:
    explicit Compositor(glm::ivec2 size);
    ~Compositor();
    Compositor(const Compositor&) = delete;
    Compositor& operator=(const Compositor&) = delete;

    // `frame` CV_8UC3 BGR, `person` CV_8UC4 premultiplied BGRA, both at size().
    void uploadVideo(const cv::Mat& frame, const cv::Mat& person);
    RenderTarget& cgTarget() { return cg_; }
    RenderTarget& holdoutTarget() { return holdout_; }
    // Runs the full-screen pass into output().
    void composite(const CompositeSettings& settings);
    // The composited frame: a texture a window can sample or blit from.
    const RenderTarget& output() const { return output_; }
    glm::ivec2 size() const { return size_; }

private:
    glm::ivec2 size_;
    RenderTarget cg_, holdout_, output_;
    GLuint frameTexture_ = 0, personTexture_ = 0, vao_ = 0;
    std::optional<ShaderProgram> program_;
};

} // namespace arcomp
