#pragma once
// A linked GLSL program built from one source with per-stage defines. The
// version line and precision come from GlApi's shaderPreamble(), so sources
// are written once for GL 3.3 and GLES 3.0.
//
//   ShaderProgram p(kSource, "#define SHADING 3\n");
//   p.use(); glUniform4f(p.uniform("uBaseColor"), ...);

#include "runtime/GlApi.hpp"

#include <string>
#include <unordered_map>

namespace arcomp {

class ShaderProgram {
public:
    // `source` holds both stages: the vertex stage sees VERTEX defined,
    // the fragment stage FRAGMENT. Throws std::runtime_error with the log.
    ShaderProgram(const std::string& source, const std::string& defines = {});
    ~ShaderProgram();
    ShaderProgram(const ShaderProgram&) = delete;
    ShaderProgram& operator=(const ShaderProgram&) = delete;
    ShaderProgram(ShaderProgram&& other) noexcept;

    void use() const;
    GLint uniform(const char* name);

private:
    GLuint program_ = 0;
    std::unordered_map<std::string, GLint> uniforms_;
};

} // namespace arcomp
