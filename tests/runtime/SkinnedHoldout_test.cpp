// A skinned, animated object's holdout at a station: baked as its posed full
// mesh, it cuts out exactly what the CG covers in the pose of the frame, on
// OpenGL 3.3 and on OpenGL ES 3.0.

#include "graph/core/SelectPass.hpp"
#include "graph/io/ModelLoader.hpp"
#include "runtime/gl/GlContext.hpp"
#include "runtime/gl/RenderTarget.hpp"
#include "runtime/render/Renderer.hpp"
#include "runtime/station/HoldoutBake.hpp"
#include "runtime/station/ImageFile.hpp"

#include "../support/GltfFile.hpp"
#include "../support/TempDir.hpp"
#include "tests/support/ImagePixels.hpp"

#include <gtest/gtest.h>

using namespace arcomp;
using arcomp::test::GltfFile;
using arcomp::test::TempDir;

namespace {

constexpr glm::ivec2 kHoldoutSize{64, 64};

// The support file's triangle, wholly on joint "bone" (a child of the mesh
// node), which the clip "slide" moves 2 units along x over 1 s.
std::string slidingSkinnedTriangle() {
    GltfFile f;
    f.nodes = R"([{"name": "body", "mesh": 0, "skin": 0, "children": [1]}, {"name": "bone"}])";
    f.skins = R"([{"name": "rig", "joints": [1]}])";
    const std::uint8_t joints[12] = {};
    const int j = f.addBytes(joints, 3, "VEC4", GltfWriter::kUnsignedByte);
    const int w = f.add({1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0}, "VEC4");
    f.attributes = R"(, "JOINTS_0": )" + std::to_string(j) + R"(, "WEIGHTS_0": )" + std::to_string(w);
    const int times = f.add({0, 1}, "SCALAR");
    const int slide = f.add({0, 0, 0, 2, 0, 0}, "VEC3");
    f.animations = R"([{"name": "slide", "samplers": [{"input": )" + std::to_string(times) + R"(, "output": )" +
                   std::to_string(slide) +
                   R"(}], "channels": [{"sampler": 0, "target": {"node": 1, "path": "translation"}}]}])";
    return f.json();
}

// Where something was drawn: the holdout's material is not the CG's.
std::vector<bool> coverMask(const Image& img) {
    std::vector<bool> out;
    for (std::size_t i = 3; i < img.rgba.size(); i += 4) out.push_back(img.rgba[i] > 0);
    return out;
}

class SkinnedHoldout : public ::testing::TestWithParam<GlRequest> {};

TEST_P(SkinnedHoldout, theHoldoutCoversWhatThePosedCgCovers) {
    TempDir dir;
    World world;
    const LoadedModel model =
        loadModel(dir.write("slide.gltf", slidingSkinnedTriangle()), world.scene, world.scene.root());
    ASSERT_TRUE(model.warnings.empty()) << model.warnings.front();
    world.animations.push_back(
        {.player = AnimationPlayer(model.animations.at(0), {.loop = false}), .node = model.root});
    world.scene.update();
    const View view = View::lookAt({1.5f, 0.5f, 4.0f}, {1.5f, 0.5f, 0.0f}, {0, 1, 0}, 60.0f, kHoldoutSize);
    bakeHoldouts(world, view, CompositorConfig{}, {}, {});

    auto ctx = HeadlessContext::create(GetParam());
    Renderer renderer;
    RenderTarget target(kHoldoutSize);
    const RenderSettings coverageOnly{.coverageOnly = true};
    const auto drawAt = [&](double seconds, bool holdout) {
        animateObjects(world, seconds);
        DrawList list;
        select(world, view, {}, list);
        if (holdout) {
            DrawList cut;
            for (const HoldoutItem& h : list.holdouts)
                if (auto item = world.holdouts.itemFor(world.scene, list.items[h.cgItem], view))
                    cut.items.push_back(*item);
            list = cut;
        }
        target.bind();
        renderer.draw(world.scene, list, view, coverageOnly);
        return target.read();
    };
    const Image cgStart = drawAt(0.0, false), holdoutStart = drawAt(0.0, true);
    const Image cgEnd = drawAt(1.0, false), holdoutEnd = drawAt(1.0, true);
    EXPECT_GT(test::coveredPixels(cgStart), 50u);
    EXPECT_EQ(coverMask(holdoutStart), coverMask(cgStart))
        << "at rest: " << test::coveredPixels(holdoutStart) << " vs " << test::coveredPixels(cgStart);
    EXPECT_EQ(coverMask(holdoutEnd), coverMask(cgEnd))
        << "slid by the bone: " << test::coveredPixels(holdoutEnd) << " vs " << test::coveredPixels(cgEnd);
    EXPECT_NE(coverMask(cgEnd), coverMask(cgStart)) << "the bone did not move the triangle";
    if (HasFailure()) {
        const std::string api = GetParam() == GlRequest::Es3 ? "-es3" : "-gl33";
        writePng(std::string(ARCOMP_TEST_OUTPUT) + "/skinned-holdout-cg" + api + ".png", cgEnd);
        writePng(std::string(ARCOMP_TEST_OUTPUT) + "/skinned-holdout-cut" + api + ".png", holdoutEnd);
    }
}

INSTANTIATE_TEST_SUITE_P(Apis, SkinnedHoldout, ::testing::Values(GlRequest::Gl33, GlRequest::Es3),
                         [](const auto& info) { return info.param == GlRequest::Gl33 ? "gl33" : "es3"; });

}  // namespace
