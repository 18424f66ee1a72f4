#pragma once
// Joins the video and the CG into one frame, in one target, with no
// full-screen shader pass: llvmpipe pays about 10 ms for every full-screen
// pass at 1080p, so only the pixels that need work get it.
//   1. begin(): the video frame is uploaded straight into the output's
//      colour texture as the backdrop (or the backdrop colour is cleared);
//      depth and stencil are cleared.
//   2. The caller draws all CG into output() (Renderer, no clear): CG is
//      over the backdrop, nearer CG over farther by depth.
//   3. beginHoldout() ... endHoldout(): the caller draws the objects that may
//      stand in front of someone with their silhouette meshes; they only
//      write depth (the CG's depth is cleared first), colour stays.
//   4. person(): the person layer (video x matte, premultiplied) is drawn
//      "over" everything, each pixel at its person's depth, except where
//      the holdout is nearer; only on the tiles where the matte has any alpha.
// Result: each person over the CG behind them; CG wherever it is nearer
// than the person it covers.
//
//   Compositor c({768, 576});
//   c.begin(frame, {});                                 // BGR, video size
//   renderer.draw(scene, cgList, view, {.clearColor = std::nullopt});
//   c.beginHoldout(); holdoutRenderer.draw(holdoutScene, frontList, view, {.clearColor = std::nullopt});
//   c.endHoldout(); c.person(personBgra, depths, view.projection);      // premultiplied BGRA Image img =
//   c.output().read();                      // or sample c.output().colorTexture() in a window
//
// Colour: everything is blended as premultiplied RGBA in the sRGB-encoded
// (gamma) space the video arrives in and the renderer writes (it lights in
// linear and encodes once). Blending encoded values is what broadcast keyers
// do; it keeps the matte's edge as the matte computed it and costs no
// decode/encode per pixel, at the price of slightly dark soft edges between
// very different colours.

#include "runtime/composite/PersonDepths.hpp"
#include "runtime/gl/GlHandle.hpp"
#include "runtime/gl/RenderTarget.hpp"
#include "runtime/gl/ShaderProgram.hpp"

#include <opencv2/core/mat.hpp>

#include <cstdint>
#include <optional>
#include <vector>

namespace arcomp {

// The tiles of a person layer that hold any of it, which is all that
// Compositor::person draws and uploads. Found again into the same value
// each frame, which keeps its buffers.
struct PersonTiles {
    std::vector<std::uint8_t> occupied;  // per tile, row by row from the top (tileGrid)
    std::vector<float> quads;            // the occupied tiles as quads (TileQuads), two triangles each, NDC x, y
    std::size_t count = 0;
    glm::ivec2 rows{0};  // the image rows [x, y) the occupied tiles cover
};

struct CompositeSettings {
    bool backdropVideo = true;
    glm::vec4 backdropColor{0.0f, 0.0f, 0.0f, 1.0f};  // straight RGBA, used as given
};

class Compositor {
public:
    // Person tiles are this many pixels square: at 8 the pass draws about a
    // quarter fewer pixels of a walking person than at 32 (1080p), and
    // TileQuads keeps the triangles few.
    static constexpr int kTile = 8;

    explicit Compositor(glm::ivec2 size);
    Compositor(const Compositor&) = delete;
    Compositor& operator=(const Compositor&) = delete;

    // The video frame as the output's colour texture takes it: RGBA, rows
    // bottom first. A pipelined station makes it on its capture thread, so
    // that the frame's own thread only uploads it. `frame`: CV_8UC3 BGR.
    static void makePlate(const cv::Mat& frame, cv::Mat& plate);
    // `frame`: CV_8UC3 BGR at size(). Leaves output() bound.
    void begin(const cv::Mat& frame, const CompositeSettings& settings);
    // begin() with the frame's plate from makePlate.
    void beginWithPlate(const cv::Mat& plate, const CompositeSettings& settings);
    void beginHoldout();
    void endHoldout();
    // `person`: CV_8UC4 premultiplied BGRA at size(). `projection`: the
    // view's, to place each person's depth among the holdout's.
    void person(const cv::Mat& person, const PersonDepths& depths, const glm::mat4& projection);
    // person() with the layer's tiles from findTiles, which a pipelined
    // station finds on its capture thread.
    void person(const cv::Mat& person, const PersonTiles& tiles, const PersonDepths& depths,
                const glm::mat4& projection);
    // The kTile-square tiles where `person` (premultiplied BGRA) has alpha,
    // into `tiles` (its buffers are reused); none for an image of another type.
    static void findTiles(const cv::Mat& person, PersonTiles& tiles);

    // The composited frame: a texture a window can sample or blit from.
    const RenderTarget& output() const { return output_; }
    glm::ivec2 size() const { return size_; }
    // Tiles the person layer was drawn on, last frame.
    std::size_t personTiles() const { return tileCount_; }

private:
    void uploadSlots(const PersonDepths& depths);

    struct PersonProgram {
        PersonProgram();
        ShaderProgram program;
        GLint person, slots, slotScale, height, depth;  // uniform locations
    };

    glm::ivec2 size_;
    RenderTarget output_;
    cv::Mat plate_;  // begin()'s plate
    GlTexture personTexture_;
    GlVertexArray tileVao_;
    GlBuffer tileBuffer_;
    PersonTiles ownTiles_;  // person()'s, when it finds them itself
    std::size_t tileCount_ = 0;
    GlTexture slotTexture_;
    glm::ivec2 slotSize_{0};
    PersonProgram program_;
};

}  // namespace arcomp
