// An error on one process inside a parallel frame [docs/parallel.md]: every process reports
// the same error naming that process, none is left waiting in a collective step, and the
// next frames render (parallel/agreeing_group.h).
#include "core/builtin_scenes.h"
#include "core/camera.h"
#include "gl/context.h"
#include "methods/make_renderer.h"
#include "parallel/agreeing_group.h"
#include "parallel/thread_group.h"
#include "parallel_util.h"
#include "raster/surface_gpu.h"

#include <gtest/gtest.h>

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

using namespace flowsurf;

namespace {

// Passes every collective step on; once armed, the `at`-th from then on throws instead of
// taking part (what a failed allocation or a driver error between two steps does).
class FaultyGroup final : public methods::ProcessGroup {
public:
    explicit FaultyGroup(methods::ProcessGroup& inner) : inner_(inner) {}
    void arm(int at) { failAt_ = at, calls_ = 0; }
    int calls() const { return calls_; }
    int rank() const override { return inner_.rank(); }
    int size() const override { return inner_.size(); }
    void minInPlace(std::span<float> v) override { hit(), inner_.minInPlace(v); }
    void minInPlace(std::span<int32_t> v) override { hit(), inner_.minInPlace(v); }
    void sumInPlace(std::span<float> v) override { hit(), inner_.sumInPlace(v); }
    std::vector<float> gather(std::span<const float> v) override { return hit(), inner_.gather(v); }
    std::vector<std::vector<uint8_t>> exchange(const std::vector<std::vector<uint8_t>>& s) override {
        return hit(), inner_.exchange(s);
    }

private:
    void hit() {
        if (calls_++ == failAt_) {
            failAt_ = -1;
            throw GlError("not enough graphics memory for a buffer (injected)");
        }
    }
    methods::ProcessGroup& inner_;
    int failAt_ = -1, calls_ = 0;
};

// Where process 1 fails in frame kFailFrame: before its `at`-th collective step of the
// frame, or after the frame's last one (at < 0).
constexpr int kFrames = 6, kFailFrame = 3;

struct Outcome {
    std::vector<std::string> errors;  // per frame, "" where it rendered
    int stepsPerFrame = 0;            // collective steps of a frame (process 1, frame 2)
};

std::vector<Outcome> runWithFailure(const std::string& method, int at) {
    const core::Dataset data = core::makeBuiltin("builtin:sphere:20000");
    const core::Viewport vp{96, 96};
    const core::Camera cam = core::fitCamera(data.bounds(), vp, {0.3f, 0.2f, 1.0f});
    methods::ThreadGroup threads(2);
    std::vector<Outcome> out(2);
    std::mutex m;
    std::condition_variable cv;
    int done = 0;
    std::vector<std::thread> workers;
    for (int r = 0; r < 2; ++r)
        workers.emplace_back([&, r] {
            try {
                gl::HeadlessContext context;
                methods::ThreadGroup::Member member(threads, r);
                methods::AgreeingGroup group(member);
                FaultyGroup faulty(group);  // fails between two of the agreeing group's steps
                // Two pieces with a seam through the view.
                const core::SurfaceMesh piece =
                    core::pieceOf(data.steps.front().mesh, [r](glm::vec3 c) { return (c.x < 0.0f) == (r == 0); });
                methods::MethodParams params;
                const methods::SurfaceStatistics whole =
                    methods::wholeSurfaceStatistics(group, piece, "velocity", params.common);
                methods::SurfaceGpu surface(piece, "velocity", params.common, false, &whole);
                auto renderer = methods::makeMethod(method, params, vp, &faulty);
                for (int k = 0; k < kFrames; ++k) {
                    const core::Camera c = core::orbitCamera(cam, 2.0f * float(k));  // every frame dynamic
                    if (k == kFailFrame && r == 1 && at >= 0) faulty.arm(at);
                    if (k == 2 && r == 1) faulty.arm(-1);
                    std::string error;
                    try {
                        methods::collectiveSection(&group, [&] {
                            renderer->renderFrame({&surface, c, uint32_t(k)});
                            if (k == kFailFrame && r == 1 && at < 0)
                                throw GlError("the composite failed after the frame (injected)");
                        });
                    } catch (const std::exception& e) {
                        error = e.what();
                    }
                    if (k == 2 && r == 1) out[1].stepsPerFrame = faulty.calls();
                    out[size_t(r)].errors.push_back(error);
                }
            } catch (const std::exception& e) {
                out[size_t(r)].errors.assign(1, std::string("setup: ") + e.what());
            }
            std::lock_guard lock(m);
            ++done;
            cv.notify_all();
        });
    {
        std::unique_lock lock(m);
        if (!cv.wait_for(lock, std::chrono::seconds(120), [&] { return done == 2; })) {
            std::fprintf(stderr, "%s, failure at step %d: a process is still waiting after 120 s (a hang)\n",
                         method.c_str(), at);
            std::fflush(stderr);
            std::_Exit(1);
        }
    }
    for (auto& w : workers) w.join();
    return out;
}

TEST(ParallelFailure, EveryProcessReportsTheSameErrorAndRendersOn) {
    for (const std::string method : {"isa", "ibfvs", "hybrid"})
        for (int at : {0, 3, -1}) {
            const std::vector<Outcome> out = runWithFailure(method, at);
            const std::string where = method + ", process 1 failing at step " + std::to_string(at);
            ASSERT_EQ(out[0].errors.size(), size_t(kFrames)) << where << ": " << out[0].errors.front();
            ASSERT_EQ(out[1].errors.size(), size_t(kFrames)) << where << ": " << out[1].errors.front();
            EXPECT_GT(out[1].stepsPerFrame, 3) << where << ": step 3 lies inside the frame";
            for (int k = 0; k < kFrames; ++k) {
                EXPECT_EQ(out[0].errors[size_t(k)], out[1].errors[size_t(k)]) << where << ", frame " << k;
                if (k != kFailFrame) {
                    EXPECT_EQ(out[0].errors[size_t(k)], "") << where << ", frame " << k;
                }
            }
            const std::string& e = out[0].errors[size_t(kFailFrame)];
            std::printf("%s: %s\n", where.c_str(), e.c_str());
            EXPECT_NE(e.find("(injected) (on process 1 of 2)"), std::string::npos) << where << ": " << e;
        }
}

}  // namespace
