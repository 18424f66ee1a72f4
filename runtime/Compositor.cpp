#include "runtime/Compositor.hpp"

#include <stdexcept>

namespace arcomp {

using namespace gl;

namespace {

// A triangle that covers the screen; uv 0..1 over the viewport. Video rows
// arrive top first, GL's texture rows bottom first: the video is sampled at
// (u, 1 - v).
const char* const kCompositeShader = R"(
#ifdef VERTEX
out vec2 vUv;
void main() {
    vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
    vUv = p;
    gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}
#else
in vec2 vUv;
out vec4 fragColor;
uniform sampler2D uCg;
uniform sampler2D uHoldout;
uniform sampler2D uFrame;
uniform sampler2D uPerson;
uniform int uBackdropVideo;
uniform vec4 uBackdropColor;
void main() {
    vec2 videoUv = vec2(vUv.x, 1.0 - vUv.y);
    vec4 cg = texture(uCg, vUv);
    float holdout = texture(uHoldout, vUv).r;
    vec4 person = texture(uPerson, videoUv).bgra * (1.0 - holdout);   // uploaded as BGRA bytes
    vec4 backdrop = uBackdropVideo != 0 ? vec4(texture(uFrame, videoUv).bgr, 1.0) : uBackdropColor;
    vec4 under = cg + (1.0 - cg.a) * backdrop;
    fragColor = person + (1.0 - person.a) * under;
}
#endif
)";

GLuint makeTexture(glm::ivec2 size, GLenum internal, GLenum format) {
    GLuint t = 0;
    glGenTextures(1, &t);
    glBindTexture(GL_TEXTURE_2D, t);
    glTexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(internal), size.x, size.y, 0, format, GL_UNSIGNED_BYTE, nullptr);
    // Output and video share one pixel grid: nearest sampling is exact.
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return t;
}

void setNearest(GLuint texture) {
    glBindTexture(GL_TEXTURE_2D, texture);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
}

} // namespace

Compositor::Compositor(glm::ivec2 size) : size_(size), cg_(size), holdout_(size), output_(size) {
    frameTexture_ = makeTexture(size, GL_RGB8, GL_RGB);
    personTexture_ = makeTexture(size, GL_RGBA8, GL_RGBA);
    setNearest(cg_.colorTexture());
    setNearest(holdout_.colorTexture());
    glGenVertexArrays(1, &vao_);
    program_.emplace(kCompositeShader);
}

Compositor::~Compositor() {
    glDeleteTextures(1, &frameTexture_);
    glDeleteTextures(1, &personTexture_);
    glDeleteVertexArrays(1, &vao_);
}

void Compositor::uploadVideo(const cv::Mat& frame, const cv::Mat& person) {
    if (frame.cols != size_.x || frame.rows != size_.y || person.size() != frame.size() || frame.type() != CV_8UC3 ||
        person.type() != CV_8UC4 || !frame.isContinuous() || !person.isContinuous())
        throw std::invalid_argument("Compositor::uploadVideo: expected continuous BGR and BGRA images of the output size");
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glBindTexture(GL_TEXTURE_2D, frameTexture_);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, size_.x, size_.y, GL_RGB, GL_UNSIGNED_BYTE, frame.data);
    glBindTexture(GL_TEXTURE_2D, personTexture_);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, size_.x, size_.y, GL_RGBA, GL_UNSIGNED_BYTE, person.data);
}

void Compositor::composite(const CompositeSettings& settings) {
    output_.bind();
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    ShaderProgram& p = *program_;
    p.use();
    const GLuint textures[] = {cg_.colorTexture(), holdout_.colorTexture(), frameTexture_, personTexture_};
    const char* names[] = {"uCg", "uHoldout", "uFrame", "uPerson"};
    for (int i = 0; i < 4; ++i) {
        glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + i));
        glBindTexture(GL_TEXTURE_2D, textures[i]);
        glUniform1i(p.uniform(names[i]), i);
    }
    glUniform1i(p.uniform("uBackdropVideo"), settings.backdropVideo ? 1 : 0);
    const glm::vec4 c = settings.backdropColor;
    glUniform4f(p.uniform("uBackdropColor"), c.r * c.a, c.g * c.a, c.b * c.a, c.a);
    glBindVertexArray(vao_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glActiveTexture(GL_TEXTURE0);
}

} // namespace arcomp
