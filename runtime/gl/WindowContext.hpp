#pragma once
// A GLFW window with its own context: the kiosk's screen. Under Xvfb it is a
// real X window, so tests exercise the same path as a station.
//
//   auto window = WindowContext::create({.title = "arcomp", .size = {1280, 720}}, GlRequest::Auto);
//   while (!window->shouldClose()) { draw(); window->swap(); window->poll(); }

#include "runtime/gl/GlContext.hpp"

#include <glm/glm.hpp>

#include <functional>

struct GLFWwindow;

namespace arcomp {

struct WindowSettings {
    std::string title = "arcomp";
    glm::ivec2 size{1280, 720};
    bool fullscreen = false;
    int monitor = 0;  // index into the connected monitors, for fullscreen
    bool vsync = true;
    bool hideCursor = false;
};

class WindowContext final : public GlContext {
public:
    static std::unique_ptr<WindowContext> create(const WindowSettings& settings, GlRequest request);
    ~WindowContext() override;
    void makeCurrent() override;

    bool shouldClose() const;
    void requestClose();
    void swap();
    void poll();
    glm::ivec2 framebufferSize() const;
    glm::dvec2 cursor() const;  // in window pixels, origin top-left
    // Called with the GLFW key code on each key press.
    void onKey(std::function<void(int key)> handler);

private:
    WindowContext() = default;
    GLFWwindow* window_ = nullptr;
    std::function<void(int)> keyHandler_;
};

}  // namespace arcomp
