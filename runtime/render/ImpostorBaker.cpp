#include "runtime/render/ImpostorBaker.hpp"

#include "runtime/gl/RenderTarget.hpp"
#include "runtime/render/Renderer.hpp"

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

// Orthographic around the sphere, in the frame the billboard will have.
View bakeView(const Sphere& bound, const glm::vec3& towardsEye, glm::ivec2 pixels) {
    const glm::mat3 f = billboardFrame(towardsEye);
    const float r = std::max(bound.radius, 1e-6f);
    View v;
    v.eye = bound.center + f[2] * (r + 1.0f);
    v.forward = -f[2];
    v.view = glm::lookAt(v.eye, bound.center, f[1]);
    v.near = 0.5f;
    v.far = 2.0f * r + 1.5f;
    v.projection = glm::ortho(-r, r, -r, r, v.near, v.far);
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

}  // namespace

std::size_t bakeImpostors(Scene& scene, NodeId groupingNode, GroupingNodes& table,
                          const ImpostorBakeSettings& settings) {
    GroupingNode& g = table.nodes[scene.payload(groupingNode)];
    const GroupingTree& tree = g.tree;
    g.impostorMaterial.assign(tree.nodeCount(), GroupingNode::kNoImpostor);
    g.impostorBound.assign(tree.nodeCount(), Sphere{});
    std::size_t baked = 0;
    Renderer renderer;
    for (std::uint32_t t = 0; t < tree.nodeCount(); ++t) {
        if (!tree.alive(t) || tree.isLeaf(t)) continue;
        const Sphere& bound = tree.bound(t);
        const int side = std::clamp(int(std::lround(2.0f * bound.radius * settings.pixelsPerUnit)), settings.minPixels,
                                    settings.maxPixels);
        const glm::vec3 towardsEye = settings.eye ? *settings.eye - bound.center : glm::vec3(0.0f, 0.0f, 1.0f);
        const View view = bakeView(bound, towardsEye, {side, side});
        DrawList list;
        std::vector<NodeId> meshes;
        for (std::uint32_t o : tree.objectsUnder(t)) finestMeshes(scene, g.objects[o], meshes);
        for (NodeId m : meshes)
            list.items.push_back(
                {m, scene.meshPart(m), glm::length(scene.worldBound(m).center - view.eye), 0.0f, 0, Shading::Phong});
        RenderTarget target({side, side});
        target.bind();
        renderer.draw(scene, list, view, {.clearColor = glm::vec4(0.0f)});
        Image img = target.read();
        unpremultiply(img);
        Material m;
        m.name = "impostor";
        m.baseColorTexture.image = static_cast<int>(scene.addImage(std::move(img)));
        m.alphaMode = AlphaMode::Blend;
        m.unlit = true;
        m.doubleSided = true;
        g.impostorMaterial[t] = scene.addMaterial(std::move(m));
        g.impostorBound[t] = bound;
        ++baked;
    }
    return baked;
}

std::size_t bakeImpostors(Scene& scene, GroupingNodes& table, const glm::vec3& eye) {
    std::size_t baked = 0;
    for (NodeId n = 0; n < scene.nodeCount(); ++n) {
        if (scene.kind(n) != NodeKind::Grouping || scene.payload(n) >= table.nodes.size()) continue;
        const GroupingNode& g = table.nodes[scene.payload(n)];
        if (g.proxy == GroupingProxy::Impostor)
            baked += bakeImpostors(scene, n, table, {.pixelsPerUnit = g.impostorPixelsPerUnit, .eye = eye});
    }
    return baked;
}

}  // namespace arcomp
