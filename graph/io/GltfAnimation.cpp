// glTF animations and skins, checked as strictly as mesh data: every
// accessor through the parser's reader, every index against its array, and
// the rules the spec puts on samplers (increasing key times, one output per
// key, three per key for CUBICSPLINE).

#include "graph/io/GltfAnimation.hpp"

#include "graph/io/GltfReader.hpp"

#include <tiny_gltf.h>

#include <algorithm>
#include <set>
#include <utility>

namespace arcomp {

namespace {

std::string at(const char* array, std::size_t index) { return std::string("/") + array + "/" + std::to_string(index); }

std::optional<AnimationPath> parsePath(const std::string& path) {
    if (path == "translation") return AnimationPath::Translation;
    if (path == "rotation") return AnimationPath::Rotation;
    if (path == "scale") return AnimationPath::Scale;
    return std::nullopt;
}

std::optional<Interpolation> parseInterpolation(const std::string& name) {
    if (name.empty() || name == "LINEAR") return Interpolation::Linear;  // the spec's default
    if (name == "STEP") return Interpolation::Step;
    if (name == "CUBICSPLINE") return Interpolation::CubicSpline;
    return std::nullopt;
}

struct SamplerKeys {
    Interpolation interpolation = Interpolation::Linear;
    std::vector<float> times;
};

class AnimationReader {
public:
    AnimationReader(const tinygltf::Model& model, const gltf::GltfReader& reader, const std::vector<int>& parsedOf,
                    ParsedModel& out)
        : model_(model), reader_(reader), parsedOf_(parsedOf), out_(out) {}

    [[noreturn]] void fail(const std::string& where, const std::string& reason) const { reader_.fail(where, reason); }

    void animations() {
        for (std::size_t a = 0; a < model_.animations.size(); ++a) out_.animations.push_back(animation(a));
    }

    void skins() {
        for (std::size_t i = 0; i < model_.skins.size(); ++i) out_.skins.push_back(skin(i));
        for (std::size_t n = 0; n < model_.nodes.size(); ++n) {
            const int s = model_.nodes[n].skin;
            if (s < 0) continue;
            if (static_cast<std::size_t>(s) >= model_.skins.size())
                fail(at("nodes", n) + "/skin", "skin " + std::to_string(s) + " does not exist (" +
                                                   std::to_string(model_.skins.size()) + " skins)");
            const int parsed = parsedOf_[n];
            if (parsed < 0) continue;  // not drawn, so nothing is drawn unskinned either
            out_.nodes[static_cast<std::size_t>(parsed)].skin = s;
            Skin& skin = out_.skins[static_cast<std::size_t>(s)];
            skin.users.push_back(static_cast<std::uint32_t>(parsed));
        }
    }

private:
    // An accessor without a buffer view holds zeros, which the spec allows
    // as a placeholder (the validator's corpus has such animations): key
    // times of all zeros do not increase, so such a sampler cannot play.
    bool placeholder(int accessor) const {
        const tinygltf::Accessor& a = model_.accessors[static_cast<std::size_t>(accessor)];
        return a.bufferView < 0 && !a.sparse.isSparse;
    }

    SamplerKeys samplerKeys(std::size_t a, std::size_t s) const {
        const tinygltf::AnimationSampler& src = model_.animations[a].samplers[s];
        const std::string where = at("animations", a) + "/samplers/" + std::to_string(s);
        SamplerKeys keys;
        const auto interpolation = parseInterpolation(src.interpolation);
        if (!interpolation)
            fail(where + "/interpolation",
                 "unknown interpolation '" + src.interpolation + "'; expected LINEAR, STEP or CUBICSPLINE");
        keys.interpolation = *interpolation;
        if (src.input < 0) fail(where + "/input", "has no accessor");
        keys.times = reader_.readFloats(static_cast<std::size_t>(src.input), where + "/input", TINYGLTF_TYPE_SCALAR,
                                        {TINYGLTF_COMPONENT_TYPE_FLOAT});
        if (placeholder(src.input)) return keys;  // all zeros: the channels using it are skipped
        for (std::size_t k = 0; k < keys.times.size(); ++k) {
            if (keys.times[k] < 0.0f)
                fail(where + "/input", "key " + std::to_string(k) + " is at " + std::to_string(keys.times[k]) +
                                           " s; key times start at 0 or later");
            // Sampling finds a key by binary search; equal or falling times
            // would make the interval (and CUBICSPLINE's division by it) void.
            if (k > 0 && keys.times[k] <= keys.times[k - 1])
                fail(where + "/input", "key times must increase: key " + std::to_string(k) + " (" +
                                           std::to_string(keys.times[k]) + " s) is not after key " +
                                           std::to_string(k - 1) + " (" + std::to_string(keys.times[k - 1]) +
                                           " s), accessor " + std::to_string(src.input));
        }
        return keys;
    }

    std::vector<glm::vec4> samplerValues(std::size_t a, std::size_t s, AnimationPath path,
                                         const SamplerKeys& keys) const {
        const tinygltf::AnimationSampler& src = model_.animations[a].samplers[s];
        const std::string where = at("animations", a) + "/samplers/" + std::to_string(s) + "/output";
        if (src.output < 0) fail(where, "has no accessor");
        const auto output = static_cast<std::size_t>(src.output);
        const bool rotation = path == AnimationPath::Rotation;
        const int width = rotation ? 4 : 3;
        // The spec allows normalized integer quaternions (as
        // KHR_mesh_quantization does for meshes); translation and scale are
        // float unless that extension is used, which arcomp does not for them.
        const std::vector<int> components =
            rotation ? std::vector<int>{TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_BYTE,
                                        TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_SHORT,
                                        TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT}
                     : std::vector<int>{TINYGLTF_COMPONENT_TYPE_FLOAT};
        const std::vector<float> raw =
            reader_.readFloats(output, where, rotation ? TINYGLTF_TYPE_VEC4 : TINYGLTF_TYPE_VEC3, components);
        const tinygltf::Accessor& accessor = model_.accessors[output];
        if (accessor.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT && !accessor.normalized)
            fail(at("accessors", output) + "/normalized",
                 "integer rotations must be normalized (used by " + where + ")");
        const bool cubic = keys.interpolation == Interpolation::CubicSpline;
        const std::size_t expected = keys.times.size() * (cubic ? 3 : 1);
        const std::size_t count = raw.size() / static_cast<std::size_t>(width);
        if (count != expected)
            fail(where, "has " + std::to_string(count) + " elements; expected " + std::to_string(expected) + " (" +
                            std::to_string(keys.times.size()) + " key times" + (cubic ? " × 3 for CUBICSPLINE" : "") +
                            ")");
        std::vector<glm::vec4> values(count, glm::vec4(0.0f));
        for (std::size_t e = 0; e < count; ++e)
            for (int c = 0; c < width; ++c)
                values[e][c] = raw[e * static_cast<std::size_t>(width) + static_cast<std::size_t>(c)];
        if (rotation && !placeholder(src.output))
            for (std::size_t e = 0; e < count; ++e) {
                if (cubic && e % 3 != 1) continue;  // tangents are not unit quaternions
                const float length = glm::length(values[e]);
                // Slerp assumes unit keys; rounding in the file is forgiven, a zero is not.
                if (!(length > 1e-6f))
                    fail(where, "key " + std::to_string(cubic ? e / 3 : e) + " is not a rotation (zero quaternion)");
                values[e] /= length;
            }
        return values;
    }

    AnimationClip animation(std::size_t a) {
        const tinygltf::Animation& src = model_.animations[a];
        const std::string where = at("animations", a);
        AnimationClip clip;
        clip.name = src.name.empty() ? "animation" + std::to_string(a) : src.name;
        std::vector<SamplerKeys> keys;
        for (std::size_t s = 0; s < src.samplers.size(); ++s) keys.push_back(samplerKeys(a, s));
        std::set<std::pair<int, AnimationPath>> driven;
        for (std::size_t c = 0; c < src.channels.size(); ++c) {
            const tinygltf::AnimationChannel& ch = src.channels[c];
            const std::string channel = where + "/channels/" + std::to_string(c);
            if (ch.sampler < 0 || static_cast<std::size_t>(ch.sampler) >= src.samplers.size())
                fail(channel + "/sampler", "sampler " + std::to_string(ch.sampler) + " does not exist (" +
                                               std::to_string(src.samplers.size()) + " samplers)");
            if (ch.target_path == "weights") {
                out_.warnings.push_back(
                    channel + ": animation '" + clip.name +
                    "' drives morph target weights, which arcomp does not support; channel skipped");
                continue;
            }
            const auto path = parsePath(ch.target_path);
            if (!path)
                fail(channel + "/target/path",
                     "unknown path '" + ch.target_path + "'; expected translation, rotation, scale or weights");
            if (ch.target_node < 0 || static_cast<std::size_t>(ch.target_node) >= model_.nodes.size())
                fail(channel + "/target/node", "node " + std::to_string(ch.target_node) + " does not exist (" +
                                                   std::to_string(model_.nodes.size()) + " nodes)");
            const auto node = static_cast<std::size_t>(ch.target_node);
            if (!model_.nodes[node].matrix.empty())
                fail(channel + "/target/node",
                     "node " + std::to_string(node) +
                         " gives a matrix; an animated node must give translation, rotation and scale");
            if (!driven.insert({ch.target_node, *path}).second)
                fail(channel,
                     "a second channel for the " + std::string(pathName(*path)) + " of node " + std::to_string(node));
            const auto sampler = static_cast<std::size_t>(ch.sampler);
            std::vector<glm::vec4> values = samplerValues(a, sampler, *path, keys[sampler]);
            const tinygltf::AnimationSampler& used = src.samplers[sampler];
            if (placeholder(used.input) || placeholder(used.output)) {
                out_.warnings.push_back(channel + ": animation '" + clip.name + "' uses sampler " +
                                        std::to_string(sampler) +
                                        ", whose accessors hold no data (no buffer view); channel skipped");
                continue;
            }
            if (parsedOf_[node] < 0) {
                out_.warnings.push_back(channel + ": animation '" + clip.name + "' targets node " +
                                        std::to_string(node) + ", which is not in the drawn scene; channel skipped");
                continue;
            }
            clip.channels.push_back({.target = static_cast<std::uint32_t>(parsedOf_[node]),
                                     .path = *path,
                                     .interpolation = keys[sampler].interpolation,
                                     .times = keys[sampler].times,
                                     .values = std::move(values)});
        }
        return clip;
    }

    Skin skin(std::size_t i) const {
        const tinygltf::Skin& src = model_.skins[i];
        const std::string where = at("skins", i);
        Skin out;
        out.name = src.name.empty() ? "skin" + std::to_string(i) : src.name;
        if (src.joints.empty()) fail(where + "/joints", "a skin needs at least one joint");
        auto placed = [&](int node, const std::string& pointer) {
            if (node < 0 || static_cast<std::size_t>(node) >= model_.nodes.size())
                fail(pointer, "node " + std::to_string(node) + " does not exist (" +
                                  std::to_string(model_.nodes.size()) + " nodes)");
            const int parsed = parsedOf_[static_cast<std::size_t>(node)];
            return parsed < 0 ? kNoJoint : static_cast<std::uint32_t>(parsed);
        };
        for (std::size_t j = 0; j < src.joints.size(); ++j)
            out.joints.push_back(placed(src.joints[j], where + "/joints/" + std::to_string(j)));
        if (src.skeleton >= 0) out.skeleton = placed(src.skeleton, where + "/skeleton");
        out.inverseBindMatrices.assign(out.joints.size(), glm::mat4(1.0f));
        if (src.inverseBindMatrices >= 0) {
            const std::string pointer = where + "/inverseBindMatrices";
            const std::vector<float> m = reader_.readFloats(static_cast<std::size_t>(src.inverseBindMatrices), pointer,
                                                            TINYGLTF_TYPE_MAT4, {TINYGLTF_COMPONENT_TYPE_FLOAT});
            if (m.size() / 16 < out.joints.size())
                fail(pointer, "has " + std::to_string(m.size() / 16) + " matrices for " +
                                  std::to_string(out.joints.size()) + " joints");
            for (std::size_t j = 0; j < out.joints.size(); ++j)
                for (int e = 0; e < 16; ++e)
                    out.inverseBindMatrices[j][e / 4][e % 4] = m[j * 16 + static_cast<std::size_t>(e)];
        }
        return out;
    }

    const tinygltf::Model& model_;
    const gltf::GltfReader& reader_;
    const std::vector<int>& parsedOf_;
    ParsedModel& out_;
};

}  // namespace

std::optional<Trs> authoredTrs(const tinygltf::Node& node) {
    if (!node.matrix.empty()) return std::nullopt;
    Trs trs;
    if (node.translation.size() == 3)
        trs.translation = glm::vec3(node.translation[0], node.translation[1], node.translation[2]);
    if (node.rotation.size() == 4) {
        const glm::quat q(static_cast<float>(node.rotation[3]), static_cast<float>(node.rotation[0]),
                          static_cast<float>(node.rotation[1]), static_cast<float>(node.rotation[2]));
        // As nodeMatrix does: a zero quaternion means no rotation.
        const float length = glm::length(q);
        if (length > 0.0f) trs.rotation = q / length;
    }
    if (node.scale.size() == 3) trs.scale = glm::vec3(node.scale[0], node.scale[1], node.scale[2]);
    return trs;
}

void readGltfAnimation(const tinygltf::Model& model, const gltf::GltfReader& reader, const std::vector<int>& parsedOf,
                       ParsedModel& out) {
    AnimationReader animations(model, reader, parsedOf, out);
    animations.skins();
    animations.animations();
}

}  // namespace arcomp
