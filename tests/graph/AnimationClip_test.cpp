// Sampling as the glTF 2.0 spec's Appendix C defines it, with the numbers
// worked by hand, and the player's clock (loop, hold, speed).

#include "graph/animation/AnimationPlayer.hpp"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>

using namespace arcomp;

namespace {

void expectVec(const glm::vec4& got, const glm::vec4& want, float tolerance = 1e-6f) {
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(got[i], want[i], tolerance) << "component " << i;
}

AnimationChannel channel(AnimationPath path, Interpolation i, std::vector<float> times, std::vector<glm::vec4> values) {
    return {.target = 0, .path = path, .interpolation = i, .times = std::move(times), .values = std::move(values)};
}

// (x, y, z, w) of a rotation by `degrees` about +Z.
glm::vec4 aboutZ(float degrees) {
    const float half = glm::radians(degrees) / 2.0f;
    return {0.0f, 0.0f, std::sin(half), std::cos(half)};
}

}  // namespace

TEST(AnimationSample, linearIsLerpBetweenKeysAndHoldsOutsideThem) {
    const auto c =
        channel(AnimationPath::Translation, Interpolation::Linear, {1.0f, 3.0f}, {{0, 0, 0, 0}, {4, 2, -2, 0}});
    expectVec(sample(c, 1.0f), {0, 0, 0, 0});
    expectVec(sample(c, 3.0f), {4, 2, -2, 0});
    expectVec(sample(c, 1.5f), {1, 0.5f, -0.5f, 0});
    expectVec(sample(c, 2.0f), {2, 1, -1, 0});
    expectVec(sample(c, 0.0f), {0, 0, 0, 0});  // before the first key: the first value
    expectVec(sample(c, -5.0f), {0, 0, 0, 0});
    expectVec(sample(c, 9.0f), {4, 2, -2, 0});  // after the last: the last value
}

TEST(AnimationSample, linearFindsTheRightIntervalAmongSeveral) {
    const auto c = channel(AnimationPath::Scale, Interpolation::Linear, {0.0f, 1.0f, 3.0f},
                           {{1, 1, 1, 0}, {3, 1, 1, 0}, {3, 5, 1, 0}});
    expectVec(sample(c, 0.5f), {2, 1, 1, 0});
    expectVec(sample(c, 1.0f), {3, 1, 1, 0});
    expectVec(sample(c, 2.5f), {3, 4, 1, 0});
}

TEST(AnimationSample, stepHoldsThePreviousKey) {
    const auto c = channel(AnimationPath::Translation, Interpolation::Step, {0.0f, 1.0f, 2.0f},
                           {{1, 0, 0, 0}, {2, 0, 0, 0}, {3, 0, 0, 0}});
    expectVec(sample(c, 0.0f), {1, 0, 0, 0});
    expectVec(sample(c, 0.99f), {1, 0, 0, 0});
    expectVec(sample(c, 1.0f), {2, 0, 0, 0});
    expectVec(sample(c, 1.5f), {2, 0, 0, 0});
    expectVec(sample(c, 2.0f), {3, 0, 0, 0});
    expectVec(sample(c, 7.0f), {3, 0, 0, 0});
    expectVec(sample(c, -1.0f), {1, 0, 0, 0});
}

// Keys at 0 s (value 0, out-tangent 1/s) and 2 s (in-tangent 2/s, value 1).
// Midway u = 0.5, td = 2: 2·(1/8 − 2/4 + 1/2)·1 + (−2/8 + 3/4)·1 + 2·(1/8 − 1/4)·2
// = 0.25 + 0.5 − 0.5 = 0.25. The first key's in-tangent and the last key's
// out-tangent (99) are never used.
TEST(AnimationSample, cubicSplineIsTheHermiteWithTangentsScaledByTheInterval) {
    const auto c =
        channel(AnimationPath::Translation, Interpolation::CubicSpline, {0.0f, 2.0f},
                {{99, 99, 99, 0}, {0, 10, 0, 0}, {1, 0, 0, 0}, {2, 0, 0, 0}, {1, 10, 0, 0}, {99, 99, 99, 0}});
    expectVec(sample(c, 0.0f), {0, 10, 0, 0});
    expectVec(sample(c, 2.0f), {1, 10, 0, 0});
    expectVec(sample(c, 1.0f), {0.25f, 10, 0, 0});
    // u = 0.25: t³ = 1/64, t² = 1/16. 2·(1/64 − 2/16 + 1/4) + (−2/64 + 3/16) + 2·(1/64 − 1/16)·2
    expectVec(
        sample(c, 0.5f),
        {2.0f * (1.0f / 64 - 2.0f / 16 + 0.25f) + (-2.0f / 64 + 3.0f / 16) + 4.0f * (1.0f / 64 - 1.0f / 16), 10, 0, 0});
    expectVec(sample(c, -1.0f), {0, 10, 0, 0});
    expectVec(sample(c, 3.0f), {1, 10, 0, 0});
}

TEST(AnimationSample, cubicSplineRotationsAreNormalised) {
    // Zero tangents: midway is the mean of the keys, normalised, which is the
    // 45° rotation between 0° and 90°.
    const glm::vec4 zero(0.0f);
    const auto c = channel(AnimationPath::Rotation, Interpolation::CubicSpline, {0.0f, 1.0f},
                           {zero, aboutZ(0.0f), zero, zero, aboutZ(90.0f), zero});
    const glm::vec4 mid = sample(c, 0.5f);
    EXPECT_NEAR(glm::length(mid), 1.0f, 1e-6f);
    expectVec(mid, aboutZ(45.0f), 1e-6f);
}

TEST(AnimationSample, linearRotationIsSlerpNotNormalisedLerp) {
    const auto c = channel(AnimationPath::Rotation, Interpolation::Linear, {0.0f, 1.0f}, {aboutZ(0.0f), aboutZ(90.0f)});
    expectVec(sample(c, 0.5f), aboutZ(45.0f), 1e-6f);
    // Normalised lerp would give 21.6° here; slerp's angle is linear in time.
    expectVec(sample(c, 0.25f), aboutZ(22.5f), 1e-6f);
    expectVec(sample(c, 0.75f), aboutZ(67.5f), 1e-6f);
}

TEST(AnimationSample, slerpTakesTheShortPathWhenTheNextKeyIsNegated) {
    // -q is the same 90° rotation as q; the short path passes through 45°,
    // the long one through -135°.
    const auto c =
        channel(AnimationPath::Rotation, Interpolation::Linear, {0.0f, 1.0f}, {aboutZ(0.0f), -aboutZ(90.0f)});
    const glm::vec4 q = sample(c, 0.5f);
    const glm::vec3 x = glm::quat(q.w, q.x, q.y, q.z) * glm::vec3(1, 0, 0);
    EXPECT_NEAR(x.x, std::sqrt(0.5f), 1e-6f);
    EXPECT_NEAR(x.y, std::sqrt(0.5f), 1e-6f);
    EXPECT_NEAR(x.z, 0.0f, 1e-6f);
}

TEST(AnimationSample, clipDurationIsTheLastKeyOfAnyChannel) {
    AnimationClip clip;
    EXPECT_EQ(clip.duration(), 0.0f);
    clip.channels.push_back(
        channel(AnimationPath::Scale, Interpolation::Step, {0.0f, 1.5f}, {glm::vec4(1), glm::vec4(2)}));
    clip.channels.push_back(
        channel(AnimationPath::Scale, Interpolation::Step, {0.5f, 2.5f}, {glm::vec4(1), glm::vec4(2)}));
    EXPECT_FLOAT_EQ(clip.duration(), 2.5f);
}

TEST(AnimationSample, findsAClipByNameThenByIndex) {
    std::vector<AnimationClip> clips(3);
    clips[0].name = "walk";
    clips[1].name = "2";
    clips[2].name = "run";
    EXPECT_EQ(findAnimation(clips, "run"), 2u);
    EXPECT_EQ(findAnimation(clips, "2"), 1u);  // the name wins over index 2
    EXPECT_EQ(findAnimation(clips, "0"), 0u);
    EXPECT_FALSE(findAnimation(clips, "3"));
    EXPECT_FALSE(findAnimation(clips, "jump"));
    EXPECT_FALSE(findAnimation(clips, ""));
    EXPECT_FALSE(findAnimation(clips, "1x"));
    EXPECT_EQ(listAnimations(clips), "0 'walk', 1 '2', 2 'run'");
    EXPECT_EQ(listAnimations({}), "none");
}

namespace {

// One node sliding from x = 0 to x = 4 over 2 s, rotated 90° about Z at rest.
struct Slider {
    Scene scene;
    NodeId node = scene.addTransform(scene.root(), glm::mat4(1.0f), "slider");
    ModelAnimation animation() const {
        ModelAnimation a;
        a.clip.name = "slide";
        a.clip.channels.push_back(
            channel(AnimationPath::Translation, Interpolation::Linear, {0.0f, 2.0f}, {{0, 0, 0, 0}, {4, 0, 0, 0}}));
        Trs rest;
        rest.rotation = glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 0, 1));
        rest.scale = glm::vec3(3.0f);
        a.nodes.push_back({node, rest});
        return a;
    }
    glm::vec3 x() const { return glm::vec3(scene.local(node)[3]); }
};

}  // namespace

TEST(AnimationPlayer, loopsByDefaultAndKeepsTheRestOfTheRestPose) {
    Slider s;
    AnimationPlayer player(s.animation());
    player.apply(s.scene, 0.5);
    EXPECT_NEAR(s.x().x, 1.0f, 1e-6f);
    player.apply(s.scene, 3.0);  // 3 mod 2 = 1 s into the clip
    EXPECT_NEAR(s.x().x, 2.0f, 1e-6f);
    // The channel drives translation only: the rest rotation and scale stay.
    const glm::mat4 expected = glm::scale(
        glm::rotate(glm::translate(glm::mat4(1.0f), {2, 0, 0}), glm::radians(90.0f), {0, 0, 1}), glm::vec3(3.0f));
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) EXPECT_NEAR(s.scene.local(s.node)[c][r], expected[c][r], 1e-5f);
}

TEST(AnimationPlayer, withoutLoopHoldsTheLastPose) {
    Slider s;
    AnimationPlayer player(s.animation(), {.loop = false});
    player.apply(s.scene, 3.0);
    EXPECT_NEAR(s.x().x, 4.0f, 1e-6f);
    EXPECT_DOUBLE_EQ(player.clipTime(100.0), 2.0);
}

TEST(AnimationPlayer, speedScalesTheClock) {
    Slider s;
    AnimationPlayer player(s.animation(), {.speed = 0.5});
    player.apply(s.scene, 1.0);
    EXPECT_NEAR(s.x().x, 1.0f, 1e-6f);
    EXPECT_DOUBLE_EQ(player.clipTime(5.0), 0.5);  // 2.5 clip seconds, looped
    EXPECT_THROW(AnimationPlayer(s.animation(), {.speed = -1.0}), std::invalid_argument);
    EXPECT_THROW(AnimationPlayer(s.animation(), {.speed = 0.0}), std::invalid_argument);
    EXPECT_THROW(AnimationPlayer(s.animation(), {.speed = std::nan("")}), std::invalid_argument);
}

TEST(AnimationPlayer, theTransportPlaysPausesStopsAndJumpsOnTheSameClock) {
    Slider s;
    AnimationPlayer player(s.animation(), {.loop = false, .speed = 2.0});
    player.stop();
    EXPECT_EQ(player.clipTime(7.0), 0.0);
    player.play(10.0);
    EXPECT_DOUBLE_EQ(player.clipTime(10.25), 0.5) << "from its start at the play, at twice the speed";
    player.pause(10.5);
    EXPECT_DOUBLE_EQ(player.clipTime(20.0), 1.0);
    player.play(30.0);
    EXPECT_DOUBLE_EQ(player.clipTime(30.25), 1.5) << "on from where it was held";
    player.play(30.4);
    EXPECT_DOUBLE_EQ(player.clipTime(30.5), 2.0) << "a play while playing changes nothing";
    player.play(40.0);
    EXPECT_DOUBLE_EQ(player.clipTime(40.25), 0.5) << "a clip without loop that ended starts again";
    player.jump(1.25, 41.0);
    EXPECT_DOUBLE_EQ(player.clipTime(41.25), 1.75);
    player.stop();
    player.jump(5.0, 50.0);
    EXPECT_EQ(player.transport(), Transport::Paused);
    EXPECT_DOUBLE_EQ(player.clipTime(60.0), 2.0) << "clamped to the clip, held";
}

TEST(AnimationPlayer, worldMatricesAndBoundsFollowAfterUpdate) {
    Slider s;
    s.scene.addMesh(s.node, {s.scene.addGeometry(makeBox({1, 1, 1})), s.scene.addMaterial({})});
    s.scene.update();
    AnimationPlayer player(s.animation());
    player.apply(s.scene, 1.0);
    s.scene.update();
    EXPECT_NEAR(s.scene.world(s.node)[3].x, 2.0f, 1e-6f);
    EXPECT_NEAR(s.scene.worldBound(s.node).center.x, 2.0f, 1e-5f);
    EXPECT_NEAR(s.scene.bound().center.x, 2.0f, 1e-5f);
}

TEST(AnimationSample, headerExample) {
    // graph/animation/AnimationClip.hpp
    AnimationChannel c{.target = 0,
                       .path = AnimationPath::Translation,
                       .interpolation = Interpolation::Linear,
                       .times = {0.0f, 1.0f},
                       .values = {{0, 0, 0, 0}, {2, 0, 0, 0}}};
    glm::vec4 v = sample(c, 0.25f);  // (0.5, 0, 0, 0)
    EXPECT_EQ(v, glm::vec4(0.5f, 0, 0, 0));
}
