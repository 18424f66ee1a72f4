#include "graph/animation/AnimationClip.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>

namespace arcomp {

const char* pathName(AnimationPath p) {
    switch (p) {
    case AnimationPath::Translation: return "translation";
    case AnimationPath::Rotation: return "rotation";
    case AnimationPath::Scale: return "scale";
    }
    return "?";
}

const char* interpolationName(Interpolation i) {
    switch (i) {
    case Interpolation::Linear: return "LINEAR";
    case Interpolation::Step: return "STEP";
    case Interpolation::CubicSpline: return "CUBICSPLINE";
    }
    return "?";
}

glm::mat4 Trs::matrix() const {
    return glm::scale(glm::translate(glm::mat4(1.0f), translation) * glm::mat4_cast(rotation), scale);
}

float AnimationClip::duration() const {
    float end = 0.0f;
    for (const AnimationChannel& c : channels)
        if (!c.times.empty()) end = std::max(end, c.times.back());
    return end;
}

std::optional<std::size_t> findAnimation(std::span<const AnimationClip> clips, const std::string& nameOrIndex) {
    // A name wins over an index: a clip may well be called "1".
    for (std::size_t i = 0; i < clips.size(); ++i)
        if (clips[i].name == nameOrIndex) return i;
    std::size_t index = 0;
    const char* end = nameOrIndex.data() + nameOrIndex.size();
    const auto [rest, ec] = std::from_chars(nameOrIndex.data(), end, index);
    if (!nameOrIndex.empty() && ec == std::errc() && rest == end && index < clips.size()) return index;
    return std::nullopt;
}

std::string listAnimations(std::span<const AnimationClip> clips) {
    if (clips.empty()) return "none";
    std::string out;
    for (std::size_t i = 0; i < clips.size(); ++i) {
        if (i) out += ", ";
        out += std::to_string(i) + " '" + clips[i].name + "'";
    }
    return out;
}

// glTF 2.0 specification, Appendix C (Animation Sampler Interpolation
// Modes), "Spherical Linear Interpolation": the shorter of the two arcs
// (negate b when the dot product is negative), plain normalised lerp where
// the angle is too small for sin() to divide by.
glm::vec4 slerp(glm::vec4 a, glm::vec4 b, float t) {
    float d = glm::dot(a, b);
    if (d < 0.0f) {
        b = -b;
        d = -d;
    }
    if (d > 0.9995f) return glm::normalize(a + t * (b - a));
    const float theta0 = std::acos(d);
    const float theta = t * theta0;
    const float sinTheta = std::sin(theta), sinTheta0 = std::sin(theta0);
    const float scaleA = std::cos(theta) - d * sinTheta / sinTheta0;
    const float scaleB = sinTheta / sinTheta0;
    return scaleA * a + scaleB * b;
}

namespace {

// glTF 2.0 specification, Appendix C, "Cubic Spline Interpolation": the
// Hermite spline between keys k and k+1 with v_k, its out-tangent b_k, the
// next key's in-tangent a_{k+1} and v_{k+1}; tangents are per second, hence
// scaled by the key interval td.
glm::vec4 hermite(const glm::vec4& vk, const glm::vec4& bk, const glm::vec4& ak1, const glm::vec4& vk1, float td,
                  float t) {
    const float t2 = t * t, t3 = t2 * t;
    return (2.0f * t3 - 3.0f * t2 + 1.0f) * vk + td * (t3 - 2.0f * t2 + t) * bk + (-2.0f * t3 + 3.0f * t2) * vk1 +
           td * (t3 - t2) * ak1;
}

// The key's own value: for CubicSpline the middle of its three.
glm::vec4 keyValue(const AnimationChannel& c, std::size_t k) {
    return c.interpolation == Interpolation::CubicSpline ? c.values[k * 3 + 1] : c.values[k];
}

}  // namespace

glm::vec4 sample(const AnimationChannel& c, float t) {
    const std::size_t keys = c.times.size();
    const bool rotation = c.path == AnimationPath::Rotation;
    if (keys == 0) return rotation ? glm::vec4(0, 0, 0, 1) : glm::vec4(0.0f);
    if (t <= c.times.front()) return keyValue(c, 0);
    if (t >= c.times.back()) return keyValue(c, keys - 1);
    // glTF 2.0 specification, Appendix C: within the key interval
    // [times[k], times[k+1]) that holds t, STEP keeps key k's value, LINEAR
    // lerps (slerp below for rotations), CUBICSPLINE is hermite() below.
    const std::size_t k =
        static_cast<std::size_t>(std::upper_bound(c.times.begin(), c.times.end(), t) - c.times.begin()) - 1;
    const float td = c.times[k + 1] - c.times[k];
    const float u = (t - c.times[k]) / td;
    switch (c.interpolation) {
    case Interpolation::Step: return c.values[k];
    case Interpolation::Linear:
        return rotation ? slerp(c.values[k], c.values[k + 1], u) : glm::mix(c.values[k], c.values[k + 1], u);
    case Interpolation::CubicSpline: {
        const glm::vec4 v =
            hermite(c.values[k * 3 + 1], c.values[k * 3 + 2], c.values[(k + 1) * 3], c.values[(k + 1) * 3 + 1], td, u);
        if (!rotation) return v;
        // Opposite tangents can cancel to nothing; hold the key then.
        const float length = glm::length(v);
        return length > 0.0f ? v / length : keyValue(c, k);
    }
    }
    return keyValue(c, k);
}

void applySample(Trs& pose, AnimationPath path, const glm::vec4& v) {
    switch (path) {
    case AnimationPath::Translation: pose.translation = glm::vec3(v); break;
    case AnimationPath::Rotation: pose.rotation = glm::quat(v.w, v.x, v.y, v.z); break;
    case AnimationPath::Scale: pose.scale = glm::vec3(v); break;
    }
}

}  // namespace arcomp
