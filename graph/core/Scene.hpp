#pragma once
// The scene graph. Nodes are rows in flat arrays indexed by NodeId. In
// depth-first order a node's subtree is the contiguous range [position,
// subtreeEnd). The select pass walks a copy of the hot data in which each
// node's children are contiguous instead (siblingLayout()): skipping a
// culled subtree is not reading it, and no node is reached through a
// pointer.
//
//   Scene scene;
//   NodeId t = scene.addTransform(scene.root(), glm::translate(...));
//   scene.addMesh(t, {scene.addGeometry(std::move(g)), scene.addMaterial({})});
//   scene.update();   // world matrices and bounds of what changed
//
// Later node kinds (LOD, grouping tree, silhouette region, point cloud) keep
// their own data in side tables addressed by payload(node).

#include "graph/core/Bounds.hpp"
#include "graph/core/Geometry.hpp"
#include "graph/core/Material.hpp"
#include "graph/core/NodeKind.hpp"
#include "graph/core/SiblingLayout.hpp"

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace arcomp {

// No skin: a mesh part drawn rigidly with its node's world matrix.
inline constexpr std::uint32_t kNoSkin = ~std::uint32_t{0};

// A primitive to draw: one geometry with one material, and the scene skin
// that poses it (addSkin) when the geometry has joints and weights.
struct MeshPart {
    std::uint32_t geometry;
    std::uint32_t material;
    std::uint32_t skin = kNoSkin;
};

class Scene {
public:
    Scene();

    NodeId root() const { return 0; }
    NodeId addGroup(NodeId parent, std::string name = {});
    NodeId addTransform(NodeId parent, const glm::mat4& local, std::string name = {});
    NodeId addMesh(NodeId parent, MeshPart part, std::string name = {});
    // For node kinds defined elsewhere in graph/: payload indexes their table.
    NodeId addNode(NodeId parent, NodeKind kind, std::uint32_t payload, std::string name = {});

    std::uint32_t addGeometry(Geometry g);
    std::uint32_t addMaterial(Material m);
    std::uint32_t addImage(Image i);
    // A skin placed in the scene (glTF 2.0, 3.7.3 Skins): `joints` are the
    // nodes whose world matrices pose the vertices, one inverse bind matrix
    // each (kNoNode: a joint outside the scene, which leaves its vertices
    // in the bind pose); `mesh` is the node that holds the skinned mesh,
    // whose own transform the joints replace. A MeshPart names the result.
    std::uint32_t addSkin(NodeId mesh, std::span<const NodeId> joints, std::span<const glm::mat4> inverseBinds);

    void setLocal(NodeId node, const glm::mat4& local);
    // The bounds of a node's own content in its local space (a mesh's is its
    // geometry's); the world bound merges it with the children's.
    void setLocalBound(NodeId node, const Sphere& bound);
    // Recomputes the traversal order if nodes were added, then the world
    // matrices and bounds of what changed since the last call.
    void update();

    std::size_t nodeCount() const { return kind_.size(); }
    NodeKind kind(NodeId n) const { return kind_[n]; }
    NodeId parent(NodeId n) const { return parent_[n]; }
    const std::string& name(NodeId n) const { return name_[n]; }
    std::uint32_t payload(NodeId n) const { return payload_[n]; }
    const MeshPart& meshPart(NodeId n) const { return meshParts_[payload_[n]]; }
    // A mesh node's part by its payload, for walks that already hold it.
    const MeshPart& meshPartAt(std::uint32_t payload) const { return meshParts_[payload]; }
    const glm::mat4& local(NodeId n) const { return local_[n]; }
    const glm::mat4& world(NodeId n) const { return world_[n]; }
    const Sphere& localBound(NodeId n) const { return localBound_[n]; }
    const Sphere& worldBound(NodeId n) const { return worldBound_[n]; }
    std::vector<NodeId> children(NodeId n) const;

    // Depth-first order after update(): order()[p] is the node at position p,
    // subtreeEnd()[p] the position just past its subtree.
    std::span<const NodeId> order() const { return order_; }
    std::span<const std::uint32_t> subtreeEnd() const { return subtreeEnd_; }
    // After update(): the select pass's copy of kinds, payloads and world
    // bounds, with each node's children side by side (SiblingLayout.hpp).
    const SiblingLayout& siblingLayout() const { return layout_; }

    const std::vector<Geometry>& geometries() const { return geometries_; }
    const std::vector<Material>& materials() const { return materials_; }
    const std::vector<Image>& images() const { return images_; }
    const Geometry& geometry(std::uint32_t i) const { return geometries_[i]; }
    const Material& material(std::uint32_t i) const { return materials_[i]; }

    std::size_t skinCount() const { return skinMesh_.size(); }
    std::span<const NodeId> skinJoints(std::uint32_t skin) const;
    // After update(): per joint, the matrix (Scene.cpp) that takes a vertex
    // in the mesh node's space to where joint j puts it, in the same space;
    // the renderer then applies the mesh node's world matrix as for any mesh.
    std::span<const glm::mat4> jointMatrices(std::uint32_t skin) const;

    // Bounds of everything under the root; empty when nothing is.
    Sphere bound() const { return worldBound_[0]; }

private:
    void rebuildOrder();
    void rebuildSiblingLayout();

    // Per node. The select pass reads layout_, a copy of what it needs laid
    // out for its walk, and world_ for the nodes that need a matrix.
    std::vector<NodeKind> kind_;
    std::vector<Sphere> worldBound_;
    std::vector<glm::mat4> world_;
    std::vector<std::uint32_t> payload_;
    std::vector<NodeId> order_;
    std::vector<std::uint32_t> subtreeEnd_;
    SiblingLayout layout_;
    // Structure and update bookkeeping.
    std::vector<NodeId> parent_, firstChild_, lastChild_, nextSibling_;
    std::vector<glm::mat4> local_;
    std::vector<Sphere> localBound_;
    std::vector<std::uint8_t> localDirty_;
    std::vector<std::string> name_;
    bool structureDirty_ = true;
    bool anyLocalDirty_ = true;

    std::vector<MeshPart> meshParts_;
    std::vector<Geometry> geometries_;
    std::vector<Material> materials_;
    std::vector<Image> images_;

    // Skins: skin s owns [skinFirst_[s], skinFirst_[s + 1]) of the joint arrays.
    std::vector<NodeId> skinMesh_;
    std::vector<std::uint32_t> skinFirst_{0};
    std::vector<NodeId> jointNode_;
    std::vector<glm::mat4> inverseBind_;
    std::vector<glm::mat4> jointMatrix_;
    void updateJointMatrices();
};

}  // namespace arcomp
