#include "runtime/ImpostorBaker.hpp"

#include "runtime/RenderTarget.hpp"
#include "runtime/Renderer.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace arcomp {

namespace {

// The meshes of a subtree at its finest level: an LOD node contributes its
// first child only.
void finestMeshes(const Scene& scene, NodeId n, std::vector<NodeId>& out) {
    if (scene.kind(n) == NodeKind::Mesh) out.push_back(n);
    const std::vector<NodeId> children = scene.children(n);
    if (scene.kind(n) == NodeKind::Lod) {
        if (!children.empty()) finestMeshes(scene, children.front(), out);
        return;
    }
    for (NodeId c : children) finestMeshes(scene, c, out);
}

View frontView(const Box& box, glm::ivec2 pixels) {
    const glm::vec3 c = box.center(), s = box.size();
    const float w = std::max(s.x, s.z), h = s.y;
    const float depth = std::max(s.z, s.x) + 1.0f;
    View v;
    v.eye = c + glm::vec3(0.0f, 0.0f, depth);
    v.forward = {0.0f, 0.0f, -1.0f};
    v.view = glm::lookAt(v.eye, c, {0.0f, 1.0f, 0.0f});
    v.near = 0.01f;
    v.far = 2.0f * depth;
    v.projection = glm::ortho(-0.5f * w, 0.5f * w, -0.5f * h, 0.5f * h, v.near, v.far);
    v.viewport = pixels;
    return v;
}

// The renderer writes premultiplied colour; a texture holds straight colour.
void unpremultiply(Image& img) {
    for (std::size_t i = 0; i + 3 < img.rgba.size(); i += 4) {
        const int a = img.rgba[i + 3];
        if (a == 0 || a == 255) continue;
        for (std::size_t k = 0; k < 3; ++k) img.rgba[i + k] = std::uint8_t(std::min(255, img.rgba[i + k] * 255 / a));
    }
}

} // namespace

std::size_t bakeImpostors(Scene& scene, NodeId groupingNode, GroupingNodes& table, const ImpostorBakeSettings& settings) {
    GroupingNode& g = table.nodes[scene.payload(groupingNode)];
    const GroupingTree& tree = g.tree;
    g.impostorMaterial.assign(tree.nodeCount(), GroupingNode::kNoImpostor);
    std::size_t baked = 0;
    Renderer renderer;
    for (std::uint32_t t = 0; t < tree.nodeCount(); ++t) {
        if (!tree.alive(t) || tree.isLeaf(t)) continue;
        const Box& box = tree.item(t).box;
        const glm::vec3 s = box.size();
        const auto side = [&](float units) {
            return std::clamp(int(std::lround(units * settings.pixelsPerUnit)), settings.minPixels, settings.maxPixels);
        };
        const glm::ivec2 pixels{side(std::max(s.x, s.z)), side(s.y)};
        const View view = frontView(box, pixels);
        DrawList list;
        std::vector<NodeId> meshes;
        for (std::uint32_t o : tree.objectsUnder(t)) finestMeshes(scene, g.objects[o], meshes);
        for (NodeId m : meshes)
            list.items.push_back({m, scene.meshPart(m), glm::length(scene.worldBound(m).center - view.eye), 0.0f, 0,
                                  Shading::Phong});
        RenderTarget target(pixels);
        target.bind();
        renderer.draw(scene, list, view, {.clearColor = glm::vec4(0.0f)});
        Image img = target.read();
        unpremultiply(img);
        Material m;
        m.name = "impostor";
        m.baseColorImage = static_cast<int>(scene.addImage(std::move(img)));
        m.alphaMode = AlphaMode::Blend;
        m.unlit = true;
        m.doubleSided = true;
        g.impostorMaterial[t] = scene.addMaterial(std::move(m));
        ++baked;
    }
    return baked;
}

std::size_t bakeImpostors(Scene& scene, GroupingNodes& table) {
    std::size_t baked = 0;
    for (NodeId n = 0; n < scene.nodeCount(); ++n) {
        if (scene.kind(n) != NodeKind::Grouping || scene.payload(n) >= table.nodes.size()) continue;
        const GroupingNode& g = table.nodes[scene.payload(n)];
        if (g.proxy == GroupingProxy::Impostor)
            baked += bakeImpostors(scene, n, table, {.pixelsPerUnit = g.impostorPixelsPerUnit});
    }
    return baked;
}

} // namespace arcomp
