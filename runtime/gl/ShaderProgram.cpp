#include "runtime/gl/ShaderProgram.hpp"

#include <algorithm>
#include <stdexcept>
#include <vector>

namespace arcomp {

using namespace gl;

namespace {

GlShader compile(GLenum stage, const std::string& text) {
    GlShader shader(glCreateShader(stage));
    const char* src = text.c_str();
    glShaderSource(shader.get(), 1, &src, nullptr);
    glCompileShader(shader.get());
    GLint ok = 0;
    glGetShaderiv(shader.get(), GL_COMPILE_STATUS, &ok);
    if (!ok) {
        GLint length = 0;
        glGetShaderiv(shader.get(), GL_INFO_LOG_LENGTH, &length);
        std::vector<char> log(static_cast<std::size_t>(std::max(length, 1)));
        glGetShaderInfoLog(shader.get(), length, nullptr, log.data());
        throw std::runtime_error(std::string(stage == GL_VERTEX_SHADER ? "vertex" : "fragment") +
                                 " shader does not compile: " + log.data());
    }
    return shader;
}

}  // namespace

ShaderProgram::ShaderProgram(const std::string& source, const std::string& defines) : defines_(defines) {
    const std::string common = shaderPreamble() + defines;
    // The stages are deleted as the constructor returns, linked or not: GL
    // keeps attached ones for as long as the program needs them.
    const GlShader vs = compile(GL_VERTEX_SHADER, common + "#define VERTEX\n" + source);
    const GlShader fs = compile(GL_FRAGMENT_SHADER, common + "#define FRAGMENT\n" + source);
    program_ = GlProgram::generate();
    glAttachShader(program_.get(), vs.get());
    glAttachShader(program_.get(), fs.get());
    glLinkProgram(program_.get());
    GLint ok = 0;
    glGetProgramiv(program_.get(), GL_LINK_STATUS, &ok);
    if (!ok) {
        GLint length = 0;
        glGetProgramiv(program_.get(), GL_INFO_LOG_LENGTH, &length);
        std::vector<char> log(static_cast<std::size_t>(std::max(length, 1)));
        glGetProgramInfoLog(program_.get(), length, nullptr, log.data());
        throw std::runtime_error(std::string("shader program does not link: ") + log.data());
    }
}

void ShaderProgram::use() const { glUseProgram(program_.get()); }

GLint ShaderProgram::location(const char* name) const { return glGetUniformLocation(program_.get(), name); }

GLint ShaderProgram::requiredLocation(const char* name) const {
    const GLint at = location(name);
    if (at < 0) {
        std::string variant = defines_;
        std::replace(variant.begin(), variant.end(), '\n', ' ');
        while (!variant.empty() && variant.back() == ' ') variant.pop_back();
        throw std::runtime_error("shader program" + (variant.empty() ? "" : " (" + variant + ")") +
                                 " has no active uniform " + name);
    }
    return at;
}

std::string fullScreenTriangle(const std::string& fragment) {
    return R"(
#ifdef VERTEX
void main() {
    vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
    gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}
#else
)" + fragment +
           "\n#endif\n";
}

}  // namespace arcomp
