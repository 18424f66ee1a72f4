// Uniform locations are looked up once: a uniform the compiler dropped from
// one variant reads -1 (which glUniform ignores), a required one that is
// missing names itself, and a kept location draws.

#include "runtime/gl/GlContext.hpp"
#include "runtime/gl/GlHandle.hpp"
#include "runtime/gl/RenderTarget.hpp"
#include "runtime/gl/ShaderProgram.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <stdexcept>
#include <string>

using namespace arcomp;

namespace {

// uScale is read only where SCALED is defined.
const char* const kSource = R"(
uniform vec4 uColor;
uniform float uScale;
#ifdef VERTEX
void main() {
    vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
    gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}
#else
out vec4 fragColor;
void main() {
#ifdef SCALED
    fragColor = uColor * uScale;
#else
    fragColor = uColor;
#endif
}
#endif
)";

std::string errorOf(const ShaderProgram& p, const char* name) {
    try {
        p.requiredLocation(name);
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return "no error";
}

class ShaderProgramOnEachApi : public ::testing::TestWithParam<GlRequest> {};

}  // namespace

TEST_P(ShaderProgramOnEachApi, aUniformThisVariantDoesNotReadIsMinusOneAndNotRequirable) {
    auto context = HeadlessContext::create(GetParam());
    const ShaderProgram plain(kSource), scaled(kSource, "#define SCALED\n");
    EXPECT_GE(plain.requiredLocation("uColor"), 0);
    EXPECT_EQ(plain.location("uScale"), -1);
    EXPECT_GE(scaled.requiredLocation("uScale"), 0);
    EXPECT_EQ(errorOf(plain, "uScale"), "shader program has no active uniform uScale");
    EXPECT_EQ(errorOf(scaled, "uColour"), "shader program (#define SCALED) has no active uniform uColour");
}

TEST_P(ShaderProgramOnEachApi, aLocationLookedUpOnceDrawsAndMinusOneIsIgnored) {
    auto context = HeadlessContext::create(GetParam());
    RenderTarget target({8, 8});
    target.bind();
    const ShaderProgram p(kSource);
    const GLint color = p.requiredLocation("uColor"), scale = p.location("uScale");
    p.use();
    gl::glUniform4f(color, 1.0f, 0.5f, 0.0f, 1.0f);
    gl::glUniform1f(scale, 0.0f);  // dropped here: no effect, no error
    EXPECT_EQ(gl::glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    const GlVertexArray empty = GlVertexArray::generate();  // core GL draws nothing without one
    gl::glBindVertexArray(empty.get());
    gl::glDrawArrays(GL_TRIANGLES, 0, 3);
    const Image img = target.read();
    const std::uint8_t* centre = &img.rgba[(4 * 8 + 4) * 4];
    EXPECT_EQ(centre[0], 255);
    EXPECT_NEAR(centre[1], 128, 1);
    EXPECT_EQ(centre[2], 0);
    EXPECT_EQ(centre[3], 255);
}

TEST_P(ShaderProgramOnEachApi, aShaderThatDoesNotCompileSaysWhichStage) {
    auto context = HeadlessContext::create(GetParam());
    try {
        ShaderProgram broken("#ifdef FRAGMENT\nout vec4 fragColor;\nvoid main() { fragColor = nonsense; }\n#else\n"
                             "void main() { gl_Position = vec4(0.0); }\n#endif\n");
        FAIL() << "compiled";
    } catch (const std::runtime_error& e) {
        EXPECT_EQ(std::string(e.what()).rfind("fragment shader does not compile", 0), 0u) << e.what();
    }
}

INSTANTIATE_TEST_SUITE_P(Apis, ShaderProgramOnEachApi, ::testing::Values(GlRequest::Gl33, GlRequest::Es3),
                         [](const auto& info) { return info.param == GlRequest::Gl33 ? "gl33" : "es3"; });
