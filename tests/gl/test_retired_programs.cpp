// Freed programs are held back from glDeleteProgram only up to RetiredPrograms::kHeld, so a long
// session that remakes its methods (Python, the viewer's method switch) does not grow without
// bound; the oldest held program is the one really deleted.
#include "gl/objects.h"

#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <vector>

using flowsurf::gl::RetiredPrograms;

TEST(RetiredPrograms, TheHeadlessContextHoldsFreedPrograms) {
    EXPECT_NE(RetiredPrograms::current(), nullptr);
}

TEST(RetiredPrograms, HoldsTheLastFewAndDeletesTheOldest) {
    RetiredPrograms* previous = RetiredPrograms::current();
    {
        RetiredPrograms list;
        RetiredPrograms::makeCurrent(&list);
        const size_t extra = 6;
        std::vector<GLuint> programs;
        for (size_t i = 0; i < RetiredPrograms::kHeld + extra; ++i) programs.push_back(glCreateProgram());
        for (GLuint p : programs) flowsurf::gl::detail::deleteProgram(p);
        EXPECT_EQ(list.held(), RetiredPrograms::kHeld);
        for (size_t i = 0; i < programs.size(); ++i)
            EXPECT_EQ(glIsProgram(programs[i]) == GL_TRUE, i >= extra) << "program " << i;
        RetiredPrograms::makeCurrent(previous);
        for (GLuint p : programs)
            if (glIsProgram(p)) glDeleteProgram(p);
    }
    EXPECT_EQ(RetiredPrograms::current(), previous);
}

TEST(RetiredPrograms, WithNoListAProgramIsDeletedAtOnce) {
    RetiredPrograms* previous = RetiredPrograms::current();
    RetiredPrograms::makeCurrent(nullptr);
    GLuint p = glCreateProgram();
    flowsurf::gl::detail::deleteProgram(p);
    EXPECT_EQ(glIsProgram(p), GL_FALSE);
    RetiredPrograms::makeCurrent(previous);
}
