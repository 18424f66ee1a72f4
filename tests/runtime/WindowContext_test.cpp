// The windowed path: a GLFW window (under Xvfb in CI, registered by
// tests/CMakeLists.txt through xvfb-run) drawn by the same renderer.

#include "graph/core/SelectPass.hpp"
#include "runtime/gl/WindowContext.hpp"
#include "runtime/render/Renderer.hpp"

#include <gtest/gtest.h>

#include <cstdlib>

using namespace arcomp;

TEST(WindowContext, sameRendererDrawsIntoAWindowOnEachApi) {
    if (!std::getenv("DISPLAY")) GTEST_SKIP() << "no X display; ctest runs this under xvfb-run";
    for (GlRequest request : {GlRequest::Gl33, GlRequest::Es3}) {
        auto window = WindowContext::create({.title = "arcomp test", .size = {200, 150}, .vsync = false}, request);
        EXPECT_EQ(window->api(), request == GlRequest::Gl33 ? GlApiKind::Gl33 : GlApiKind::Es3);
        World world;
        Scene& scene = world.scene;
        scene.addMesh(scene.root(), {scene.addGeometry(makeBox({2, 2, 2})),
                                     scene.addMaterial({.name = "red", .baseColor = {1, 0, 0, 1}})});
        scene.update();
        const glm::ivec2 size = window->framebufferSize();
        ASSERT_GT(size.x, 0);
        const View view = View::lookAt({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 45, size);
        DrawList list;
        select(world, view, {.shading = Shading::Unlit}, list);
        gl::glBindFramebuffer(GL_FRAMEBUFFER, 0);
        gl::glViewport(0, 0, size.x, size.y);
        Renderer renderer;
        renderer.draw(scene, list, view, {.clearColor = glm::vec4(0, 0, 1, 1)});
        std::uint8_t centre[4] = {}, corner[4] = {};
        gl::glReadPixels(size.x / 2, size.y / 2, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, centre);
        gl::glReadPixels(1, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, corner);
        window->swap();
        window->poll();
        EXPECT_EQ(centre[0], 255) << toString(window->api());
        EXPECT_EQ(centre[2], 0);
        EXPECT_EQ(corner[2], 255) << "clear colour in the corner";
    }
}
