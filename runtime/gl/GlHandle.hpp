#pragma once
// Owns one GL object and deletes it when the owner goes: moved, never
// copied. A class whose GL objects are GlHandles needs no destructor of its
// own, and a constructor that throws half-way leaks none of those it made.
//
//   GlTexture texture = GlTexture::generate();    // glGenTextures
//   glBindTexture(GL_TEXTURE_2D, texture.get());
//   GlShader shader(glCreateShader(GL_VERTEX_SHADER));   // adopts a name made elsewhere
//   texture.reset();                               // deleted now
//
// The context that made an object must be current where its handle goes.

#include "runtime/gl/GlApi.hpp"

#include <type_traits>
#include <utility>

namespace arcomp {

// `Create` and `Destroy` name gl:: entry points, as references: they are
// loaded at run time, after this template is instantiated.
template <auto& Create, auto& Destroy>
class GlHandle {
public:
    GlHandle() = default;  // no object
    explicit GlHandle(GLuint name) : name_(name) {}

    static GlHandle generate() {
        if constexpr (std::is_invocable_v<decltype(Create)>) {
            return GlHandle(Create());  // glCreateProgram
        } else {
            GLuint name = 0;
            Create(1, &name);  // glGenTextures and the like
            return GlHandle(name);
        }
    }

    ~GlHandle() { reset(); }
    GlHandle(GlHandle&& other) noexcept : name_(std::exchange(other.name_, 0)) {}
    GlHandle& operator=(GlHandle&& other) noexcept {
        if (this != &other) {
            reset();
            name_ = std::exchange(other.name_, 0);
        }
        return *this;
    }
    GlHandle(const GlHandle&) = delete;
    GlHandle& operator=(const GlHandle&) = delete;

    GLuint get() const { return name_; }
    explicit operator bool() const { return name_ != 0; }

    void reset() {
        if (!name_) return;
        if constexpr (std::is_invocable_v<decltype(Destroy), GLuint>)
            Destroy(name_);  // glDeleteProgram, glDeleteShader
        else
            Destroy(1, &name_);
        name_ = 0;
    }

private:
    GLuint name_ = 0;
};

using GlTexture = GlHandle<gl::glGenTextures, gl::glDeleteTextures>;
using GlBuffer = GlHandle<gl::glGenBuffers, gl::glDeleteBuffers>;
using GlVertexArray = GlHandle<gl::glGenVertexArrays, gl::glDeleteVertexArrays>;
using GlFramebuffer = GlHandle<gl::glGenFramebuffers, gl::glDeleteFramebuffers>;
using GlRenderbuffer = GlHandle<gl::glGenRenderbuffers, gl::glDeleteRenderbuffers>;
using GlQuery = GlHandle<gl::glGenQueries, gl::glDeleteQueries>;
using GlProgram = GlHandle<gl::glCreateProgram, gl::glDeleteProgram>;
// glCreateShader needs the stage: adopt its result rather than generate().
using GlShader = GlHandle<gl::glCreateShader, gl::glDeleteShader>;

}  // namespace arcomp
