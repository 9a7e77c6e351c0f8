// GL tests share one headless context (llvmpipe on CI, a GPU where there is one), with
// KHR_debug output on and synchronous: a GL error or a high-severity message fails the
// test that caused it (test::AllowGlErrors lets a test expect them).
#include "gl/context.h"
#include "gl_test_util.h"

#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <memory>
#include <string>

namespace {

int allowErrors = 0;

void GLAPIENTRY onGlMessage(GLenum /*source*/, GLenum type, GLuint id, GLenum severity, GLsizei /*length*/,
                            const GLchar* message, const void* /*user*/) {
    const bool bad = type == GL_DEBUG_TYPE_ERROR || severity == GL_DEBUG_SEVERITY_HIGH;
    if (bad && allowErrors == 0)
        ADD_FAILURE() << "GL debug message " << id << (type == GL_DEBUG_TYPE_ERROR ? " (error)" : " (high severity)")
                      << ": " << message;
}

class GlEnvironment : public ::testing::Environment {
public:
    void SetUp() override {
        context_ = std::make_unique<flowsurf::gl::HeadlessContext>(true);
        glEnable(GL_DEBUG_OUTPUT);
        glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
        glDebugMessageCallback(onGlMessage, nullptr);
    }
    void TearDown() override { context_.reset(); }

private:
    std::unique_ptr<flowsurf::gl::HeadlessContext> context_;
};

}  // namespace

namespace flowsurf::test {
AllowGlErrors::AllowGlErrors() { ++allowErrors; }
AllowGlErrors::~AllowGlErrors() { --allowErrors; }
}  // namespace flowsurf::test

int main(int argc, char** argv) {
    ::testing::InitGoogleTest(&argc, argv);
    ::testing::AddGlobalTestEnvironment(new GlEnvironment);
    return RUN_ALL_TESTS();
}
