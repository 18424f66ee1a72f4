#pragma once
// What the select pass decided to draw this frame, sorted into bins in the
// order it found them:
// - items: the CG, opaque and blended (the renderer orders each by depth);
//   the frame-time controller edits level and shading in place before the
//   renderer reads them;
// - holdouts: the CG items that also cut a person out of the video
//   (graph/silhouette/HoldoutMeshes.hpp), with their depth, so that the compositor can
//   decide per person which of them stand in front;
// - pointClouds: the visible point-cloud nodes, drawn as layers after the CG.

#include "graph/core/Scene.hpp"
#include "graph/core/Shading.hpp"

#include <vector>

namespace arcomp {

struct DrawItem {
    NodeId node;  // world matrix: scene.world(node)
    MeshPart part;
    float viewDistance;  // eye to bounding-sphere centre
    float screenArea;    // projected pixels of the bounding sphere
    std::uint8_t level;  // LOD level the part came from, 0 = finest
    Shading shading;
    // Opacity during an LOD cross-fade (both levels are listed, weights
    // summing to 1); 1 otherwise.
    float fade = 1.0f;
    // A part of the geometry's index list; indexCount 0 draws all of it.
    // Silhouette nodes use it to pick their region's list.
    std::uint32_t firstIndex = 0;
    std::uint32_t indexCount = 0;
    // Grouping proxies are no scene node: they bring their own model matrix
    // (owned by the grouping table until the next select) and a colour that
    // multiplies the material's base colour, alpha included.
    const glm::mat4* model = nullptr;
    glm::vec4 tint{1.0f};
};

// A CG item with a holdout mesh. It names the item rather than holding the
// silhouette range: the controller may still move the item to a coarser
// level, whose own silhouette is then the one to draw.
struct HoldoutItem {
    std::uint32_t cgItem;  // index into DrawList::items
    float depth;           // eye to bounding-sphere centre along the view axis
};

struct PointCloudItem {
    NodeId node;
    float viewDistance;  // eye to bounding-sphere centre
};

struct DrawList {
    std::vector<DrawItem> items;
    std::vector<HoldoutItem> holdouts;
    std::vector<PointCloudItem> pointClouds;
    std::size_t nodesVisited = 0;
    std::size_t nodesCulled = 0;

    void clear() {
        items.clear();
        holdouts.clear();
        pointClouds.clear();
        nodesVisited = nodesCulled = 0;
    }
};

}  // namespace arcomp
