// flowsurf — the analysis's loops over vertices and triangles on every core (internal to
// src/skeleton). Each index is handled by one thread and
// results land by index, so the output does not depend on the number of threads.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <thread>
#include <vector>

namespace flowsurf::skeleton::detail {

// Calls fn(begin, end, thread) over [0, n) in contiguous chunks, one per thread.
template <typename Fn>
void parallelChunks(size_t n, Fn&& fn) {
    const size_t threads = std::clamp<size_t>(std::thread::hardware_concurrency(), 1, 16);
    if (n < 20000 || threads == 1) {
        fn(size_t(0), n, size_t(0));
        return;
    }
    std::vector<std::thread> pool;
    const size_t chunk = (n + threads - 1) / threads;
    for (size_t t = 1; t < threads; ++t) {
        const size_t b = std::min(n, t * chunk), e = std::min(n, (t + 1) * chunk);
        pool.emplace_back([&fn, b, e, t] { fn(b, e, t); });
    }
    fn(size_t(0), std::min(n, chunk), size_t(0));
    for (auto& th : pool) th.join();
}

template <typename Fn>
void parallelFor(size_t n, Fn&& fn) {
    parallelChunks(n, [&fn](size_t b, size_t e, size_t) {
        for (size_t i = b; i < e; ++i) fn(i);
    });
}

}  // namespace flowsurf::skeleton::detail
