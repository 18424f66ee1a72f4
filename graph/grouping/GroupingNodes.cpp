#include "graph/grouping/GroupingNodes.hpp"
#include "graph/core/Check.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace arcomp {

namespace {

Geometry makeUnitQuad() {
    Geometry g;
    g.positions = {{-0.5f, -0.5f, 0.0f}, {0.5f, -0.5f, 0.0f}, {0.5f, 0.5f, 0.0f}, {-0.5f, 0.5f, 0.0f}};
    g.normals.assign(4, {0.0f, 0.0f, 1.0f});
    g.texcoords = {{0.0f, 1.0f}, {1.0f, 1.0f}, {1.0f, 0.0f}, {0.0f, 0.0f}};
    g.indices = {0, 1, 2, 0, 2, 3};
    g.finalize();
    return g;
}

float surfaceArea(const Geometry& g) {
    float area = 0.0f;
    for (std::size_t i = 0; i + 2 < g.indices.size(); i += 3) {
        const glm::vec3 a = g.positions[g.indices[i]], b = g.positions[g.indices[i + 1]],
                        c = g.positions[g.indices[i + 2]];
        area += 0.5f * glm::length(glm::cross(b - a, c - a));
    }
    return area;
}

}  // namespace

NodeId addGroupingNode(Scene& scene, NodeId parent, GroupingNodes& table, std::string name) {
    GroupingNode n;
    Material white;
    white.name = "grouping proxy";
    white.baseColor = glm::vec4(1.0f);
    white.alphaMode = AlphaMode::Blend;
    white.doubleSided = true;
    n.boxPart = {scene.addGeometry(makeBox(glm::vec3(1.0f))), scene.addMaterial(std::move(white))};
    n.quadGeometry = scene.addGeometry(makeUnitQuad());
    table.nodes.push_back(std::move(n));
    return scene.addNode(parent, NodeKind::Grouping, static_cast<std::uint32_t>(table.nodes.size() - 1),
                         std::move(name));
}

GroupingItem groupingItemOf(const Scene& scene, NodeId subtree) {
    Box box;
    glm::vec3 color{0.0f};
    float area = 0.0f;
    std::vector<NodeId> stack{subtree};
    while (!stack.empty()) {
        const NodeId n = stack.back();
        stack.pop_back();
        if (scene.kind(n) == NodeKind::Mesh) {
            const MeshPart& part = scene.meshPart(n);
            const Geometry& g = scene.geometry(part.geometry);
            if (part.skin == kNoSkin) {
                box.expand(transformed(g.box, scene.world(n)));
            } else {
                // Its joints, not its node, place a skinned mesh: the box
                // around its bound, fitted over its poses (Skinning.hpp).
                const Sphere& s = scene.worldBound(n);
                if (!s.empty()) box.expand(Box{s.center - s.radius, s.center + s.radius});
            }
            const float a = surfaceArea(g);
            color += glm::vec3(scene.material(part.material).baseColor) * a;
            area += a;
        }
        for (NodeId c : scene.children(n)) stack.push_back(c);
    }
    return groupingItem(box, area > 0.0f ? color / area : color);
}

void buildGrouping(Scene& scene, NodeId groupingNode, GroupingNodes& table, const GroupingParams& params) {
    ARCOMP_CHECK(scene.kind(groupingNode) == NodeKind::Grouping, "a grouping node");
    GroupingNode& g = table.nodes[scene.payload(groupingNode)];
    g.objects = scene.children(groupingNode);
    std::vector<GroupingItem> items;
    items.reserve(g.objects.size());
    for (NodeId o : g.objects) items.push_back(groupingItemOf(scene, o));
    g.tree.build(items, params);
    g.omegaT = params.omegaT;
    g.objectSlot.clear();
    g.impostorMaterial.clear();
    g.impostorBound.clear();
}

bool GroupingNode::impostorFits(std::uint32_t t) const {
    if (t >= impostorMaterial.size() || t >= impostorBound.size() || impostorMaterial[t] == kNoImpostor) return false;
    const Sphere& now = tree.bound(t);
    const Sphere& then = impostorBound[t];
    const float slack = 0.02f * then.radius;
    return glm::length(now.center - then.center) <= slack && std::abs(now.radius - then.radius) <= slack;
}

GroupingRebuildStats regroupMoved(const Scene& scene, NodeId groupingNode, GroupingNodes& table,
                                  std::span<const MovedObject> moved) {
    GroupingNode& g = table.nodes[scene.payload(groupingNode)];
    for (const MovedObject& m : moved) {
        ARCOMP_CHECK(m.object < g.objects.size(), "a moved object of this grouping node");
        g.tree.moveObject(m.object, groupingItemOf(scene, g.objects[m.object]).box, m.velocity);
    }
    return g.tree.rebuildMoved();
}

glm::mat4 boxProxyModel(const Box& box) {
    const glm::mat4 t = glm::translate(glm::mat4(1.0f), box.center());
    return glm::scale(t, glm::max(box.size(), glm::vec3(1e-6f)));
}

glm::mat3 billboardFrame(const glm::vec3& towardsEye) {
    const float len = glm::length(towardsEye);
    const glm::vec3 z = len > 0.0f ? towardsEye / len : glm::vec3(0.0f, 0.0f, 1.0f);
    glm::vec3 x = glm::cross(glm::vec3(0.0f, 1.0f, 0.0f), z);
    x = glm::length(x) > 1e-6f ? glm::normalize(x) : glm::vec3(1.0f, 0.0f, 0.0f);
    return {x, glm::cross(z, x), z};
}

glm::mat4 billboardModel(const Sphere& bound, const glm::vec3& eye) {
    const glm::mat3 f = billboardFrame(eye - bound.center);
    const float d = std::max(2.0f * bound.radius, 1e-6f);
    return {glm::vec4(f[0] * d, 0.0f), glm::vec4(f[1] * d, 0.0f), glm::vec4(f[2], 0.0f), glm::vec4(bound.center, 1.0f)};
}

}  // namespace arcomp
