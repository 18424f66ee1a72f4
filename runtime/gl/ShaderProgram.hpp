#pragma once
// A linked GLSL program built from one source with per-stage defines. The
// version line and precision come from GlApi's shaderPreamble(), so sources
// are written once for GL 3.3 and GLES 3.0.
//
// Uniform locations are looked up once, after linking, and kept by the
// program's user (a struct of GLints beside the program), so that drawing
// hashes no names:
//
//   ShaderProgram p(kSource, "#define SHADING 3\n");
//   const GLint baseColor = p.location("uBaseColor");
//   p.use(); glUniform4f(baseColor, ...);

#include "runtime/gl/GlHandle.hpp"

#include <string>

namespace arcomp {

class ShaderProgram {
public:
    // `source` holds both stages: the vertex stage sees VERTEX defined,
    // the fragment stage FRAGMENT. Throws std::runtime_error with the log.
    ShaderProgram(const std::string& source, const std::string& defines = {});

    void use() const;

    // -1 where the compiler dropped the uniform because this variant of the
    // shader never reads it: legal, glUniform* with -1 does nothing.
    GLint location(const char* name) const;
    // For a uniform every variant reads: a missing one is a misspelt name
    // or a shader that changed, and throws std::runtime_error naming it.
    GLint requiredLocation(const char* name) const;

private:
    GlProgram program_;
    std::string defines_;  // says which variant, in errors
};

// A source for ShaderProgram whose vertex stage is one triangle covering the
// viewport, made from gl_VertexID alone (draw three vertices, no buffers);
// `fragment` is the fragment stage.
std::string fullScreenTriangle(const std::string& fragment);

}  // namespace arcomp
