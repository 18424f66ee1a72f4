#pragma once
// A glTF skin as data: the joints that deform a mesh and their inverse bind
// matrices, as the parser reads them. Placing a model turns each skinned
// node's skin into a scene skin (Scene::addSkin), which the renderer poses
// on the GPU (graph/animation/Skinning.hpp has the same on the CPU).

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace arcomp {

// A joint or skeleton root that is not in the drawn scene.
inline constexpr std::uint32_t kNoJoint = ~std::uint32_t{0};

// The most joints one skinned draw can have: the renderer keeps the joint
// matrices in a uniform array of mat3x4 (three vectors each), and 64 of them
// take 192 of the 256 vertex uniform vectors OpenGL ES 3.0 guarantees,
// leaving room for the rest of the vertex stage's uniforms (30 vectors). A skin
// with more joints is drawn in its bind pose, with a warning at load.
inline constexpr std::size_t kMaxJointsPerDraw = 64;

struct Skin {
    std::string name;
    // Node indices: a parsed model's, or NodeIds once placed (kNoJoint for
    // nodes outside the drawn scene, which becomes kNoNode).
    std::vector<std::uint32_t> joints;
    std::vector<glm::mat4> inverseBindMatrices;  // one per joint; identity where the file gives none
    std::uint32_t skeleton = kNoJoint;           // the common root, when the file names one
    std::vector<std::uint32_t> users;            // the nodes whose mesh it would deform
};

}  // namespace arcomp
