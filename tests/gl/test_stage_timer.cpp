// The stage timer (src/gl/stage_timer.h) with GL timestamp queries: what the benchmark,
// the viewer's stats and the API report. Times themselves are never asserted; the
// bookkeeping is: stages in first-seen order, frames still on the GPU folded in when asked,
// reset() forgetting them, a timer that is off issuing nothing, the synchronous mode
// also charging each stage its CPU time.
#include "gl/objects.h"
#include "gl/stage_timer.h"

#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

using namespace flowsurf;

namespace {

// Some GPU work: clearing a 256² float texture.
void work(GLuint texture) {
    const float value[4] = {0.5f, 0.25f, 0.0f, 1.0f};
    glClearTexImage(texture, 0, GL_RGBA, GL_FLOAT, value);
}

std::vector<std::string> names(const std::vector<std::pair<std::string, double>>& means) {
    std::vector<std::string> out;
    for (const auto& [name, ms] : means) {
        EXPECT_GE(ms, 0.0) << name;
        out.push_back(name);
    }
    return out;
}

class StageTimerTest : public ::testing::Test {
protected:
    void SetUp() override {
        GLuint id = 0;
        glCreateTextures(GL_TEXTURE_2D, 1, &id);
        glTextureStorage2D(id, 1, GL_RGBA32F, 256, 256);
        texture_ = id;
    }
    void TearDown() override { glDeleteTextures(1, &texture_); }
    void frame(gl::StageTimer& t, const std::vector<const char*>& stages) {
        t.beginFrame();
        for (const char* s : stages) {
            t.begin(s);
            work(texture_);
        }
        t.endFrame();
    }
    GLuint texture_ = 0;
};

}  // namespace

TEST_F(StageTimerTest, StagesInFirstSeenOrderOverEveryFrame) {
    gl::StageTimer t;
    t.setEnabled(true);
    frame(t, {"advect", "overlay"});
    frame(t, {"surface", "advect", "overlay"});  // a dynamic-only stage appears later
    for (int k = 0; k < 20; ++k) frame(t, {"advect", "overlay"});  // more than stay pending
    EXPECT_EQ(names(t.meanMs()), (std::vector<std::string>{"advect", "overlay", "surface"}));
}

TEST_F(StageTimerTest, ResetForgetsFramesStillOnTheGpu) {
    gl::StageTimer t;
    t.setEnabled(true);
    frame(t, {"old"});
    t.reset();
    frame(t, {"new"});
    EXPECT_EQ(names(t.meanMs()), (std::vector<std::string>{"new"}));
    EXPECT_EQ(names(t.meanMs()), (std::vector<std::string>{"new"})) << "asking twice changes nothing";
}

TEST_F(StageTimerTest, DisabledTimerReportsNothing) {
    gl::StageTimer t;
    frame(t, {"advect"});
    EXPECT_TRUE(t.meanMs().empty());
}

TEST_F(StageTimerTest, SynchronousTimerAlsoReportsEachStagesCpuTime) {
    gl::StageTimer t;
    t.setEnabled(true);
    t.setSynchronous(true);
    for (int k = 0; k < 3; ++k) frame(t, {"advect", "overlay"});
    EXPECT_EQ(names(t.meanMs()), (std::vector<std::string>{"advect", "overlay"}));
    EXPECT_EQ(names(t.meanCpuMs()), (std::vector<std::string>{"advect", "overlay"})) << "the same stages, in the same order";
    t.reset();
    EXPECT_TRUE(t.meanCpuMs().empty());

    gl::StageTimer queries;  // timestamp queries measure the GPU's time, not the process's
    queries.setEnabled(true);
    frame(queries, {"advect"});
    EXPECT_TRUE(queries.meanCpuMs().empty());
}
