#include "runtime/ShaderProgram.hpp"

#include <stdexcept>
#include <vector>

namespace arcomp {

using namespace gl;

namespace {

GLuint compile(GLenum stage, const std::string& text) {
    const GLuint shader = glCreateShader(stage);
    const char* src = text.c_str();
    glShaderSource(shader, 1, &src, nullptr);
    glCompileShader(shader);
    GLint ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        GLint length = 0;
        glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
        std::vector<char> log(static_cast<std::size_t>(std::max(length, 1)));
        glGetShaderInfoLog(shader, length, nullptr, log.data());
        glDeleteShader(shader);
        throw std::runtime_error(std::string(stage == GL_VERTEX_SHADER ? "vertex" : "fragment") +
                                 " shader does not compile: " + log.data());
    }
    return shader;
}

} // namespace

ShaderProgram::ShaderProgram(const std::string& source, const std::string& defines) {
    const std::string common = shaderPreamble() + defines;
    const GLuint vs = compile(GL_VERTEX_SHADER, common + "#define VERTEX\n" + source);
    const GLuint fs = compile(GL_FRAGMENT_SHADER, common + "#define FRAGMENT\n" + source);
    program_ = glCreateProgram();
    glAttachShader(program_, vs);
    glAttachShader(program_, fs);
    glLinkProgram(program_);
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint ok = 0;
    glGetProgramiv(program_, GL_LINK_STATUS, &ok);
    if (!ok) {
        GLint length = 0;
        glGetProgramiv(program_, GL_INFO_LOG_LENGTH, &length);
        std::vector<char> log(static_cast<std::size_t>(std::max(length, 1)));
        glGetProgramInfoLog(program_, length, nullptr, log.data());
        glDeleteProgram(program_);
        throw std::runtime_error(std::string("shader program does not link: ") + log.data());
    }
}

ShaderProgram::ShaderProgram(ShaderProgram&& other) noexcept
    : program_(other.program_), uniforms_(std::move(other.uniforms_)) {
    other.program_ = 0;
}

ShaderProgram::~ShaderProgram() {
    if (program_) glDeleteProgram(program_);
}

void ShaderProgram::use() const { glUseProgram(program_); }

GLint ShaderProgram::uniform(const char* name) {
    auto it = uniforms_.find(name);
    if (it == uniforms_.end()) it = uniforms_.emplace(name, glGetUniformLocation(program_, name)).first;
    return it->second;
}

} // namespace arcomp
