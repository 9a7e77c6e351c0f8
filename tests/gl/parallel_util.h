// flowsurf tests — what the parallel tests share: N threads as one process group
// (methods::ProcessGroup; each collective writes its contribution, waits for all, reads the
// result, and waits again before the slots are reused), pieces of a mesh, the processes'
// images run in threads, composited by depth and compared.
#pragma once

#include "core/camera.h"
#include "core/mesh.h"
#include "gl/context.h"
#include "methods/common/process_group.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <barrier>
#include <cmath>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <thread>
#include <unordered_map>
#include <utility>
#include <vector>

namespace flowsurf::test {

class ThreadGroup {
public:
    explicit ThreadGroup(int n) : n_(n), sync_(n), floats_(size_t(n)), ints_(size_t(n)) {}

    class Member : public methods::ProcessGroup {
    public:
        Member(ThreadGroup& g, int rank) : g_(g), rank_(rank) {}
        int rank() const override { return rank_; }
        int size() const override { return g_.n_; }
        void minInPlace(std::span<float> v) override { reduce(g_.floats_, v, [](float a, float b) { return std::min(a, b); }); }
        void minInPlace(std::span<int32_t> v) override { reduce(g_.ints_, v, [](int32_t a, int32_t b) { return std::min(a, b); }); }
        void sumInPlace(std::span<float> v) override { reduce(g_.floats_, v, [](float a, float b) { return a + b; }); }
        std::vector<float> gather(std::span<const float> v) override {
            g_.floats_[size_t(rank_)].assign(v.begin(), v.end());
            g_.sync_.arrive_and_wait();
            std::vector<float> all;
            for (const auto& part : g_.floats_) all.insert(all.end(), part.begin(), part.end());
            g_.sync_.arrive_and_wait();
            return all;
        }
        std::vector<std::vector<uint8_t>> exchange(const std::vector<std::vector<uint8_t>>& sends) override {
            g_.messages_[size_t(rank_)] = sends;
            g_.sync_.arrive_and_wait();
            std::vector<std::vector<uint8_t>> received(size_t(g_.n_));
            for (int q = 0; q < g_.n_; ++q)
                if (q != rank_) received[size_t(q)] = g_.messages_[size_t(q)][size_t(rank_)];
            g_.sync_.arrive_and_wait();
            return received;
        }

    private:
        template <class T, class Op>
        void reduce(std::vector<std::vector<T>>& slots, std::span<T> v, Op op) {
            slots[size_t(rank_)].assign(v.begin(), v.end());
            g_.sync_.arrive_and_wait();
            for (size_t i = 0; i < v.size(); ++i) {  // in rank order: the same sum everywhere
                T acc = slots[0][i];
                for (size_t r = 1; r < slots.size(); ++r) acc = op(acc, slots[r][i]);
                v[i] = acc;
            }
            g_.sync_.arrive_and_wait();
        }
        ThreadGroup& g_;
        int rank_;
    };

private:
    int n_;
    std::barrier<> sync_;
    std::vector<std::vector<float>> floats_;
    std::vector<std::vector<int32_t>> ints_;
    std::vector<std::vector<std::vector<uint8_t>>> messages_{size_t(n_)};  // [sender][receiver]
};

// The triangles of `mesh` whose centroid `keep` accepts, with their vertices (shared seam
// vertices appear in both pieces, as in a partitioned dataset).
inline core::SurfaceMesh pieceOf(const core::SurfaceMesh& mesh, const std::function<bool(glm::vec3)>& keep) {
    core::SurfaceMesh p;
    std::unordered_map<uint32_t, uint32_t> index;
    auto vertex = [&](uint32_t v) {
        auto [it, fresh] = index.try_emplace(v, uint32_t(p.positions.size()));
        if (fresh) {
            p.positions.push_back(mesh.positions[v]);
            p.normals.push_back(mesh.normals[v]);
        }
        return it->second;
    };
    for (const auto& t : mesh.triangles) {
        const glm::vec3 c = (mesh.positions[t.x] + mesh.positions[t.y] + mesh.positions[t.z]) / 3.0f;
        if (keep(c)) p.triangles.push_back({vertex(t.x), vertex(t.y), vertex(t.z)});
    }
    for (const auto& f : mesh.fields) {
        core::VectorField g{f.name, std::vector<glm::vec3>(p.positions.size())};
        for (auto [from, to] : index) g.values[to] = f.values[from];
        p.fields.push_back(std::move(g));
    }
    return p;
}

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
    test::ThreadGroup group(n);
    std::vector<Images> images(static_cast<size_t>(n));
    std::vector<std::string> errors(static_cast<size_t>(n));
    std::vector<std::thread> threads;
    for (int r = 0; r < n; ++r)
        threads.emplace_back([&, r] {
            try {
                gl::HeadlessContext context;
                test::ThreadGroup::Member member(group, r);
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
