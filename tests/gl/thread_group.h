// flowsurf tests — N threads as one process group (methods::ProcessGroup), for the
// parallel tests: each collective writes its contribution, waits for all, reads the
// result, and waits again before the slots are reused.
#pragma once

#include "methods/common/process_group.h"

#include <algorithm>
#include <barrier>
#include <cstdint>
#include <span>
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

}  // namespace flowsurf::test
