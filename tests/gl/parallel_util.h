// flowsurf tests — what the parallel tests share: N threads as one process group
// (methods::ProcessGroup; each collective writes its contribution, waits for all, reads the
// result, and waits again before the slots are reused) and pieces of a mesh.
#pragma once

#include "core/mesh.h"
#include "methods/common/process_group.h"

#include <algorithm>
#include <barrier>
#include <cstdint>
#include <functional>
#include <span>
#include <unordered_map>
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

}  // namespace flowsurf::test
