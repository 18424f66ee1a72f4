#include "runtime/gl/GlApi.hpp"

#include <cstring>
#include <stdexcept>

namespace arcomp {

namespace {
GlApiKind g_api = GlApiKind::Gl33;
bool g_timerQueries = false;

bool hasExtension(const char* name) {
    GLint count = 0;
    gl::glGetIntegerv(GL_NUM_EXTENSIONS, &count);
    for (GLint i = 0; i < count; ++i) {
        const auto* ext = reinterpret_cast<const char*>(gl::glGetStringi(GL_EXTENSIONS, static_cast<GLuint>(i)));
        if (ext && std::strcmp(ext, name) == 0) return true;
    }
    return false;
}
}  // namespace

std::string_view toString(GlApiKind kind) { return kind == GlApiKind::Gl33 ? "gl33" : "es3"; }

std::optional<GlApiKind> parseGlApi(std::string_view text, bool& isAuto) {
    isAuto = text == "auto";
    if (text == "gl33") return GlApiKind::Gl33;
    if (text == "es3") return GlApiKind::Es3;
    return std::nullopt;
}

void loadGl(GlApiKind kind, const GetProcAddress& getProc) {
#define ARCOMP_LOAD_GL(suffix, name)                                                                                   \
    gl::name = reinterpret_cast<PFNGL##suffix##PROC>(getProc(#name));                                                  \
    if (!gl::name) throw std::runtime_error("OpenGL entry point " #name " is not available");
    ARCOMP_GL_FUNCTIONS(ARCOMP_LOAD_GL)
#undef ARCOMP_LOAD_GL
    g_api = kind;
    if (kind == GlApiKind::Gl33) {
        gl::glGetQueryObjectui64v = reinterpret_cast<gl::PFNGETQUERYOBJECTUI64>(getProc("glGetQueryObjectui64v"));
        g_timerQueries = gl::glGetQueryObjectui64v != nullptr;
    } else {
        // ES 3.0 has no timer queries; GL_EXT_disjoint_timer_query adds them.
        g_timerQueries = hasExtension("GL_EXT_disjoint_timer_query");
        gl::glGetQueryObjectui64v =
            g_timerQueries ? reinterpret_cast<gl::PFNGETQUERYOBJECTUI64>(getProc("glGetQueryObjectui64vEXT")) : nullptr;
        g_timerQueries = gl::glGetQueryObjectui64v != nullptr;
    }
}

GlApiKind currentGlApi() { return g_api; }

std::string shaderPreamble() {
    if (g_api == GlApiKind::Gl33) return "#version 330 core\n";
    return "#version 300 es\nprecision highp float;\nprecision highp int;\nprecision highp sampler2D;\n";
}

bool hasTimerQueries() { return g_timerQueries; }

bool isSoftwareRasterizer() {
    const auto* r = reinterpret_cast<const char*>(gl::glGetString(GL_RENDERER));
    const std::string renderer = r ? r : "";
    for (const char* name : {"llvmpipe", "softpipe", "SwiftShader"})
        if (renderer.find(name) != std::string::npos) return true;
    return false;
}

std::string glDescription() {
    auto str = [](GLenum e) {
        const auto* s = reinterpret_cast<const char*>(gl::glGetString(e));
        return std::string(s ? s : "?");
    };
    return std::string(toString(g_api)) + ": " + str(GL_VERSION) + " on " + str(GL_RENDERER);
}

}  // namespace arcomp
