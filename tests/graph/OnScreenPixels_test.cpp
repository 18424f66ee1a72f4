// The pixels the cost model charges: the bounding sphere's screen disc,
// clipped to the viewport.
#include "graph/budget/OnScreenPixels.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace arcomp;

namespace {

// 60° vertical, 16:9, looking down -Z from the origin; the screen's edges
// at 10 m in front of the eye.
const View kView = View::lookAt({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 60.0f, {1280, 720});
const float kTop = 10.0f * std::tan(glm::radians(30.0f));
const float kRight = kTop * 16.0f / 9.0f;

}  // namespace

TEST(OnScreenPixels, aDiscInsideTheViewportCountsWhole) {
    EXPECT_FLOAT_EQ(onScreenShare({{0.0f, 0.0f, -10.0f}, 1.0f}, kView), 1.0f);
}

TEST(OnScreenPixels, aDiscCentredOnAnEdgeCountsHalfAndInACornerAQuarter) {
    EXPECT_NEAR(onScreenShare({{kRight, 0.0f, -10.0f}, 1.0f}, kView), 0.5f, 0.01f);
    EXPECT_NEAR(onScreenShare({{0.0f, -kTop, -10.0f}, 1.0f}, kView), 0.5f, 0.01f);
    EXPECT_NEAR(onScreenShare({{kRight, kTop, -10.0f}, 1.0f}, kView), 0.25f, 0.01f);
}

TEST(OnScreenPixels, aDiscOverAnEdgeCountsThePartOnScreen) {
    // Radius 3 at 10 m: a disc of 187 pixels' radius around a point 100
    // pixels left of the right edge.
    const View& v = kView;
    const float radiusPx = 3.0f / 10.0f * v.pixelScale();
    const float x = kRight - 100.0f / v.pixelScale() * 10.0f;
    const float share = onScreenShare({{x, 0.0f, -10.0f}, 3.0f}, v);
    // The part of the disc left of a chord 100 px right of its centre.
    const float d = 100.0f / radiusPx;
    const float outside = (std::acos(d) - d * std::sqrt(1.0f - d * d)) / std::numbers::pi_v<float>;
    EXPECT_NEAR(share, 1.0f - outside, 0.01f);
}

TEST(OnScreenPixels, anObjectOffScreenCountsNothingAndOneAroundTheEyeCountsWhole) {
    EXPECT_NEAR(onScreenShare({{3.0f * kRight, 0.0f, -10.0f}, 1.0f}, kView), 0.0f, 1e-6f);
    EXPECT_FLOAT_EQ(onScreenShare({{0.0f, 0.0f, -0.5f}, 1.0f}, kView), 1.0f);
}

TEST(OnScreenPixels, scalesTheSelectPassesScreenAreaByTheShare) {
    Scene scene;
    const NodeId box = scene.addMesh(scene.root(), {scene.addGeometry(makeBox({1, 1, 1})), scene.addMaterial({})});
    scene.setLocal(box, glm::translate(glm::mat4(1.0f), glm::vec3(kRight, 0.0f, -10.0f)));
    scene.update();
    const DrawItem item{box, scene.meshPart(box), 10.0f, 5000.0f, 0, Shading::Phong};
    EXPECT_NEAR(onScreenPixels(item, scene, kView), 2500.0f, 50.0f);
}

TEST(OnScreenPixels, aBoxAheadCoversTheRectangleAroundItsNearFace) {
    const Box cube{{-0.5f, -0.5f, -10.5f}, {0.5f, 0.5f, -9.5f}};
    const float side = 1.0f / 9.5f * kView.pixelScale();
    EXPECT_NEAR(boxRectanglePixels(cube, glm::mat4(1.0f), kView), side * side, 0.01f * side * side);
}

TEST(OnScreenPixels, aBoxAroundTheEyeCoversTheScreenAndOneBehindItNothing) {
    EXPECT_FLOAT_EQ(boxRectanglePixels({{-1, -1, -1}, {1, 1, 1}}, glm::mat4(1.0f), kView), 1280.0f * 720.0f);
    EXPECT_FLOAT_EQ(boxRectanglePixels({{-1, -1, 1}, {1, 1, 3}}, glm::mat4(1.0f), kView), 0.0f);
    EXPECT_FLOAT_EQ(boxRectanglePixels({}, glm::mat4(1.0f), kView), 0.0f);
}

// A 2 x 2 x 4 box to the right of the eye, from 1 to 3 m: its sphere
// (radius 2.45 around x = 2) holds the eye. The item is charged the whole
// screen by the select pass, as such an item is.
struct BoxBesideTheEye {
    Scene scene;
    DrawItem item;
    BoxBesideTheEye() {
        const NodeId box = scene.addMesh(scene.root(), {scene.addGeometry(makeBox({2, 2, 4})), scene.addMaterial({})});
        scene.setLocal(box, glm::translate(glm::mat4(1.0f), glm::vec3(2.0f, 0.0f, 0.0f)));
        scene.update();
        item = {box, scene.meshPart(box), 2.0f, kScreen, 0, Shading::Phong};
    }
    static constexpr float kScreen = 1280.0f * 720.0f;
};

TEST(OnScreenPixels, anObjectWhoseSphereHoldsTheEyeIsChargedItsPartOfTheScreenNotAllOfIt) {
    // Its near end reaches across the whole height of the screen's right
    // part, which starts where its far left edge (x = 1, 2 m ahead) projects.
    const BoxBesideTheEye b;
    const float leftNdc = 0.5f / std::tan(glm::radians(30.0f)) / (16.0f / 9.0f);
    const float expected = (1.0f - leftNdc) * 0.5f * BoxBesideTheEye::kScreen;
    EXPECT_NEAR(onScreenPixels(b.item, b.scene, kView), expected, 0.01f * expected);
    EXPECT_LT(expected, 0.3f * BoxBesideTheEye::kScreen);
}

TEST(OnScreenPixels, aSkinnedMeshKeepsItsDisc) {
    BoxBesideTheEye b;
    b.item.part.skin = 0;
    EXPECT_FLOAT_EQ(onScreenPixels(b.item, b.scene, kView), BoxBesideTheEye::kScreen);
}
