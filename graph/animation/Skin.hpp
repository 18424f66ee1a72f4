#pragma once
// A glTF skin as data: the joints that would deform a mesh and their
// inverse bind matrices. arcomp does not skin yet; a skinned mesh is drawn
// in its bind pose, and the skins are kept so `inspect` can report them and
// a later GPU skinning step has what it needs.

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace arcomp {

// A joint or skeleton root that is not in the drawn scene.
inline constexpr std::uint32_t kNoJoint = ~std::uint32_t{0};

struct Skin {
    std::string name;
    // Node indices: a parsed model's, or NodeIds once placed (kNoJoint for
    // nodes outside the drawn scene, which becomes kNoNode).
    std::vector<std::uint32_t> joints;
    std::vector<glm::mat4> inverseBindMatrices;  // one per joint; identity where the file gives none
    std::uint32_t skeleton = kNoJoint;           // the common root, when the file names one
    std::vector<std::uint32_t> users;            // the nodes whose mesh it would deform
};

} // namespace arcomp
