#pragma once
// What the select pass decided to draw this frame, in the order it found it.
// The frame-time controller edits level and shading in place before the
// renderer reads the list.

#include "graph/Scene.hpp"
#include "graph/Shading.hpp"

#include <vector>

namespace arcomp {

struct DrawItem {
    NodeId node;           // world matrix: scene.world(node)
    MeshPart part;
    float viewDistance;    // eye to bounding-sphere centre
    float screenArea;      // projected pixels of the bounding sphere
    std::uint8_t level;    // LOD level the part came from, 0 = finest
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

struct DrawList {
    std::vector<DrawItem> items;
    std::size_t nodesVisited = 0;
    std::size_t nodesCulled = 0;

    void clear() { items.clear(); nodesVisited = nodesCulled = 0; }
};

} // namespace arcomp
