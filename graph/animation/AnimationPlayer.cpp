#include "graph/animation/AnimationPlayer.hpp"

#include <algorithm>
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

const char* transportName(Transport t) {
    switch (t) {
    case Transport::Playing: return "playing";
    case Transport::Paused: return "paused";
    case Transport::Stopped: return "stopped";
    }
    return "?";
}

double AnimationPlayer::clipTime(double seconds) const {
    const double duration = animation_.clip.duration();
    const double t = transport_ == Transport::Playing ? held_ + (seconds - origin_) * options_.speed : held_;
    if (duration <= 0.0 || !(t > 0.0)) return 0.0;
    if (!options_.loop) return std::min(t, duration);
    return std::fmod(t, duration);
}

void AnimationPlayer::play(double seconds) {
    if (transport_ == Transport::Playing) {
        // A clip that played once to its end starts again.
        if (options_.loop || clipTime(seconds) < animation_.clip.duration()) return;
        held_ = 0.0;
    }
    transport_ = Transport::Playing;
    origin_ = seconds;
}

void AnimationPlayer::pause(double seconds) {
    if (transport_ != Transport::Playing) return;
    held_ = clipTime(seconds);
    transport_ = Transport::Paused;
}

void AnimationPlayer::stop() {
    held_ = 0.0;
    transport_ = Transport::Stopped;
}

void AnimationPlayer::jump(double clipSeconds, double seconds) {
    held_ = std::clamp(std::isfinite(clipSeconds) ? clipSeconds : 0.0, 0.0, double(animation_.clip.duration()));
    origin_ = seconds;
    if (transport_ == Transport::Stopped) transport_ = Transport::Paused;
}

void AnimationPlayer::apply(Scene& scene, double seconds) {
    const auto t = static_cast<float>(clipTime(seconds));
    for (std::size_t i = 0; i < pose_.size(); ++i) pose_[i] = animation_.nodes[i].rest;
    for (const AnimationChannel& c : animation_.clip.channels) applySample(pose_[c.target], c.path, sample(c, t));
    for (std::size_t i = 0; i < pose_.size(); ++i) scene.setLocal(animation_.nodes[i].node, pose_[i].matrix());
}

}  // namespace arcomp
