#pragma once
// A keyframe animation as data, the way glTF 2.0 stores it: each channel
// drives one property (translation, rotation or scale) of one node from a
// list of key times and values, with one interpolation for the whole channel.
//
//   AnimationChannel c{.target = 0, .path = AnimationPath::Translation,
//                      .interpolation = Interpolation::Linear,
//                      .times = {0.0f, 1.0f}, .values = {{0, 0, 0, 0}, {2, 0, 0, 0}}};
//   glm::vec4 v = sample(c, 0.25f);   // (0.5, 0, 0, 0)
//
// Values are vec4 whatever the path: translation and scale use xyz, a
// rotation is a unit quaternion in glTF's (x, y, z, w) order. A CUBICSPLINE
// channel keeps three values per key: in-tangent, value, out-tangent.
// Sampling before the first key gives the first value, after the last key
// the last value.

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace arcomp {

enum class AnimationPath : std::uint8_t { Translation, Rotation, Scale };
enum class Interpolation : std::uint8_t { Linear, Step, CubicSpline };

const char* pathName(AnimationPath p);
const char* interpolationName(Interpolation i);

// A node's pose as glTF authors it; the local matrix is T * R * S.
struct Trs {
    glm::vec3 translation{0.0f};
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};  // glm's (w, x, y, z) constructor
    glm::vec3 scale{1.0f};

    glm::mat4 matrix() const;
};

struct AnimationChannel {
    // Which node it drives: an index the owner defines (a parsed model's
    // node index, or an entry in a placed animation's node table).
    std::uint32_t target = 0;
    AnimationPath path = AnimationPath::Translation;
    Interpolation interpolation = Interpolation::Linear;
    std::vector<float> times;       // strictly increasing, at least one
    std::vector<glm::vec4> values;  // times.size() values, 3 × for CubicSpline
};

struct AnimationClip {
    std::string name;
    std::vector<AnimationChannel> channels;

    // The last key time over all channels: the clip's loop length.
    float duration() const;
};

// The clip a config names: by its name, or by its index when the text is a
// number that no clip is named. Empty when there is no such clip.
std::optional<std::size_t> findAnimation(std::span<const AnimationClip> clips, const std::string& nameOrIndex);
// "0 'walk', 1 'run'" (or "none") for messages about a missing one.
std::string listAnimations(std::span<const AnimationClip> clips);

// The channel's value at time t (seconds), by its interpolation; rotations
// come back normalised.
glm::vec4 sample(const AnimationChannel& channel, float t);

// Shortest-path spherical interpolation of unit quaternions in (x, y, z, w).
glm::vec4 slerp(glm::vec4 a, glm::vec4 b, float t);

// The pose with one channel's sampled value put in.
void applySample(Trs& pose, AnimationPath path, const glm::vec4& value);

}  // namespace arcomp
