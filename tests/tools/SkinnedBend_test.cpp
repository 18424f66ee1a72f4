// The skinned-bend feature model through the whole path: loaded with its
// skin, posed by its animation, culled by a bound that covers every pose and
// drawn with GPU skinning, on OpenGL 3.3 and on OpenGL ES 3.0.
#include "tools/bench/scenes/GltfFeatureModels.hpp"

#include "graph/animation/AnimationPlayer.hpp"
#include "graph/animation/Skinning.hpp"
#include "graph/core/SelectPass.hpp"
#include "graph/io/ModelLoader.hpp"
#include "runtime/gl/GlContext.hpp"
#include "runtime/gl/RenderTarget.hpp"
#include "runtime/render/Renderer.hpp"
#include "runtime/station/ImageFile.hpp"

#include "../support/TempDir.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>

namespace arcomp {
namespace {

using test::TempDir;

constexpr glm::ivec2 kBendSize{128, 128};

const FeatureModel& bendModel() {
    for (const FeatureModel& m : featureModels())
        if (m.name == "skinned-bend") return m;
    throw std::logic_error("no skinned-bend feature model");
}

View bendView() {
    const FeatureCamera& c = bendModel().camera;
    return View::lookAt(c.eye, c.target, {0, 1, 0}, c.fovyDegrees, kBendSize, c.near, c.far);
}

struct Bend {
    World world;
    LoadedModel model;
    NodeId mesh = kNoNode;

    Bend() {
        TempDir dir;
        model = loadModel(writeFeatureModel(bendModel(), dir.path()), world.scene, world.scene.root());
        for (NodeId n = 0; n < world.scene.nodeCount(); ++n)
            if (world.scene.kind(n) == NodeKind::Mesh) mesh = n;
        world.scene.update();
    }
    void pose(double seconds) {
        AnimationPlayer(model.animations.at(0), {.loop = false}).apply(world.scene, seconds);
        world.scene.update();
    }
};

Image draw(World& world, GlRequest api) {
    auto ctx = HeadlessContext::create(api);
    RenderTarget target(kBendSize);
    target.bind();
    Renderer renderer;
    DrawList list;
    const View view = bendView();
    select(world, view, {.shading = Shading::Phong}, list);
    renderer.draw(world.scene, list, view, {});
    return target.read();
}

int channelDifference(const Image& a, const Image& b, std::size_t pixel) {
    int d = 0;
    for (std::size_t c = 0; c < 4; ++c)
        d = std::max(d, std::abs(int(a.rgba[pixel * 4 + c]) - int(b.rgba[pixel * 4 + c])));
    return d;
}

// The image row where a point of the world lands.
int rowOf(const glm::vec3& p) {
    const glm::vec4 clip = bendView().viewProjection() * glm::vec4(p, 1.0f);
    return static_cast<int>((1.0f - (clip.y / clip.w * 0.5f + 0.5f)) * static_cast<float>(kBendSize.y));
}

class SkinnedBend : public ::testing::TestWithParam<GlRequest> {
protected:
    void saveOnFailure(const Image& img, const std::string& name) const {
        if (HasFailure())
            writePng(std::string(ARCOMP_TEST_OUTPUT) + "/skinned-bend-" + name +
                         (GetParam() == GlRequest::Es3 ? "-es3" : "-gl33") + ".png",
                     img);
    }
};

TEST_P(SkinnedBend, atTimeZeroItIsTheBindPoseAndAtOneSecondOnlyTheUpperHalfHasMoved) {
    Bend skinned;
    ASSERT_NE(skinned.mesh, kNoNode);
    ASSERT_NE(skinned.world.scene.meshPart(skinned.mesh).skin, kNoSkin);
    // The bind pose: the same geometry and material drawn rigidly where the
    // skinned mesh's node is.
    World rigid;
    {
        const Scene& s = skinned.world.scene;
        const MeshPart& part = s.meshPart(skinned.mesh);
        const NodeId place = rigid.scene.addTransform(rigid.scene.root(), s.world(skinned.mesh));
        rigid.scene.addMesh(place, {rigid.scene.addGeometry(s.geometry(part.geometry)),
                                    rigid.scene.addMaterial(s.material(part.material))});
        rigid.scene.update();
    }
    const Image bind = draw(rigid, GetParam());
    skinned.pose(0.0);
    const Image start = draw(skinned.world, GetParam());
    skinned.pose(1.0);
    const Image bent = draw(skinned.world, GetParam());

    std::size_t covered = 0, startOff = 0;
    for (std::size_t p = 0; p < std::size_t(kBendSize.x * kBendSize.y); ++p) {
        covered += bind.rgba[p * 4 + 3] > 0;
        startOff += channelDifference(bind, start, p) > 2;
    }
    EXPECT_GT(covered, 500u) << "the tube is in view";
    EXPECT_EQ(startOff, 0u) << "t = 0 differs from the bind pose";

    // Below y = -0.4 every weight is on the base joint, which does not move;
    // above y = 0.4 all is on the bending joint, which turns 45 degrees by 1 s.
    const int lowTop = rowOf({0, -0.4f, 0}), lowBottom = rowOf({0, -1.0f, 0});
    const int highTop = rowOf({0, 1.0f, 0}), highBottom = rowOf({0, 0.4f, 0});
    ASSERT_LT(highTop, highBottom);
    ASSERT_LT(highBottom, lowTop);
    std::size_t lowChanged = 0, highChanged = 0;
    for (int y = 0; y < kBendSize.y; ++y)
        for (int x = 0; x < kBendSize.x; ++x) {
            const auto p = std::size_t(y * kBendSize.x + x);
            const bool changed = channelDifference(start, bent, p) > 2;
            if (y > lowTop + 1 && y <= lowBottom) lowChanged += changed;
            if (y >= highTop && y < highBottom - 1) highChanged += changed;
        }
    EXPECT_EQ(lowChanged, 0u) << "the base moved";
    EXPECT_GT(highChanged, 100u) << "the upper half did not bend";
    saveOnFailure(bind, "bind");
    saveOnFailure(start, "t0");
    saveOnFailure(bent, "t1");
}

INSTANTIATE_TEST_SUITE_P(Apis, SkinnedBend, ::testing::Values(GlRequest::Gl33, GlRequest::Es3),
                         [](const auto& info) { return info.param == GlRequest::Gl33 ? "gl33" : "es3"; });

// The bound the loader fits holds every vertex of every pose, sampled here
// at times between its own samples; the bent tube leaves the bind pose's
// box, so the poses are not the bind pose in disguise.
TEST(SkinnedBendBound, theWorldBoundCoversThePosedMeshAtEverySampledTime) {
    Bend b;
    const Scene& scene = b.world.scene;
    const MeshPart part = scene.meshPart(b.mesh);
    const Geometry& g = scene.geometry(part.geometry);
    bool leavesBindBox = false;
    for (int step = 0; step <= 90; ++step) {
        const double t = step * (2.0 / 90.0) + 0.0011;
        b.pose(t);
        const Sphere& bound = scene.worldBound(b.mesh);
        for (const glm::vec3& p : skinPositions(g, scene.jointMatrices(part.skin))) {
            const glm::vec3 w = glm::vec3(scene.world(b.mesh) * glm::vec4(p, 1.0f));
            ASSERT_LE(glm::length(w - bound.center), bound.radius + 1e-4f) << "at t = " << t;
            leavesBindBox |=
                glm::any(glm::lessThan(p, g.box.min - 1e-3f)) || glm::any(glm::greaterThan(p, g.box.max + 1e-3f));
        }
    }
    EXPECT_TRUE(leavesBindBox) << "the bend never leaves the bind pose's box: this test shows nothing";
}

}  // namespace
}  // namespace arcomp
