// A GlHandle deletes its object when it goes, is reset or is assigned over,
// and a moved-from handle owns nothing. Programs show it: asking about a
// deleted program's name is GL_INVALID_VALUE on both APIs.

#include "runtime/gl/GlContext.hpp"
#include "runtime/gl/GlHandle.hpp"

#include <gtest/gtest.h>

#include <utility>

using namespace arcomp;

namespace {

bool isProgram(GLuint name) {
    while (gl::glGetError() != GL_NO_ERROR) {}
    GLint status = 0;
    gl::glGetProgramiv(name, GL_DELETE_STATUS, &status);
    return gl::glGetError() == GL_NO_ERROR;
}

class GlHandleOnEachApi : public ::testing::TestWithParam<GlRequest> {};

}  // namespace

TEST_P(GlHandleOnEachApi, deletesItsObjectWhenItGoesOrIsResetOrAssignedOver) {
    auto context = HeadlessContext::create(GetParam());
    GLuint name = 0;
    {
        const GlProgram p = GlProgram::generate();
        name = p.get();
        ASSERT_NE(name, 0u);
        EXPECT_TRUE(isProgram(name));
    }
    EXPECT_FALSE(isProgram(name));

    GlProgram reset = GlProgram::generate();
    name = reset.get();
    reset.reset();
    EXPECT_EQ(reset.get(), 0u);
    EXPECT_FALSE(isProgram(name));

    GlProgram kept = GlProgram::generate(), other = GlProgram::generate();
    const GLuint replaced = kept.get(), moved = other.get();
    kept = std::move(other);
    EXPECT_FALSE(isProgram(replaced));
    EXPECT_EQ(kept.get(), moved);
    EXPECT_TRUE(isProgram(moved));
}

TEST_P(GlHandleOnEachApi, aMovedFromHandleOwnsNothing) {
    auto context = HeadlessContext::create(GetParam());
    GlTexture first = GlTexture::generate();
    const GLuint name = first.get();
    ASSERT_TRUE(first);
    GlTexture second(std::move(first));
    EXPECT_FALSE(first);  // NOLINT(bugprone-use-after-move): that is the point
    EXPECT_EQ(first.get(), 0u);
    EXPECT_EQ(second.get(), name);
    gl::glBindTexture(GL_TEXTURE_2D, second.get());
    EXPECT_EQ(gl::glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

INSTANTIATE_TEST_SUITE_P(Apis, GlHandleOnEachApi, ::testing::Values(GlRequest::Gl33, GlRequest::Es3),
                         [](const auto& info) { return info.param == GlRequest::Gl33 ? "gl33" : "es3"; });
