// GL tests share one headless context (llvmpipe on CI, a GPU where there is one).
#include "gl/context.h"

#include <gtest/gtest.h>

#include <memory>

namespace {
class GlEnvironment : public ::testing::Environment {
public:
    void SetUp() override { context_ = std::make_unique<flowsurf::gl::HeadlessContext>(true); }
    void TearDown() override { context_.reset(); }

private:
    std::unique_ptr<flowsurf::gl::HeadlessContext> context_;
};
}  // namespace

int main(int argc, char** argv) {
    ::testing::InitGoogleTest(&argc, argv);
    ::testing::AddGlobalTestEnvironment(new GlEnvironment);
    return RUN_ALL_TESTS();
}
