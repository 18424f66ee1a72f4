// The point-cloud layer over CG: configs/translucent-trees.yaml rendered
// three ways (CG only, clouds only, both) and compared where the config
// puts a box in front of a tree and a ball behind one.

#include "graph/core/SelectPass.hpp"
#include "runtime/gl/GlContext.hpp"
#include "runtime/gl/RenderTarget.hpp"
#include "runtime/render/PointCloudLayer.hpp"
#include "runtime/render/Renderer.hpp"
#include "runtime/station/SceneFile.hpp"

#include <gtest/gtest.h>

#include <cstdlib>

using namespace arcomp;

namespace {

struct Renders {
    Image cgOnly, cloudsOnly, both;
};

glm::ivec4 cloudPixelAt(const Image& img, glm::ivec2 p) {
    const std::size_t i =
        (static_cast<std::size_t>(p.y) * static_cast<std::size_t>(img.width) + static_cast<std::size_t>(p.x)) * 4;
    return {img.rgba[i], img.rgba[i + 1], img.rgba[i + 2], img.rgba[i + 3]};
}

// Pixels (top-down rows) whose centres lie within `radius` world units of
// `center` as projected, i.e. inside the object's silhouette core.
std::vector<glm::ivec2> pixelsAround(const View& view, glm::vec3 center, float radius) {
    const glm::vec4 clip = view.viewProjection() * glm::vec4(center, 1.0f);
    const glm::vec2 c = (glm::vec2(clip.x, -clip.y) / clip.w * 0.5f + 0.5f) * glm::vec2(view.viewport);
    const float r = radius / glm::dot(center - view.eye, view.forward) * view.pixelScale();
    std::vector<glm::ivec2> out;
    for (int y = static_cast<int>(c.y - r); y <= static_cast<int>(c.y + r); ++y)
        for (int x = static_cast<int>(c.x - r); x <= static_cast<int>(c.x + r); ++x)
            if (glm::distance(glm::vec2(x + 0.5f, y + 0.5f), c) < r) out.emplace_back(x, y);
    return out;
}

class TranslucentTrees : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        file_ = std::make_unique<SceneFile>(
            loadSceneFile(std::string(ARCOMP_SOURCE_DIR) + "/configs/translucent-trees.yaml"));
        file_->world.scene.update();
        const View view = *file_->camera;
        auto ctx = HeadlessContext::create(GlRequest::Auto);
        RenderTarget target(view.viewport);
        target.bind();
        Renderer renderer;
        PointCloudLayer layer;
        DrawList list, none;
        select(file_->world, view, {.lod = false, .grouping = false}, list);
        renders_ = std::make_unique<Renders>();
        renderer.draw(file_->world.scene, list, view, {.clearColor = glm::vec4(0.0f)});
        renders_->cgOnly = target.read();
        renderer.draw(file_->world.scene, none, view, {.clearColor = glm::vec4(0.0f)});
        layer.draw(file_->world.scene, file_->world.pointClouds, list.pointClouds, view);
        renders_->cloudsOnly = target.read();
        clouds_ = layer.cloudsDrawn();
        renderer.draw(file_->world.scene, list, view, {.clearColor = glm::vec4(0.0f)});
        layer.draw(file_->world.scene, file_->world.pointClouds, list.pointClouds, view);
        renders_->both = target.read();
    }
    static void TearDownTestSuite() {
        renders_.reset();
        file_.reset();
    }
    static inline std::unique_ptr<SceneFile> file_;
    static inline std::unique_ptr<Renders> renders_;
    static inline std::size_t clouds_ = 0;
};

}  // namespace

TEST_F(TranslucentTrees, configAddsBothCloudsAndTheLayerDrawsThem) {
    EXPECT_TRUE(file_->warnings.empty());
    EXPECT_EQ(file_->world.pointClouds.size(), 2u);
    EXPECT_EQ(clouds_, 2u);
}

TEST_F(TranslucentTrees, boxInFrontHidesTheTrunk) {
    std::size_t overCloud = 0;
    for (glm::ivec2 p : pixelsAround(*file_->camera, {0.0f, 0.45f, 1.0f}, 0.15f)) {
        if (cloudPixelAt(renders_->cloudsOnly, p).a == 0) continue;
        ++overCloud;
        EXPECT_EQ(cloudPixelAt(renders_->both, p), cloudPixelAt(renders_->cgOnly, p)) << "at " << p.x << "," << p.y;
    }
    EXPECT_GT(overCloud, 20u) << "the trunk must lie behind the box for this test to mean anything";
}

TEST_F(TranslucentTrees, ballBehindTheCrownShowsThroughTheLeaves) {
    std::size_t blended = 0;
    for (glm::ivec2 p : pixelsAround(*file_->camera, {0.1f, 1.75f, -1.4f}, 0.3f)) {
        const glm::ivec4 cloud = cloudPixelAt(renders_->cloudsOnly, p), ball = cloudPixelAt(renders_->cgOnly, p),
                         both = cloudPixelAt(renders_->both, p);
        if (cloud.a < 20 || cloud.a > 235) continue;  // translucent layer pixels only
        ++blended;
        // Not the ball alone, not the cloud alone: the cloud over the ball.
        EXPECT_GT(std::abs(both.b - ball.b) + std::abs(both.g - ball.g), 8) << "at " << p.x << "," << p.y;
        EXPECT_GT(both.b, cloud.b + 10) << "the blue ball shows through at " << p.x << "," << p.y;
        EXPECT_EQ(both.a, 255);
    }
    EXPECT_GT(blended, 20u) << "the crown must cover the ball for this test to mean anything";
}
