#include "runtime/gl/WindowContext.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <stdexcept>

namespace arcomp {

namespace {
std::string lastGlfwError() {
    const char* description = nullptr;
    glfwGetError(&description);
    return description ? description : "unknown GLFW error";
}
}  // namespace

std::unique_ptr<WindowContext> WindowContext::create(const WindowSettings& settings, GlRequest request) {
    if (!glfwInit()) throw std::runtime_error("cannot open a window: " + lastGlfwError());
    GLFWmonitor* monitor = nullptr;
    if (settings.fullscreen) {
        int count = 0;
        GLFWmonitor** monitors = glfwGetMonitors(&count);
        if (count > 0) monitor = monitors[settings.monitor < count ? settings.monitor : 0];
    }
    std::string why;
    for (GlApiKind kind : {GlApiKind::Gl33, GlApiKind::Es3}) {
        if ((kind == GlApiKind::Gl33 && request == GlRequest::Es3) ||
            (kind == GlApiKind::Es3 && request == GlRequest::Gl33))
            continue;
        glfwDefaultWindowHints();
        if (kind == GlApiKind::Gl33) {
            glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_API);
            glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
            glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
            glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
            glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
        } else {
            glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_ES_API);
            glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
            glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 0);
        }
        glm::ivec2 size = settings.size;
        if (monitor) {
            const GLFWvidmode* mode = glfwGetVideoMode(monitor);
            size = {mode->width, mode->height};
        }
        GLFWwindow* window = glfwCreateWindow(size.x, size.y, settings.title.c_str(), monitor, nullptr);
        if (!window) {
            why += std::string(toString(kind)) + ": " + lastGlfwError() + "; ";
            continue;
        }
        std::unique_ptr<WindowContext> ctx(new WindowContext);
        ctx->window_ = window;
        ctx->api_ = kind;
        glfwMakeContextCurrent(window);
        glfwSwapInterval(settings.vsync ? 1 : 0);
        if (settings.hideCursor) glfwSetInputMode(window, GLFW_CURSOR, GLFW_CURSOR_HIDDEN);
        glfwSetWindowUserPointer(window, ctx.get());
        glfwSetKeyCallback(window, [](GLFWwindow* w, int key, int, int action, int) {
            auto* self = static_cast<WindowContext*>(glfwGetWindowUserPointer(w));
            if (action == GLFW_PRESS && self->keyHandler_) self->keyHandler_(key);
        });
        loadGl(kind, [](const char* name) { return reinterpret_cast<void*>(glfwGetProcAddress(name)); });
        return ctx;
    }
    glfwTerminate();
    throw std::runtime_error("cannot open an OpenGL window: " + why);
}

WindowContext::~WindowContext() {
    if (window_) glfwDestroyWindow(window_);
    glfwTerminate();
}

void WindowContext::makeCurrent() { glfwMakeContextCurrent(window_); }
bool WindowContext::shouldClose() const { return glfwWindowShouldClose(window_); }
void WindowContext::requestClose() { glfwSetWindowShouldClose(window_, GLFW_TRUE); }
void WindowContext::swap() { glfwSwapBuffers(window_); }
void WindowContext::poll() { glfwPollEvents(); }
void WindowContext::onKey(std::function<void(int)> handler) { keyHandler_ = std::move(handler); }

glm::ivec2 WindowContext::framebufferSize() const {
    glm::ivec2 s;
    glfwGetFramebufferSize(window_, &s.x, &s.y);
    return s;
}

glm::dvec2 WindowContext::cursor() const {
    glm::dvec2 c;
    glfwGetCursorPos(window_, &c.x, &c.y);
    return c;
}

}  // namespace arcomp
