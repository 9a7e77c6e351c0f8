#include "parallel/thread_group.h"

#include <algorithm>
#include <utility>

namespace flowsurf::methods {

ThreadGroup::ThreadGroup(int n) : n_(n), sync_(n), floats_(size_t(n)), ints_(size_t(n)), messages_(size_t(n)) {}

template <class T, class Op>
void ThreadGroup::Member::reduce(std::vector<std::vector<T>>& slots, std::span<T> v, Op op) {
    slots[size_t(rank_)].assign(v.begin(), v.end());
    g_.sync_.arrive_and_wait();
    for (size_t i = 0; i < v.size(); ++i) {  // in rank order: the same result on every member
        T acc = slots[0][i];
        for (size_t r = 1; r < slots.size(); ++r) acc = op(acc, slots[r][i]);
        v[i] = acc;
    }
    g_.sync_.arrive_and_wait();
}

void ThreadGroup::Member::minInPlace(std::span<float> v) {
    reduce(g_.floats_, v, [](float a, float b) { return std::min(a, b); });
}

void ThreadGroup::Member::minInPlace(std::span<int32_t> v) {
    reduce(g_.ints_, v, [](int32_t a, int32_t b) { return std::min(a, b); });
}

void ThreadGroup::Member::sumInPlace(std::span<float> v) {
    reduce(g_.floats_, v, [](float a, float b) { return a + b; });
}

std::vector<float> ThreadGroup::Member::gather(std::span<const float> v) {
    g_.floats_[size_t(rank_)].assign(v.begin(), v.end());
    g_.sync_.arrive_and_wait();
    std::vector<float> all;
    for (const auto& part : g_.floats_) all.insert(all.end(), part.begin(), part.end());
    g_.sync_.arrive_and_wait();
    return all;
}

std::vector<std::vector<uint8_t>> ThreadGroup::Member::exchange(const std::vector<std::vector<uint8_t>>& sends) {
    g_.messages_[size_t(rank_)] = sends;
    g_.sync_.arrive_and_wait();
    std::vector<std::vector<uint8_t>> received(size_t(g_.n_));
    for (int q = 0; q < g_.n_; ++q)
        if (q != rank_) received[size_t(q)] = std::move(g_.messages_[size_t(q)][size_t(rank_)]);  // read by this rank only
    g_.sync_.arrive_and_wait();
    return received;
}

}  // namespace flowsurf::methods
