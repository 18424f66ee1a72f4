#pragma once
// Shows the scene's PointCloud nodes as layers over the CG: each visible
// cloud is rendered on the CPU by its LdiRenderer (McMillan order, merge
// of its LDIs), uploaded as a premultiplied texture with its depth image,
// and drawn over the bound framebuffer with "over", depth-tested against
// what the Renderer left in the depth buffer.
//
//   renderer.draw(scene, list, view, settings);                // CG first
//   layer.draw(scene, clouds, list.pointClouds, view);         // then the clouds the select pass found
//
// Depth: every layer pixel carries the view depth of the nearest point
// drawn there, written as gl_FragDepth. A CG surface in front of that
// point hides the pixel; one behind it shows through the cloud's
// translucency. A CG surface between a pixel's points is treated as behind
// all of them: one depth per pixel is as well as a flat image can do.
// The layer writes no depth, so clouds are drawn after all CG, blended CG
// included, and farthest cloud first.
//
// A cloud under a transform is drawn with the view taken into its local
// space; the transform must be rigid with a uniform scale.

#include "graph/core/DrawList.hpp"
#include "graph/core/View.hpp"
#include "graph/points/LdiRenderer.hpp"
#include "graph/points/PointCloudNodes.hpp"
#include "runtime/gl/GlHandle.hpp"
#include "runtime/gl/ShaderProgram.hpp"

#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace arcomp {

class PointCloudLayer {
public:
    explicit PointCloudLayer(int threads = 2);
    PointCloudLayer(const PointCloudLayer&) = delete;
    PointCloudLayer& operator=(const PointCloudLayer&) = delete;

    // Needs a current context. `visible`: the select pass's point-cloud bin.
    void draw(const Scene& scene, const PointCloudNodes& clouds, std::span<const PointCloudItem> visible,
              const View& view);

    std::size_t cloudsDrawn() const { return cloudsDrawn_; }
    std::size_t splatsDrawn() const { return splatsDrawn_; }

private:
    LdiRenderer& rendererFor(const LdiSet& set);

    struct LayerProgram {
        LayerProgram();
        ShaderProgram program;
        GLint color, depth;  // uniform locations
    };

    int threads_;
    LayerProgram program_;
    GlVertexArray vao_;
    GlTexture color_, depth_;
    glm::ivec2 textureSize_{0, 0};
    std::vector<std::pair<const LdiSet*, std::unique_ptr<LdiRenderer>>> renderers_;
    std::vector<PointCloudItem> farthestFirst_;
    std::vector<float> ndcDepth_;
    std::size_t cloudsDrawn_ = 0, splatsDrawn_ = 0;
};

}  // namespace arcomp
