#include "runtime/triggers/ObjectActions.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>

namespace arcomp {
namespace {

std::string unknownObject(const World& world, const std::string& name) {
    std::string known;
    for (const NamedObject& o : world.objects) known += (known.empty() ? "" : ", ") + o.name;
    return "no object '" + name + "' in the scene; its objects: " + (known.empty() ? "none" : known);
}

}  // namespace

std::string ObjectActions::perform(World& world, const TriggerAction& action, double seconds) {
    const NamedObject* object = findObject(world, action.object);
    if (!object) return unknownObject(world, action.object);
    const NodeId node = object->node;
    switch (action.kind) {
    case ActionKind::Show:
    case ActionKind::Hide:
        std::erase_if(fades_, [&](const Fade& f) { return f.node == node; });
        setOpacity(world.opacity, node, action.kind == ActionKind::Show ? 1.0f : 0.0f);
        return {};
    case ActionKind::Fade:
        std::erase_if(fades_, [&](const Fade& f) { return f.node == node; });
        fades_.push_back({node, opacityOf(world.opacity, node), action.opacity, seconds, action.seconds});
        advance(world, seconds);
        return {};
    case ActionKind::Play:
    case ActionKind::Pause:
    case ActionKind::Stop:
    case ActionKind::Jump: return animate(world, *object, action, seconds);
    default: return std::string("'") + actionName(action.kind) + "' is not an action on an object";
    }
}

std::string ObjectActions::animate(World& world, const NamedObject& object, const TriggerAction& action,
                                   double seconds) {
    if (object.animations.empty()) return "object '" + object.name + "' has no animations";
    auto player = std::find_if(world.animations.begin(), world.animations.end(),
                               [&](const ObjectAnimation& a) { return a.node == object.node; });
    // A clip named by the action replaces the one playing; an object that
    // has played nothing yet gets its first clip.
    std::optional<std::size_t> clip;
    if (!action.animation.empty()) {
        std::vector<AnimationClip> clips;
        for (const ModelAnimation& a : object.animations) clips.push_back(a.clip);
        clip = findAnimation(clips, action.animation);
        if (!clip)
            return "object '" + object.name + "' has no animation '" + action.animation +
                   "'; its animations: " + listAnimations(clips);
        if (player != world.animations.end() && player->player.animation().clip.name == clips[*clip].name)
            clip.reset();  // already the one
    } else if (player == world.animations.end()) {
        clip = 0;
    }
    if (clip) {
        const PlaybackOptions options = player != world.animations.end() ? player->player.options() : PlaybackOptions{};
        AnimationPlayer fresh(object.animations[*clip], options);
        fresh.stop();
        if (player != world.animations.end()) {
            player->player = std::move(fresh);
        } else {
            const auto [groupingNode, groupingObject] = groupingSlot(world, object.node);
            world.animations.push_back({.player = std::move(fresh),
                                        .node = object.node,
                                        .groupingNode = groupingNode,
                                        .groupingObject = groupingObject});
            player = world.animations.end() - 1;
        }
    }
    AnimationPlayer& p = player->player;
    switch (action.kind) {
    case ActionKind::Play: p.play(seconds); break;
    case ActionKind::Pause: p.pause(seconds); break;
    case ActionKind::Stop: p.stop(); break;
    default: p.jump(action.seconds, seconds); break;
    }
    return {};
}

std::string ObjectActions::startTurn(World& world, const TriggerAction& action, double seconds, int owner) {
    const NamedObject* object = findObject(world, action.object);
    if (!object) return unknownObject(world, action.object);
    stopTurn(owner);
    // Two turns of one object would each start from a matrix the other
    // keeps changing: the later one takes over.
    std::erase_if(turns_, [&](const Turn& t) { return t.node == object->node; });
    turns_.push_back({owner, object->node, world.scene.local(object->node), glm::normalize(action.axis),
                      action.degreesPerSecond, seconds});
    return {};
}

void ObjectActions::stopTurn(int owner) {
    std::erase_if(turns_, [&](const Turn& t) { return t.owner == owner; });
}

void ObjectActions::advance(World& world, double seconds) {
    for (const Fade& f : fades_) {
        const double t = f.seconds > 0.0 ? std::clamp((seconds - f.start) / f.seconds, 0.0, 1.0) : 1.0;
        setOpacity(world.opacity, f.node, f.from + (f.to - f.from) * static_cast<float>(t));
    }
    std::erase_if(fades_, [&](const Fade& f) { return seconds >= f.start + f.seconds; });
    for (const Turn& t : turns_) {
        // From the start each time, not a step a frame: the angle at a video
        // second is the same however the frames fell.
        const auto angle = static_cast<float>(glm::radians(t.degreesPerSecond * (seconds - t.start)));
        world.scene.setLocal(t.node, t.rest * glm::rotate(glm::mat4(1.0f), angle, t.axis));
    }
}

}  // namespace arcomp
