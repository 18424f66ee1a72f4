#pragma once
// The one place that knows whether we run on desktop OpenGL 3.3 core or
// OpenGL ES 3.0. Everything else in the renderer writes plain GL calls from
// the common subset and never asks which it is.
//
//   loadGl(GlApiKind::Es3, [](const char* n) { return (void*)eglGetProcAddress(n); });
//   std::string src = shaderPreamble() + body;   // #version line and precision
//
// Functions are loaded through the context's getProcAddress rather than
// linked, so one binary serves a desktop GPU, Mesa's llvmpipe and a GLES-only
// board (which has no libOpenGL). Types and constants come from the GLES 3.0
// header, whose values are the same on desktop GL; the few desktop-only ones
// are defined here.

#define GL_GLES_PROTOTYPES 0
#include <GLES3/gl3.h>

#include <functional>
#include <optional>
#include <string>
#include <string_view>

#ifndef GL_TIME_ELAPSED
#define GL_TIME_ELAPSED 0x88BF  // GL 3.3 core; GL_TIME_ELAPSED_EXT on ES
#endif

namespace arcomp {

enum class GlApiKind { Gl33, Es3 };

std::string_view toString(GlApiKind kind);
// "gl33", "es3"; "auto" gives nullopt (the caller tries Gl33, then Es3).
std::optional<GlApiKind> parseGlApi(std::string_view text, bool& isAuto);

// The list of entry points the renderer uses; X(type-suffix, name).
// clang-format off
#define ARCOMP_GL_FUNCTIONS(X)                              \
    X(ACTIVETEXTURE, glActiveTexture)                       \
    X(ATTACHSHADER, glAttachShader)                         \
    X(BINDATTRIBLOCATION, glBindAttribLocation)             \
    X(BINDBUFFER, glBindBuffer)                             \
    X(BINDFRAMEBUFFER, glBindFramebuffer)                   \
    X(BINDRENDERBUFFER, glBindRenderbuffer)                 \
    X(BINDTEXTURE, glBindTexture)                           \
    X(BINDVERTEXARRAY, glBindVertexArray)                   \
    X(BLENDFUNC, glBlendFunc)                               \
    X(BLENDFUNCSEPARATE, glBlendFuncSeparate)               \
    X(BUFFERDATA, glBufferData)                             \
    X(BUFFERSUBDATA, glBufferSubData)                       \
    X(CHECKFRAMEBUFFERSTATUS, glCheckFramebufferStatus)     \
    X(CLEAR, glClear)                                       \
    X(CLEARCOLOR, glClearColor)                             \
    X(CLEARDEPTHF, glClearDepthf)                           \
    X(COLORMASK, glColorMask)                               \
    X(COMPILESHADER, glCompileShader)                       \
    X(CREATEPROGRAM, glCreateProgram)                       \
    X(CREATESHADER, glCreateShader)                         \
    X(CULLFACE, glCullFace)                                 \
    X(DELETEBUFFERS, glDeleteBuffers)                       \
    X(DELETEFRAMEBUFFERS, glDeleteFramebuffers)             \
    X(DELETEPROGRAM, glDeleteProgram)                       \
    X(DELETEQUERIES, glDeleteQueries)                       \
    X(DELETERENDERBUFFERS, glDeleteRenderbuffers)           \
    X(DELETESHADER, glDeleteShader)                         \
    X(DELETETEXTURES, glDeleteTextures)                     \
    X(DELETEVERTEXARRAYS, glDeleteVertexArrays)             \
    X(DEPTHFUNC, glDepthFunc)                               \
    X(DEPTHMASK, glDepthMask)                               \
    X(DISABLE, glDisable)                                   \
    X(DRAWARRAYS, glDrawArrays)                             \
    X(DRAWELEMENTS, glDrawElements)                         \
    X(ENABLE, glEnable)                                     \
    X(ENABLEVERTEXATTRIBARRAY, glEnableVertexAttribArray)   \
    X(DISABLEVERTEXATTRIBARRAY, glDisableVertexAttribArray) \
    X(VERTEXATTRIB4F, glVertexAttrib4f)                     \
    X(FINISH, glFinish)                                     \
    X(FLUSH, glFlush)                                       \
    X(FRAMEBUFFERRENDERBUFFER, glFramebufferRenderbuffer)   \
    X(FRAMEBUFFERTEXTURE2D, glFramebufferTexture2D)         \
    X(GENBUFFERS, glGenBuffers)                             \
    X(GENFRAMEBUFFERS, glGenFramebuffers)                   \
    X(GENQUERIES, glGenQueries)                             \
    X(GENRENDERBUFFERS, glGenRenderbuffers)                 \
    X(GENTEXTURES, glGenTextures)                           \
    X(GENVERTEXARRAYS, glGenVertexArrays)                   \
    X(GENERATEMIPMAP, glGenerateMipmap)                     \
    X(GETERROR, glGetError)                                 \
    X(GETINTEGERV, glGetIntegerv)                           \
    X(GETPROGRAMINFOLOG, glGetProgramInfoLog)               \
    X(GETPROGRAMIV, glGetProgramiv)                         \
    X(GETSHADERINFOLOG, glGetShaderInfoLog)                 \
    X(GETSHADERIV, glGetShaderiv)                           \
    X(GETSTRING, glGetString)                               \
    X(GETSTRINGI, glGetStringi)                             \
    X(GETUNIFORMLOCATION, glGetUniformLocation)             \
    X(GETQUERYOBJECTUIV, glGetQueryObjectuiv)               \
    X(BEGINQUERY, glBeginQuery)                             \
    X(ENDQUERY, glEndQuery)                                 \
    X(LINKPROGRAM, glLinkProgram)                           \
    X(PIXELSTOREI, glPixelStorei)                           \
    X(READPIXELS, glReadPixels)                             \
    X(READBUFFER, glReadBuffer)                             \
    X(RENDERBUFFERSTORAGE, glRenderbufferStorage)           \
    X(SCISSOR, glScissor)                                   \
    X(SHADERSOURCE, glShaderSource)                         \
    X(STENCILMASK, glStencilMask)                           \
    X(TEXIMAGE2D, glTexImage2D)                             \
    X(TEXSUBIMAGE2D, glTexSubImage2D)                       \
    X(TEXPARAMETERI, glTexParameteri)                       \
    X(UNIFORM1F, glUniform1f)                               \
    X(UNIFORM3FV, glUniform3fv)                             \
    X(UNIFORM1I, glUniform1i)                               \
    X(UNIFORM1IV, glUniform1iv)                             \
    X(UNIFORM2F, glUniform2f)                               \
    X(UNIFORM3F, glUniform3f)                               \
    X(UNIFORM4F, glUniform4f)                               \
    X(UNIFORMMATRIX3FV, glUniformMatrix3fv)                 \
    X(UNIFORMMATRIX3X4FV, glUniformMatrix3x4fv)             \
    X(UNIFORMMATRIX4FV, glUniformMatrix4fv)                 \
    X(USEPROGRAM, glUseProgram)                             \
    X(VERTEXATTRIBPOINTER, glVertexAttribPointer)           \
    X(VIEWPORT, glViewport)                                 \
    X(BLITFRAMEBUFFER, glBlitFramebuffer)                   \
    X(MAPBUFFERRANGE, glMapBufferRange)                     \
    X(UNMAPBUFFER, glUnmapBuffer)
// clang-format on

namespace gl {
#define ARCOMP_DECLARE_GL(suffix, name) inline PFNGL##suffix##PROC name = nullptr;
ARCOMP_GL_FUNCTIONS(ARCOMP_DECLARE_GL)
#undef ARCOMP_DECLARE_GL
// 64-bit timer results: core in GL 3.3, an extension on ES; may stay null.
using PFNGETQUERYOBJECTUI64 = void(GL_APIENTRYP)(GLuint, GLenum, GLuint64*);
inline PFNGETQUERYOBJECTUI64 glGetQueryObjectui64v = nullptr;
}  // namespace gl

using GetProcAddress = std::function<void*(const char*)>;

// Loads every entry point for the current context; throws std::runtime_error
// naming the first one missing.
void loadGl(GlApiKind kind, const GetProcAddress& getProc);
GlApiKind currentGlApi();

// "#version 330 core" or "#version 300 es" plus default precisions: the
// first lines of every shader.
std::string shaderPreamble();
// Whether GPU timer queries (GL_TIME_ELAPSED) can be used on this context.
bool hasTimerQueries();
// Whether the "GPU" is the CPU (Mesa's llvmpipe or softpipe, SwiftShader):
// there a timer query leaves out the rasterization, which runs at flush.
bool isSoftwareRasterizer();
// A short description of the context: API, version, renderer.
std::string glDescription();

}  // namespace arcomp
