#include "graph/animation/Skinning.hpp"
#include "graph/animation/AnimationPlayer.hpp"
#include "graph/core/Check.hpp"

#include <algorithm>
#include <cmath>

namespace arcomp {

glm::mat4 skinMatrix(const Geometry& g, std::size_t vertex, std::span<const glm::mat4> jointMatrices) {
    const glm::u16vec4 j = g.joints[vertex];
    const glm::vec4 w = g.weights[vertex];
    glm::mat4 s(0.0f);
    for (int i = 0; i < 4; ++i) {
        if (w[i] == 0.0f) continue;
        ARCOMP_CHECK(j[i] < jointMatrices.size(), "a vertex's joints are the skin's");
        s += w[i] * jointMatrices[j[i]];
    }
    return s;
}

std::vector<glm::vec3> skinPositions(const Geometry& g, std::span<const glm::mat4> jointMatrices) {
    std::vector<glm::vec3> out(g.positions.size());
    for (std::size_t v = 0; v < out.size(); ++v)
        out[v] = glm::vec3(skinMatrix(g, v, jointMatrices) * glm::vec4(g.positions[v], 1.0f));
    return out;
}

void fitPosedBounds(Scene& scene, std::span<const NodeId> meshes, std::span<const ModelAnimation> animations,
                    float samplesPerSecond) {
    std::vector<NodeId> skinned;
    for (const NodeId n : meshes)
        if (scene.kind(n) == NodeKind::Mesh && scene.meshPart(n).skin != kNoSkin) skinned.push_back(n);
    if (skinned.empty()) return;
    std::vector<Box> boxes(skinned.size());
    const auto addPose = [&] {
        scene.update();
        for (std::size_t i = 0; i < skinned.size(); ++i) {
            const MeshPart& part = scene.meshPart(skinned[i]);
            const Geometry& g = scene.geometry(part.geometry);
            for (const glm::vec3& p : skinPositions(g, scene.jointMatrices(part.skin))) boxes[i].expand(p);
        }
    };
    addPose();
    for (const ModelAnimation& animation : animations) {
        std::vector<float> times;
        const float duration = animation.clip.duration();
        const auto steps = static_cast<std::size_t>(std::ceil(duration * samplesPerSecond));
        for (std::size_t s = 0; s <= steps; ++s)
            times.push_back(std::min(duration, static_cast<float>(s) / samplesPerSecond));
        for (const AnimationChannel& c : animation.clip.channels)
            times.insert(times.end(), c.times.begin(), c.times.end());
        std::sort(times.begin(), times.end());
        times.erase(std::unique(times.begin(), times.end()), times.end());
        AnimationPlayer player(animation, {.loop = false});
        for (const float t : times) {
            player.apply(scene, t);
            addPose();
        }
        for (const AnimatedNode& n : animation.nodes) scene.setLocal(n.node, n.rest.matrix());
    }
    for (std::size_t i = 0; i < skinned.size(); ++i) scene.setLocalBound(skinned[i], sphereAround(boxes[i]));
    scene.update();
}

}  // namespace arcomp
