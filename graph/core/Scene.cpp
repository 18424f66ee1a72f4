#include "graph/core/Scene.hpp"
#include "graph/core/BadInput.hpp"
#include "graph/core/Check.hpp"

#include <cstdlib>

namespace arcomp {

namespace {
// Kinds the select pass does nothing at but step down: with one child and
// no bound of their own, they give their slot to the child.
bool passesThroughKind(NodeKind k) { return k == NodeKind::Transform || k == NodeKind::Group; }
}  // namespace

Scene::Scene() { addNode(kNoNode, NodeKind::Group, 0, "root"); }

NodeId Scene::addNode(NodeId parent, NodeKind kind, std::uint32_t payload, std::string name) {
    const auto id = static_cast<NodeId>(kind_.size());
    ARCOMP_CHECK(parent == kNoNode || parent < id, "parents exist before children");
    kind_.push_back(kind);
    worldBound_.push_back({});
    world_.emplace_back(1.0f);
    payload_.push_back(payload);
    parent_.push_back(parent);
    firstChild_.push_back(kNoNode);
    lastChild_.push_back(kNoNode);
    nextSibling_.push_back(kNoNode);
    local_.emplace_back(1.0f);
    localBound_.push_back({});
    localDirty_.push_back(1);
    name_.push_back(std::move(name));
    if (parent != kNoNode) {
        if (lastChild_[parent] == kNoNode)
            firstChild_[parent] = id;
        else
            nextSibling_[lastChild_[parent]] = id;
        lastChild_[parent] = id;
    }
    structureDirty_ = true;
    anyLocalDirty_ = true;
    return id;
}

NodeId Scene::addGroup(NodeId parent, std::string name) { return addNode(parent, NodeKind::Group, 0, std::move(name)); }

NodeId Scene::addTransform(NodeId parent, const glm::mat4& local, std::string name) {
    const NodeId id = addNode(parent, NodeKind::Transform, 0, std::move(name));
    local_[id] = local;
    return id;
}

NodeId Scene::addMesh(NodeId parent, MeshPart part, std::string name) {
    ARCOMP_CHECK(part.geometry < geometries_.size() && part.material < materials_.size(),
                 "a mesh part's geometry and material are in the scene");
    meshParts_.push_back(part);
    const NodeId id =
        addNode(parent, NodeKind::Mesh, static_cast<std::uint32_t>(meshParts_.size() - 1), std::move(name));
    localBound_[id] = geometries_[part.geometry].bound;
    return id;
}

std::uint32_t Scene::addGeometry(Geometry g) {
    geometries_.push_back(std::move(g));
    return static_cast<std::uint32_t>(geometries_.size() - 1);
}

std::uint32_t Scene::addMaterial(Material m) {
    materials_.push_back(std::move(m));
    return static_cast<std::uint32_t>(materials_.size() - 1);
}

std::uint32_t Scene::addImage(Image i) {
    images_.push_back(std::move(i));
    return static_cast<std::uint32_t>(images_.size() - 1);
}

std::uint32_t Scene::addSkin(NodeId mesh, std::span<const NodeId> joints, std::span<const glm::mat4> inverseBinds) {
    ARCOMP_CHECK(mesh < kind_.size() && joints.size() == inverseBinds.size(),
                 "a skin's mesh node exists and each joint has an inverse bind matrix");
    for (const NodeId j : joints) ARCOMP_CHECK(j == kNoNode || j < kind_.size(), "a skin's joints are in the scene");
    skinMesh_.push_back(mesh);
    jointNode_.insert(jointNode_.end(), joints.begin(), joints.end());
    inverseBind_.insert(inverseBind_.end(), inverseBinds.begin(), inverseBinds.end());
    jointMatrix_.resize(jointNode_.size(), glm::mat4(1.0f));
    skinFirst_.push_back(static_cast<std::uint32_t>(jointNode_.size()));
    anyLocalDirty_ = true;  // the next update() works out its joint matrices
    return static_cast<std::uint32_t>(skinMesh_.size() - 1);
}

std::span<const NodeId> Scene::skinJoints(std::uint32_t skin) const {
    return std::span<const NodeId>(jointNode_).subspan(skinFirst_[skin], skinFirst_[skin + 1] - skinFirst_[skin]);
}

std::span<const glm::mat4> Scene::jointMatrices(std::uint32_t skin) const {
    return std::span<const glm::mat4>(jointMatrix_).subspan(skinFirst_[skin], skinFirst_[skin + 1] - skinFirst_[skin]);
}

// glTF 2.0, 3.7.3 (skins): the joints' world transforms place a skinned mesh
// and the mesh node's own is ignored. As the Khronos glTF tutorial on skins
// writes it: jointMatrix(j) = inverse(globalTransform(mesh node)) *
// globalTransform(joint j) * inverseBindMatrix(j); the renderer's model
// matrix, the mesh node's world, then cancels the first factor.
void Scene::updateJointMatrices() {
    for (std::size_t s = 0; s < skinMesh_.size(); ++s) {
        const glm::mat4 toMesh = glm::inverse(world_[skinMesh_[s]]);
        for (std::uint32_t j = skinFirst_[s]; j < skinFirst_[s + 1]; ++j)
            jointMatrix_[j] =
                jointNode_[j] == kNoNode ? glm::mat4(1.0f) : toMesh * world_[jointNode_[j]] * inverseBind_[j];
    }
}

void Scene::setLocalBound(NodeId node, const Sphere& bound) {
    // A transform or group with a bound of its own may no longer share its
    // child's slot (rebuildSiblingLayout).
    if (passesThroughKind(kind_[node])) structureDirty_ = true;
    localBound_[node] = bound;
    localDirty_[node] = 1;
    anyLocalDirty_ = true;
}

void Scene::setLocal(NodeId node, const glm::mat4& local) {
    local_[node] = local;
    localDirty_[node] = 1;
    anyLocalDirty_ = true;
}

std::vector<NodeId> Scene::children(NodeId n) const {
    std::vector<NodeId> out;
    for (NodeId c = firstChild_[n]; c != kNoNode; c = nextSibling_[c]) out.push_back(c);
    return out;
}

void Scene::rebuildOrder() {
    order_.clear();
    order_.reserve(kind_.size());
    subtreeEnd_.assign(kind_.size(), 0);
    // Iterative pre-order walk; a node's subtree ends where the walk next
    // leaves it, which is when its position's end is filled in.
    std::vector<std::pair<NodeId, std::uint32_t>> stack;  // node, its position
    stack.push_back({root(), 0});
    order_.push_back(root());
    NodeId next = firstChild_[root()];
    while (!stack.empty()) {
        if (next != kNoNode) {
            const auto pos = static_cast<std::uint32_t>(order_.size());
            order_.push_back(next);
            stack.push_back({next, pos});
            next = firstChild_[next];
        } else {
            const auto [node, pos] = stack.back();
            stack.pop_back();
            subtreeEnd_[pos] = static_cast<std::uint32_t>(order_.size());
            next = nextSibling_[node];
            if (stack.empty()) break;
        }
    }
    structureDirty_ = false;
    rebuildSiblingLayout();
}

// A node's children take consecutive slots when the depth-first walk
// reaches the node: each run of siblings is one stretch of every array, and
// an object's own subtree follows soon after the run that holds it. Bounds
// are filled in by update(), which recomputes them all after a change of
// structure.
//
// A transform or group with one child and no bound of its own tells the
// walk nothing: its world bound is its child's, and world matrices are
// already applied. Its child takes its slot, so a typical object (transform
// over an LOD node over levels) costs the walk one hop less. A grouping
// node's objects keep their own slots: its tree names them.
void Scene::rebuildSiblingLayout() {
    const auto passesThrough = [this](NodeId n) {
        return passesThroughKind(kind_[n]) && firstChild_[n] != kNoNode && nextSibling_[firstChild_[n]] == kNoNode &&
               localBound_[n].empty();
    };
    layout_.slots.assign(order_.size(), {{glm::vec3(0.0f), -1.0f}, kNoNode, 0, 0, 0, NodeKind::Group});
    layout_.slotOf.assign(kind_.size(), ~std::uint32_t{0});  // nodes outside the root's tree have none
    std::vector<std::uint8_t> elided(kind_.size(), 0);
    layout_.slotOf[root()] = 0;
    std::uint32_t next = 1;
    for (const NodeId n : order_) {
        if (elided[n]) continue;
        SiblingLayout::Slot& slot = layout_.slots[layout_.slotOf[n]];
        slot.kind = kind_[n];
        slot.payload = payload_[n];
        slot.node = n;
        slot.firstChild = next;
        const bool elide = kind_[n] != NodeKind::Grouping;
        for (NodeId c = firstChild_[n]; c != kNoNode; c = nextSibling_[c]) {
            // Every node of the chain shares the slot: update() writes each
            // one's bound there, all equal, the deepest's first.
            NodeId d = c;
            for (; elide && passesThrough(d); d = firstChild_[d]) {
                elided[d] = 1;
                layout_.slotOf[d] = next;
            }
            layout_.slotOf[d] = next++;
        }
        if (next - slot.firstChild > SiblingLayout::kMaxChildren)
            throw BadInput("scene", "node " + std::to_string(n),
                           std::to_string(next - slot.firstChild) + " children; the select pass takes at most " +
                               std::to_string(SiblingLayout::kMaxChildren) + " under one node: group them");
        slot.childCount = next - slot.firstChild;
    }
    layout_.slots.resize(next);
    layout_.centerX.assign(next, 0.0f);
    layout_.centerY.assign(next, 0.0f);
    layout_.centerZ.assign(next, 0.0f);
    layout_.radius.assign(next, -1.0f);
}

void Scene::update() {
    const bool structureChanged = structureDirty_;
    if (structureChanged) rebuildOrder();
    if (!anyLocalDirty_ && !structureChanged) return;

    // Top-down: a world matrix changes when its local or its parent's world did.
    std::vector<std::uint8_t> changed(kind_.size(), 0);
    for (NodeId n : order_) {
        const NodeId p = parent_[n];
        const bool parentChanged = p != kNoNode && changed[p];
        if (!localDirty_[n] && !parentChanged) continue;
        world_[n] = p == kNoNode ? local_[n] : world_[p] * local_[n];
        changed[n] = 1;
        localDirty_[n] = 0;
    }
    // Bottom-up: bounds of changed nodes, then of every ancestor above them.
    for (auto it = order_.rbegin(); it != order_.rend(); ++it) {
        const NodeId n = *it;
        if (!changed[n] && !structureChanged) continue;
        Sphere s = transformed(localBound_[n], world_[n]);
        for (NodeId c = firstChild_[n]; c != kNoNode; c = nextSibling_[c]) s = merged(s, worldBound_[c]);
        worldBound_[n] = s;
        layout_.setBound(layout_.slotOf[n], s);
        if (parent_[n] != kNoNode) changed[parent_[n]] = 1;
    }
    updateJointMatrices();
    anyLocalDirty_ = false;
}

}  // namespace arcomp
