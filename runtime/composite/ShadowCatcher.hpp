#pragma once
// Contact shadows on the video (a "shadow catcher"): the CG's objects
// darken the real floor where they keep the light from it, so that they
// stand on the place rather than float over it. Each object is flattened
// onto the floor (y = 0) along the light into a quarter-size coverage mask;
// the video is then multiplied by 1 - strength x the mask, blurred a few
// pixels, and only on the 8-pixel tiles that an object's shadow rectangle
// on screen touches (llvmpipe pays about 10 ms for a full-screen pass at
// 1080p, and objects spread over the floor leave most of it between them).
// On a software rasterizer the mask is also read back when it is drawn, and
// only the tiles it reaches are shaded: elsewhere the shade is exactly 1.
// A GPU shades the rectangles instead of waiting for the mask.
//
//   ShadowCatcher shadows(videoSize);
//   compositor.begin(frame, {});
//   shadows.cast(scene, cgList, view, cfg.compositor.shadow, renderer, compositor.output());
//   renderer.draw(scene, cgList, view, {.clearColor = std::nullopt});   // the CG over its shadow
//
// Only the floor catches shadows: a shadow reaching a wall or a person in
// the video is drawn where the floor behind them would be.

#include "graph/core/DrawList.hpp"
#include "graph/core/Scene.hpp"
#include "graph/core/View.hpp"
#include "runtime/config/CompositingConfig.hpp"
#include "runtime/gl/RenderTarget.hpp"
#include "runtime/gl/ShaderProgram.hpp"
#include "runtime/render/Renderer.hpp"

#include <vector>

namespace arcomp {

class ShadowCatcher {
public:
    // Which tiles are shaded: those under the shadows' rectangles, or only
    // those the mask reaches (Auto: the mask's on a software rasterizer).
    enum class Tiles { Auto, Rectangles, Mask };
    explicit ShadowCatcher(glm::ivec2 size, Tiles tiles = Tiles::Auto);
    ShadowCatcher(const ShadowCatcher&) = delete;
    ShadowCatcher& operator=(const ShadowCatcher&) = delete;

    // Darkens `output` (the video backdrop) under the shadows of `cg`'s items.
    void cast(const Scene& scene, const DrawList& cg, const View& view, const ShadowConfig& shadow, Renderer& renderer,
              const RenderTarget& output);
    // Pixels of the output the last cast() darkened at most (its tiles).
    std::size_t pixelsCovered() const { return pixels_; }
    // Times the mask was drawn; it is kept while the objects and the view stay.
    std::size_t masksDrawn() const { return masksDrawn_; }

private:
    struct ApplyProgram {
        ApplyProgram();
        ShaderProgram program;
        GLint mask, texel, outputSize, strength;  // uniform locations
    };

    // What the mask was drawn from.
    struct MaskKey {
        std::uint32_t geometry, material, firstIndex, indexCount;
        float fade;  // a fading item covers less
        glm::mat4 model;
        bool operator==(const MaskKey&) const = default;
    };

    struct Rectangle {
        glm::ivec2 from, to;  // window pixels [from, to), rows from the bottom
    };
    // The tiles under rectangles_, in covered_.
    void coverRectangles(glm::ivec2 size);
    // maskTiles_ from the mask as drawn: the tiles whose blur reaches a texel it covers.
    void findMaskTiles(glm::ivec2 size);
    // covered_ as quads in tiles_, and their pixels.
    void buildQuads(glm::ivec2 size);

    RenderTarget mask_;
    std::vector<MaskKey> maskKey_;
    glm::mat4 maskViewProjection_{0.0f};
    std::size_t masksDrawn_ = 0;
    DrawList flattened_;
    std::vector<glm::mat4> models_;
    std::vector<Rectangle> rectangles_;
    bool tilesFromMask_;
    Image maskImage_;
    std::vector<std::uint8_t> maskTiles_;  // per tile, rows from the bottom: 1 where the mask's blur reaches
    std::vector<std::uint8_t> covered_;    // per tile, rows from the bottom
    std::vector<float> tiles_;             // two triangles per quad of covered tiles, NDC x, y
    GlVertexArray tileVao_;
    GlBuffer tileBuffer_;
    ApplyProgram apply_;
    std::size_t pixels_ = 0;
};

// The projection of every point onto the floor (y = 0) along `light`
// (towards the light, y > 0): where its shadow falls.
glm::mat4 floorShadowMatrix(const glm::vec3& light);

}  // namespace arcomp
