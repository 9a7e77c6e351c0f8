// flowsurf tests — what the parallel tests share: N threads as one process group
// (methods::ThreadGroup), pieces of a mesh (core::pieceOf), the processes' images run in
// threads, composited by depth and compared.
#pragma once

#include "core/camera.h"
#include "core/mesh.h"
#include "gl/context.h"
#include "parallel/process_group.h"
#include "parallel/thread_group.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace flowsurf::test {


// One process's image: what the parallel tests compare.
struct Images {
    std::vector<uint8_t> rgb;  // top-down RGB8
    std::vector<float> depth;  // bottom-up
};

// Mean absolute gray difference over the surface pixels and the worst 16 x 16 tile.
inline std::pair<double, double> difference(const Images& a, const Images& b, const core::Viewport& vp) {
    double sum = 0, worst = 0;
    long n = 0;
    for (int ty = 0; ty < vp.height; ty += 16)
        for (int tx = 0; tx < vp.width; tx += 16) {
            double tileSum = 0;
            long tileN = 0;
            for (int y = ty; y < std::min(ty + 16, vp.height); ++y)
                for (int x = tx; x < std::min(tx + 16, vp.width); ++x) {
                    const int yb = vp.height - 1 - y;  // depth rows are bottom-up
                    if (a.depth[size_t(yb) * vp.width + x] >= 1.0f) continue;
                    double d = 0;
                    for (int c = 0; c < 3; ++c) {
                        const size_t i = (size_t(y) * vp.width + x) * 3 + c;
                        d += std::abs(double(a.rgb[i]) - double(b.rgb[i]));
                    }
                    tileSum += d / 3;
                    ++tileN;
                }
            sum += tileSum;
            n += tileN;
            if (tileN) worst = std::max(worst, tileSum / tileN);
        }
    return {n ? sum / n : 0.0, worst};
}

// `n` processes as threads of one group, each with its own GL context: `render(member, r)`
// makes rank r's images; what a thread throws fails the test, naming its rank.
inline std::vector<Images> inThreads(int n, const std::function<Images(methods::ProcessGroup&, int)>& render) {
    methods::ThreadGroup group(n);
    std::vector<Images> images(static_cast<size_t>(n));
    std::vector<std::string> errors(static_cast<size_t>(n));
    std::vector<std::thread> threads;
    for (int r = 0; r < n; ++r)
        threads.emplace_back([&, r] {
            try {
                gl::HeadlessContext context;
                methods::ThreadGroup::Member member(group, r);
                images[size_t(r)] = render(member, r);
            } catch (const std::exception& e) {
                errors[size_t(r)] = e.what();
            }
        });
    for (auto& t : threads) t.join();
    for (int r = 0; r < n; ++r) EXPECT_EQ(errors[size_t(r)], "") << "rank " << r;
    return images;
}

// What a host's depth compositing (ParaView's IceT) makes of the processes' images: at
// each pixel the nearest fragment's colour, on a tie the lowest rank's.
inline Images depthComposite(const std::vector<Images>& ranks, const core::Viewport& vp) {
    Images out = ranks.front();
    for (size_t r = 1; r < ranks.size(); ++r)
        for (int y = 0; y < vp.height; ++y)
            for (int x = 0; x < vp.width; ++x) {
                const size_t d = size_t(y) * vp.width + x;  // bottom-up
                if (!(ranks[r].depth[d] < out.depth[d])) continue;
                out.depth[d] = ranks[r].depth[d];
                const size_t i = (size_t(vp.height - 1 - y) * vp.width + x) * 3;  // top-down
                for (int c = 0; c < 3; ++c) out.rgb[i + c] = ranks[r].rgb[i + c];
            }
    return out;
}

}  // namespace flowsurf::test
