#include "runtime/gl/GlContext.hpp"

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <stdexcept>
#include <vector>

namespace arcomp {

GlRequest parseGlRequest(const std::string& text) {
    if (text == "auto") return GlRequest::Auto;
    if (text == "gl33") return GlRequest::Gl33;
    if (text == "es3") return GlRequest::Es3;
    throw std::invalid_argument("unknown GL API '" + text + "'; expected auto, gl33 or es3");
}

namespace {

// Mesa offers a surfaceless platform; NVIDIA's EGL offers devices instead.
// Try both, then the default display, so the same binary runs on llvmpipe,
// a kiosk GPU and a headless server GPU.
EGLDisplay openDisplay(std::string& why) {
    auto getPlatformDisplay =
        reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (getPlatformDisplay) {
        EGLDisplay d = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (d != EGL_NO_DISPLAY && eglInitialize(d, nullptr, nullptr)) return d;
        why += "surfaceless platform unavailable; ";
        auto queryDevices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
        if (queryDevices) {
            EGLDeviceEXT devices[8];
            EGLint count = 0;
            if (queryDevices(8, devices, &count)) {
                for (EGLint i = 0; i < count; ++i) {
                    d = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
                    if (d != EGL_NO_DISPLAY && eglInitialize(d, nullptr, nullptr)) return d;
                }
            }
            why += std::to_string(count) + " EGL devices, none usable; ";
        }
    }
    EGLDisplay d = eglGetDisplay(EGL_DEFAULT_DISPLAY);
    if (d != EGL_NO_DISPLAY && eglInitialize(d, nullptr, nullptr)) return d;
    why += "no default EGL display";
    return EGL_NO_DISPLAY;
}

}  // namespace

bool HeadlessContext::tryCreate(GlApiKind kind, std::string& why) {
    auto display = static_cast<EGLDisplay>(display_);
    const bool es = kind == GlApiKind::Es3;
    if (!eglBindAPI(es ? EGL_OPENGL_ES_API : EGL_OPENGL_API)) {
        why += std::string(toString(kind)) + ": eglBindAPI failed; ";
        return false;
    }
    const EGLint configAttributes[] = {EGL_RENDERABLE_TYPE, es ? EGL_OPENGL_ES3_BIT : EGL_OPENGL_BIT, EGL_SURFACE_TYPE,
                                       EGL_PBUFFER_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint count = 0;
    // Surfaceless rendering needs no surface type; drivers without pbuffer
    // configs still offer one without that requirement.
    if (!eglChooseConfig(display, configAttributes, &config, 1, &count) || count == 0) {
        const EGLint anyConfig[] = {EGL_RENDERABLE_TYPE, es ? EGL_OPENGL_ES3_BIT : EGL_OPENGL_BIT, EGL_NONE};
        if (!eglChooseConfig(display, anyConfig, &config, 1, &count) || count == 0) {
            why += std::string(toString(kind)) + ": no EGL config; ";
            return false;
        }
    }
    std::vector<EGLint> contextAttributes{EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, es ? 0 : 3};
    if (!es)
        contextAttributes.insert(contextAttributes.end(),
                                 {EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT});
    contextAttributes.push_back(EGL_NONE);
    EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, contextAttributes.data());
    if (context == EGL_NO_CONTEXT) {
        why += std::string(toString(kind)) + ": eglCreateContext failed (0x" + std::to_string(eglGetError()) + "); ";
        return false;
    }
    if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
        eglDestroyContext(display, context);
        why += std::string(toString(kind)) + ": cannot make the context current without a surface; ";
        return false;
    }
    context_ = context;
    api_ = kind;
    loadGl(kind, [](const char* name) { return reinterpret_cast<void*>(eglGetProcAddress(name)); });
    return true;
}

std::unique_ptr<HeadlessContext> HeadlessContext::create(GlRequest request) {
    std::unique_ptr<HeadlessContext> ctx(new HeadlessContext);
    std::string why;
    EGLDisplay display = openDisplay(why);
    if (display == EGL_NO_DISPLAY) throw std::runtime_error("no headless OpenGL: " + why);
    ctx->display_ = display;
    if (request != GlRequest::Es3 && ctx->tryCreate(GlApiKind::Gl33, why)) return ctx;
    if (request != GlRequest::Gl33 && ctx->tryCreate(GlApiKind::Es3, why)) return ctx;
    throw std::runtime_error("no headless OpenGL context: " + why);
}

HeadlessContext::~HeadlessContext() {
    auto display = static_cast<EGLDisplay>(display_);
    if (!display) return;
    eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (context_) eglDestroyContext(display, static_cast<EGLContext>(context_));
    eglTerminate(display);
}

void HeadlessContext::makeCurrent() {
    eglMakeCurrent(static_cast<EGLDisplay>(display_), EGL_NO_SURFACE, EGL_NO_SURFACE,
                   static_cast<EGLContext>(context_));
}

}  // namespace arcomp
