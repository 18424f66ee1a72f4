#include "graph/animation/AnimationPlayer.hpp"

#include <cmath>
#include <stdexcept>

namespace arcomp {

AnimationPlayer::AnimationPlayer(ModelAnimation animation, PlaybackOptions options)
    : animation_(std::move(animation)), options_(options) {
    // Backwards play would need its own notion of where a loop starts; nobody
    // has asked for it.
    if (!(options_.speed > 0.0) || !std::isfinite(options_.speed))
        throw std::invalid_argument("animation '" + animation_.clip.name + "': speed " +
                                    std::to_string(options_.speed) + " must be a positive number");
    for (const AnimationChannel& c : animation_.clip.channels)
        if (c.target >= animation_.nodes.size())
            throw std::invalid_argument("animation '" + animation_.clip.name + "': channel targets node slot " +
                                        std::to_string(c.target) + " of " + std::to_string(animation_.nodes.size()));
    pose_.resize(animation_.nodes.size());
}

double AnimationPlayer::clipTime(double seconds) const {
    const double duration = animation_.clip.duration();
    const double t = seconds * options_.speed;
    if (duration <= 0.0 || t <= 0.0) return 0.0;
    if (!options_.loop) return std::min(t, duration);
    return std::fmod(t, duration);
}

void AnimationPlayer::apply(Scene& scene, double seconds) {
    const auto t = static_cast<float>(clipTime(seconds));
    for (std::size_t i = 0; i < pose_.size(); ++i) pose_[i] = animation_.nodes[i].rest;
    for (const AnimationChannel& c : animation_.clip.channels) applySample(pose_[c.target], c.path, sample(c, t));
    for (std::size_t i = 0; i < pose_.size(); ++i) scene.setLocal(animation_.nodes[i].node, pose_[i].matrix());
}

}  // namespace arcomp
