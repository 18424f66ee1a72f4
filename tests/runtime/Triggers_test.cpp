// Triggers: each condition (enter, leave, dwell, count, near) fires on the
// frame it becomes true, a held one ends with its on_end, cooldown holds
// back what comes too soon; and each action does what it says to the
// world: shown and hidden objects leave or join the select pass's list, a
// fade and a turn are where the video's clock puts them, an animation
// plays, pauses, stops and jumps. The config's mistakes are reported at
// their lines.

#include "graph/core/SelectPass.hpp"
#include "runtime/config/StationConfig.hpp"
#include "runtime/station/SceneFile.hpp"
#include "runtime/triggers/Triggers.hpp"
#include "runtime/zones/ZoneOccupancy.hpp"

#include "tests/support/ConfigIssues.hpp"
#include "tests/support/GltfFile.hpp"
#include "tests/support/TempDir.hpp"

#include <gtest/gtest.h>

using namespace arcomp;
using arcomp::test::configIssues;
using arcomp::test::describe;
using arcomp::test::hasIssue;
using arcomp::test::lineOf;
using arcomp::test::TempDir;

namespace {

constexpr const char* kScene = R"(scene:
  objects:
    - {name: sign, shape: box, position: [-1, 0, -4], visible: false}
    - {name: plinth, shape: box, position: [1, 0, -4]}
    - {name: walker, model: slide.gltf, position: [0, 1, -4], animation: slide, playing: false}
camera: {eye: [0, 0, 0], target: [0, 0, -1]}
zones:
  - {name: left, image_rect: {min: [0, 0], max: [0.5, 1]}}
)";

// A station's world and its triggers, from `triggers` under kScene.
struct Installation {
    TempDir dir;
    StationConfig cfg;
    World world;
    std::vector<std::string> warnings;
    explicit Installation(const std::string& triggers) {
        dir.write("slide.gltf", arcomp::test::slidingTriangle());
        cfg = loadStationConfig(dir.write("station.yaml", std::string(kScene) + triggers));
        buildScene(cfg, world, warnings);
        world.scene.update();
    }
    NodeId node(const std::string& name) const { return findObject(world, name)->node; }
    // Whether the select pass lists anything of the object.
    bool drawn(const std::string& name) {
        world.scene.update();
        DrawList list;
        select(world, View::lookAt({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 45.0f, {320, 240}), {}, list);
        for (const DrawItem& item : list.items)
            for (NodeId n = item.node; n != kNoNode; n = world.scene.parent(n))
                if (n == node(name)) return true;
        return false;
    }
};

// Frames of people standing at picture points; ZoneOccupancy gives them
// their zones as the station does.
struct Visitors {
    ZoneOccupancy zones;
    std::uint64_t frame = 0;
    explicit Visitors(const StationConfig& cfg) : zones(cfg.zones) {}
    const PeopleFrame& at(double seconds, std::vector<std::pair<int, float>> people) {
        PeopleFrame f;
        f.frame = frame++;
        f.seconds = seconds;
        for (const auto& [id, u] : people)
            f.people.push_back({.id = id,
                                .ageSeconds = 0.0,
                                .seen = true,
                                .position = {u, 0.8f},
                                .velocity = {},
                                .heightMetres = 0.0f,
                                .box = {},
                                .picture = {u, 0.8f},
                                .zones = {}});
        return zones.update(f);
    }
};

}  // namespace

TEST(Triggers, enterFiresForEachEntryOutsideTheCooldownAndCountsTheRest) {
    Installation s(R"(triggers:
  - {name: hello, when: {enter: left}, do: [{show: sign}], cooldown: 2}
)");
    Triggers triggers(s.cfg.triggers);
    Visitors v(s.cfg);
    EXPECT_FALSE(s.drawn("sign")) << "visible: false hides it from the start";
    EXPECT_TRUE(triggers.update(v.at(0.0, {{1, 0.8f}}), s.world).firings.empty());
    const TriggerFrame& first = triggers.update(v.at(0.1, {{1, 0.2f}}), s.world);
    ASSERT_EQ(first.firings.size(), 1u);
    EXPECT_EQ(first.firings[0].person, 1);
    EXPECT_FALSE(first.firings[0].ended);
    EXPECT_TRUE(s.drawn("sign"));
    // A second person enters a second later: within the 2 s cooldown.
    EXPECT_TRUE(triggers.update(v.at(1.1, {{1, 0.2f}, {2, 0.2f}}), s.world).firings.empty());
    EXPECT_EQ(triggers.counts(0).cooledDown, 1u);
    // A third, after it.
    EXPECT_EQ(triggers.update(v.at(2.2, {{1, 0.2f}, {2, 0.2f}, {3, 0.2f}}), s.world).firings.size(), 1u);
    EXPECT_EQ(triggers.counts(0).fired, 2u);
}

TEST(Triggers, aCountHoldsWhileEnoughAreInAndEndsWithItsOnEnd) {
    Installation s(R"(triggers:
  - name: pair
    when: {count: left, at_least: 2}
    do: [{show: sign}]
    on_end: [{hide: sign}]
    cooldown: 0
)");
    Triggers triggers(s.cfg.triggers);
    Visitors v(s.cfg);
    EXPECT_TRUE(triggers.update(v.at(0.0, {{1, 0.2f}}), s.world).firings.empty()) << "one is not two";
    EXPECT_EQ(triggers.update(v.at(0.1, {{1, 0.2f}, {2, 0.3f}}), s.world).firings.size(), 1u);
    EXPECT_TRUE(s.drawn("sign"));
    EXPECT_TRUE(triggers.update(v.at(0.2, {{1, 0.2f}, {2, 0.3f}}), s.world).firings.empty()) << "fires once";
    EXPECT_TRUE(triggers.holds(0));
    const TriggerFrame& end = triggers.update(v.at(0.3, {{1, 0.2f}, {2, 0.9f}}), s.world);
    ASSERT_EQ(end.firings.size(), 1u);
    EXPECT_TRUE(end.firings[0].ended);
    EXPECT_FALSE(s.drawn("sign"));
}

TEST(Triggers, aHeldConditionWaitsOutItsCooldownInsteadOfBeingLost) {
    Installation s(R"(triggers:
  - {name: sign, when: {count: left, at_least: 1}, do: [{show: sign}], on_end: [{hide: sign}], cooldown: 1}
)");
    Triggers triggers(s.cfg.triggers);
    Visitors v(s.cfg);
    EXPECT_EQ(triggers.update(v.at(0.0, {{1, 0.2f}}), s.world).firings.size(), 1u);
    EXPECT_EQ(triggers.update(v.at(0.2, {}), s.world).firings.size(), 1u) << "ended";
    // Back in 0.4 s after the firing: held back, and fired once the second has passed.
    EXPECT_TRUE(triggers.update(v.at(0.4, {{2, 0.2f}}), s.world).firings.empty());
    EXPECT_FALSE(s.drawn("sign"));
    EXPECT_TRUE(triggers.update(v.at(0.9, {{2, 0.2f}}), s.world).firings.empty());
    EXPECT_EQ(triggers.update(v.at(1.0, {{2, 0.2f}}), s.world).firings.size(), 1u);
    EXPECT_TRUE(s.drawn("sign"));
}

TEST(Triggers, dwellFiresOnceSomeoneHasStoodInTheZoneLongEnough) {
    Installation s(R"(triggers:
  - {name: stay, when: {dwell: left, seconds: 2}, do: [{hide: plinth}], on_end: [{show: plinth}]}
)");
    Triggers triggers(s.cfg.triggers);
    Visitors v(s.cfg);
    for (double t = 0.0; t < 1.95; t += 0.5) {
        EXPECT_TRUE(triggers.update(v.at(t, {{1, 0.2f}}), s.world).firings.empty()) << t;
        EXPECT_TRUE(s.drawn("plinth"));
    }
    EXPECT_EQ(triggers.update(v.at(2.0, {{1, 0.2f}}), s.world).firings.size(), 1u);
    EXPECT_FALSE(s.drawn("plinth"));
    // A newcomer does not inherit the first one's time.
    EXPECT_EQ(triggers.update(v.at(2.5, {{2, 0.2f}}), s.world).firings.size(), 1u) << "ended";
    EXPECT_TRUE(triggers.update(v.at(4.0, {{2, 0.2f}}), s.world).firings.empty());
    EXPECT_EQ(triggers.update(v.at(4.5, {{2, 0.2f}}), s.world).firings.size(), 1u);
}

TEST(Triggers, nearFiresWithinTheRadiusOfTheObjectOnTheFloorAndLeavesBeyondItsMargin) {
    Installation s("");
    const Trigger near{.name = "close",
                       .when = {.event = TriggerEvent::Near, .object = "plinth", .metres = 1.0f, .margin = 0.2f},
                       .actions = {{.kind = ActionKind::Hide, .object = "sign"}},
                       .onEnd = {},
                       .cooldownSeconds = 0.0};
    Triggers triggers({near});
    const auto standingAt = [](double seconds, glm::vec2 floor) {
        PeopleFrame f;
        f.seconds = seconds;
        f.units = PositionUnits::FloorMetres;
        f.people.push_back({.id = 1,
                            .ageSeconds = 0.0,
                            .seen = true,
                            .position = floor,
                            .velocity = {},
                            .heightMetres = 0.0f,
                            .box = {},
                            .picture = {},
                            .zones = {}});
        return f;
    };
    // The plinth stands at x = 1, z = -4.
    EXPECT_TRUE(triggers.update(standingAt(0.0, {1.0f, -2.8f}), s.world).firings.empty());
    EXPECT_EQ(triggers.update(standingAt(0.1, {1.0f, -3.1f}), s.world).firings.size(), 1u);
    EXPECT_TRUE(triggers.update(standingAt(0.2, {1.0f, -2.9f}), s.world).firings.empty()) << "within the margin";
    EXPECT_EQ(triggers.update(standingAt(0.3, {1.0f, -2.7f}), s.world).firings.size(), 1u) << "beyond it";
    EXPECT_FALSE(triggers.holds(0));
}

TEST(Triggers, fadeAndTurnArePlacedByTheVideoClock) {
    Installation s(R"(triggers:
  - name: spin
    when: {count: left, at_least: 1}
    do: [{fade: plinth, to: 0, seconds: 2}, {turn: plinth, degrees_per_second: 90}]
    cooldown: 0
)");
    Triggers triggers(s.cfg.triggers);
    Visitors v(s.cfg);
    const glm::mat4 rest = s.world.scene.local(s.node("plinth"));
    triggers.update(v.at(10.0, {{1, 0.2f}}), s.world);
    triggers.update(v.at(11.0, {{1, 0.2f}}), s.world);
    EXPECT_NEAR(opacityOf(s.world.opacity, s.node("plinth")), 0.5f, 1e-6f) << "half way through its 2 s";
    // 90 degrees about +y in one second: the box's +x axis turns to -z.
    const glm::mat4 turned = s.world.scene.local(s.node("plinth"));
    EXPECT_NEAR(turned[0].x, 0.0f, 1e-5f);
    EXPECT_NEAR(turned[0].z, -1.0f, 1e-5f);
    EXPECT_EQ(turned[3], rest[3]) << "turns in place";
    triggers.update(v.at(12.0, {}), s.world);  // out: the turn stops where it is
    const glm::mat4 stopped = s.world.scene.local(s.node("plinth"));
    triggers.update(v.at(13.0, {}), s.world);
    EXPECT_EQ(s.world.scene.local(s.node("plinth")), stopped);
    EXPECT_FLOAT_EQ(opacityOf(s.world.opacity, s.node("plinth")), 0.0f);
    EXPECT_FALSE(s.drawn("plinth")) << "faded out";
}

TEST(Triggers, playPauseStopAndJumpDriveTheModelsAnimation) {
    Installation s(R"(triggers:
  - {name: go, when: {enter: left}, do: [{play: walker}], cooldown: 0}
  - {name: halt, when: {leave: left}, do: [{pause: walker}], cooldown: 0}
)");
    Triggers triggers(s.cfg.triggers);
    Visitors v(s.cfg);
    ASSERT_EQ(s.world.animations.size(), 1u);
    AnimationPlayer& player = s.world.animations[0].player;
    EXPECT_EQ(player.transport(), Transport::Stopped) << "playing: false";
    triggers.update(v.at(5.0, {{1, 0.2f}}), s.world);
    EXPECT_EQ(player.transport(), Transport::Playing);
    EXPECT_NEAR(player.clipTime(5.25), 0.25, 1e-9) << "from its start at the firing";
    triggers.update(v.at(5.5, {{1, 0.9f}}), s.world);
    EXPECT_EQ(player.transport(), Transport::Paused);
    EXPECT_NEAR(player.clipTime(9.0), 0.5, 1e-9) << "held where it was";
    ObjectActions& objects = triggers.objects();
    EXPECT_EQ(objects.perform(s.world, {.kind = ActionKind::Jump, .object = "walker", .seconds = 0.75}, 9.0), "");
    EXPECT_NEAR(player.clipTime(9.5), 0.75, 1e-9);
    EXPECT_EQ(objects.perform(s.world, {.kind = ActionKind::Stop, .object = "walker"}, 10.0), "");
    EXPECT_EQ(player.clipTime(11.0), 0.0);
    const std::string noFly =
        objects.perform(s.world, {.kind = ActionKind::Play, .object = "walker", .animation = "fly"}, 12.0);
    EXPECT_NE(noFly.find("no animation 'fly'; its animations: 0 'slide', 1 'grow'"), std::string::npos) << noFly;
    EXPECT_NE(objects.perform(s.world, {.kind = ActionKind::Show, .object = "ghost"}, 12.0)
                  .find("no object 'ghost' in the scene; its objects: sign, plinth, walker"),
              std::string::npos);
}

TEST(Triggers, aHiddenObjectCutsNoOneOut) {
    Installation s("");
    const NodeId mesh = s.world.scene.children(s.node("plinth")).at(0);
    s.world.holdouts.addPosed(s.world.scene, mesh, 0);
    s.world.scene.update();
    DrawList list;
    const View view = View::lookAt({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 45.0f, {320, 240});
    select(s.world, view, {}, list);
    ASSERT_EQ(list.holdouts.size(), 1u);
    EXPECT_EQ(list.items[list.holdouts[0].cgItem].node, mesh);
    setOpacity(s.world.opacity, s.node("plinth"), 0.25f);
    select(s.world, view, {}, list);
    ASSERT_EQ(list.holdouts.size(), 1u) << "fading, still there";
    EXPECT_FLOAT_EQ(list.items[list.holdouts[0].cgItem].fade, 0.25f);
    setOpacity(s.world.opacity, s.node("plinth"), 0.0f);
    select(s.world, view, {}, list);
    EXPECT_TRUE(list.holdouts.empty());
    EXPECT_EQ(list.items.size(), 1u) << "the walker alone: the sign is hidden too";
}

TEST(TriggerConfig, reportsEachMistakeAtItsLine) {
    TempDir dir;
    dir.write("slide.gltf", arcomp::test::slidingTriangle());
    const std::string text = std::string(kScene) + R"(triggers:
  - {name: a, when: {enter: back}, do: [{show: sign}]}
  - {name: b, when: {enter: left}, do: [{show: sing}]}
  - {name: c, when: {enter: left}, do: [{turn: sign, degrees_per_second: 10}]}
  - {name: d, when: {enter: left}, do: [{osc: /cue}]}
  - {name: e, when: {near: sign, metres: 1}, do: [{show: sign}]}
  - {name: f, when: {enter: left, leave: left}, do: [{show: sign}]}
  - {name: g, when: {enter: left}, do: [{play: plinth}]}
  - {name: g, when: {enter: left}, do: [{mqtt: "a/#"}]}
  - {name: i, when: {enter: left}, do: [{show: sign}], on_end: [{hide: sign}]}
  - {name: j, when: {count: left, at_least: 1}, do: [{wave: sign}]}
  - {name: "", when: {enter: left}, do: [{show: sign}]}
)";
    const auto issues = configIssues(dir.write("station.yaml", text));
    const int first = lineOf(text, "name: a,");
    EXPECT_TRUE(hasIssue(issues, first, "no zone is named 'back' in zones; the names: left")) << describe(issues);
    EXPECT_TRUE(
        hasIssue(issues, first + 1, "no object is named 'sing' in scene.objects; the names: plinth, sign, walker"))
        << describe(issues);
    EXPECT_TRUE(hasIssue(issues, first + 2, "an enter holds for one frame")) << describe(issues);
    EXPECT_TRUE(hasIssue(issues, first + 3, "no show_control.osc target")) << describe(issues);
    EXPECT_TRUE(hasIssue(issues, first + 4, "needs camera.calibration")) << describe(issues);
    EXPECT_TRUE(hasIssue(issues, first + 5, "expected one event of enter, leave, dwell, count, near; it has 2"))
        << describe(issues);
    EXPECT_TRUE(hasIssue(issues, first + 6, "is a shape; only a model has animations")) << describe(issues);
    EXPECT_TRUE(hasIssue(issues, first + 7, "used by an earlier trigger")) << describe(issues);
    EXPECT_TRUE(hasIssue(issues, first + 7, "no + or # wildcards")) << describe(issues);
    EXPECT_TRUE(hasIssue(issues, first + 8, "never ends")) << describe(issues);
    EXPECT_TRUE(hasIssue(issues, first + 9, "expected one action of play, pause")) << describe(issues);
    EXPECT_TRUE(hasIssue(issues, first + 10, "name: empty")) << describe(issues);
}

TEST(TriggerConfig, readsEveryActionWithItsSettings) {
    TempDir dir;
    dir.write("slide.gltf", arcomp::test::slidingTriangle());
    const StationConfig cfg = loadStationConfig(dir.write("station.yaml", std::string(kScene) + R"(show_control:
  osc: {targets: ["127.0.0.1:9000"]}
triggers:
  - name: all
    when: {dwell: left, seconds: 3}
    do:
      - {play: walker, animation: slide}
      - {jump: walker, to: 0.5}
      - {fade: sign, to: 0.5, seconds: 2}
      - {turn: plinth, degrees_per_second: -30, axis: [1, 0, 0]}
      - {snapshot: snaps}
      - {clip: clips, seconds: 4}
      - {osc: /show/cue, args: [3, 0.5, go]}
    on_end: [{stop: walker}]
    cooldown: 5
)"));
    ASSERT_EQ(cfg.triggers.size(), 1u);
    const Trigger& t = cfg.triggers[0];
    EXPECT_EQ(t.when.event, TriggerEvent::Dwell);
    EXPECT_EQ(t.when.zone, 0);
    EXPECT_EQ(t.when.seconds, 3.0);
    EXPECT_EQ(t.cooldownSeconds, 5.0);
    ASSERT_EQ(t.actions.size(), 7u);
    EXPECT_EQ(t.actions[0].animation, "slide");
    EXPECT_EQ(t.actions[1].seconds, 0.5);
    EXPECT_EQ(t.actions[2].opacity, 0.5f);
    EXPECT_EQ(t.actions[3].axis, glm::vec3(1, 0, 0));
    EXPECT_EQ(t.actions[3].degreesPerSecond, -30.0f);
    EXPECT_EQ(t.actions[4].folder, dir.path() / "snaps");
    EXPECT_EQ(t.actions[5].seconds, 4.0);
    ASSERT_EQ(t.actions[6].args.size(), 3u);
    EXPECT_EQ(t.actions[6].args[0].type, OscArgument::Type::Int);
    EXPECT_EQ(t.actions[6].args[1].type, OscArgument::Type::Float);
    EXPECT_EQ(t.actions[6].args[2].s, "go");
    ASSERT_EQ(t.onEnd.size(), 1u);
    EXPECT_EQ(t.onEnd[0].kind, ActionKind::Stop);
}
